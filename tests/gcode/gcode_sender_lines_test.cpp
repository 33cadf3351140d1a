// Lines a program's sender reads, not the control: grbl's `$` commands and `#` comment lines
// are skipped with one warning each kind, never a refusal and never a move.
#include <gtest/gtest.h>

#include "gcode_test_support.h"

using namespace isurface;
using namespace isurface::gcodetest;

TEST(gcodeSenderLines, GrblCommandsAreSkippedWithOneWarning) {
  const InterpretResult r = run("$H\n$X\nG21 G90\nG0 X1\n$$\nG1 X2 F100\nM2\n");
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  ASSERT_EQ(r.program.moves.size(), 2u);
  EXPECT_EQ(r.program.moves[1].line, 6u);
  ASSERT_EQ(r.program.warnings.size(), 1u);
  EXPECT_EQ(r.program.warnings[0].line, 1u);
  EXPECT_NE(r.program.warnings[0].message.find("grbl"), std::string::npos);
}

TEST(gcodeSenderLines, HashCommentLinesAreNotParameterSettings) {
  const InterpretResult r = run("# made by a sender\n#\n#1=3\nG21 G0 X#1\nM2\n");
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  ASSERT_EQ(r.program.moves.size(), 1u);
  EXPECT_DOUBLE_EQ(r.program.moves[0].end.x(), 3);
  ASSERT_EQ(r.program.warnings.size(), 1u);
  EXPECT_NE(r.program.warnings[0].message.find("'#' comment"), std::string::npos);
}

TEST(gcodeSenderLines, ASettingWithABlankAfterItsHashIsASetting) {
  const InterpretResult r = run("G21\n# 5 = 3\nG0 X#5\n");
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  EXPECT_EQ(r.program.moves.at(0).end.x(), 3);
  EXPECT_TRUE(r.program.warnings.empty());
}
