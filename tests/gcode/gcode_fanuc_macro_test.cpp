// Fanuc macro B in the Fanuc dialect: GOTO, IF .. GOTO, IF .. THEN, WHILE .. DO .. END, and
// settings whose value needs no brackets, checked against moves worked by hand.
#include <gtest/gtest.h>

#include "gcode_test_support.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

InterpretResult fanuc(const std::string& text) {
  InterpreterOptions options;
  options.fanuc = true;
  return run(text, options);
}

std::vector<double> xs(const InterpretResult& r) {
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors[0].str());
  std::vector<double> out;
  for (const Move& m : r.program.moves) out.push_back(m.end.x());
  return out;
}

}  // namespace

TEST(gcodeFanucMacro, WhileLoopsCountAndSettingsNeedNoBrackets) {
  const InterpretResult r =
      fanuc("G21 G90\n#1 = 0\nWHILE [#1 LT 3] DO1\n  #1 = #1 + 1\n  G1 X#1 * 2 F100\nEND1\nG0 X[#1 * 10]\n");
  // "X#1 * 2": a word's value is one value; only a setting takes a whole expression.
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(xs(fanuc("G21 G90\n#1 = 0\nWHILE [#1 LT 3] DO1\n  #1 = #1 + 1\n  G1 X[#1 * 2] F100\nEND1\nG0 X[#1 * 10]\n")),
            std::vector<double>({2, 4, 6, 30}));
  EXPECT_EQ(xs(fanuc("G21\n#1 = 5\nWHILE [#1 LT 3] DO2\nG0 X1\nEND2\nG0 X2\n")), std::vector<double>({2}));
}

TEST(gcodeFanucMacro, JumpsGoToTheNumberedBlock) {
  // Forward, and back (a counted loop made of GOTOs); the move keeps its physical line.
  const InterpretResult r = fanuc(
      "G21 G90\n#3 = 0\nN60 #3 = #3 + 1\nG0 X#3\nIF [#3 LT 3] GOTO 60\nIF [#3 EQ 3] GOTO 80\nG0 X99\nN80 G0 X7\n");
  EXPECT_EQ(xs(r), std::vector<double>({1, 2, 3, 7}));
  EXPECT_EQ(r.program.moves[1].line, 4u);
  EXPECT_EQ(r.program.moves[3].line, 8u);
  EXPECT_EQ(xs(fanuc("G21\nGOTO 20\nG0 X1\nN20 G0 X2\n")), std::vector<double>({2}));
}

TEST(gcodeFanucMacro, IfThenRunsItsStatementOnlyWhenTrue) {
  EXPECT_EQ(xs(fanuc("G21\n#1 = 3\nIF [#1 EQ 3] THEN #2 = 7 * 2\nIF [#1 NE 3] THEN #2 = 1\nG0 X#2\n")),
            std::vector<double>({14}));
  EXPECT_EQ(xs(fanuc("G21\nIF [1 GT 0] THEN G0 X4\nIF [1 LT 0] THEN G0 X5\n")), std::vector<double>({4}));
}

TEST(gcodeFanucMacro, MistakesAreErrorsNamingTheLine) {
  EXPECT_EQ(fanuc("G21\nGOTO 99\n").errors.at(0).str(), "t.ngc:2:1: GOTO 99: no block N99 in the program");
  EXPECT_EQ(fanuc("G21\nEND1\n").errors.at(0).str(), "t.ngc:2:1: END1 without its WHILE .. DO1");
  EXPECT_EQ(fanuc("G21\nWHILE [0] DO3\nG0 X1\n").errors.at(0).str(), "t.ngc:2:1: WHILE .. DO3 has no END3");
  EXPECT_EQ(fanuc("G21\nIF [1] G0 X1\n").errors.at(0).str(), "t.ngc:2:1: IF [..] must go on with GOTO or THEN");
  const std::string forever = fanuc("N10 GOTO 10\n").errors.at(0).str();
  EXPECT_NE(forever.find("never ends"), std::string::npos) << forever;
  // In LinuxCNC's dialect these are not statements: the words are refused as written.
  EXPECT_NE(firstError("GOTO 10\n"), "<no error>");
}
