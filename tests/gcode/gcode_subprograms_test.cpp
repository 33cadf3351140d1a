// Fanuc subprograms (M98/M99) and macro calls (G65), checked against moves worked by hand.
#include <gtest/gtest.h>

#include "gcode_test_support.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

const char* const kProgram =
    "O1000 (MAIN)\n"
    "G21 G90\n"
    "G0 X0 Y0\n"
    "M98 P2000 L2\n"      // twice: X+5 incremental
    "G65 P3000 A1.5 X2.\n"  // #1 = 1.5, #24 = 2
    "G0 X90\n"
    "M30\n"
    "%\n"
    "O2000 (STEP)\n"
    "G91 G1 X5 F100\n"
    "G90\n"
    "M99\n"
    "O3000 (MACRO)\n"
    "G1 X[#1+#24] Y#1\n"
    "M99\n";

}  // namespace

TEST(gcodeSubprograms, M98RunsTheSubprogramItsTimesAndM99ComesBack) {
  const Program p = interpret(kProgram);
  ASSERT_EQ(p.moves.size(), 5u);
  EXPECT_EQ(p.moves[1].end, Vec3(5, 0, 0));
  EXPECT_EQ(p.moves[2].end, Vec3(10, 0, 0));
  EXPECT_EQ(p.moves[1].line, 10u);  // the subprogram's own line
  EXPECT_EQ(p.moves[2].line, 10u);
  EXPECT_EQ(p.moves[3].end, Vec3(3.5, 1.5, 0));  // G65's letters as #1 and #24
  EXPECT_EQ(p.moves[3].line, 14u);
  EXPECT_EQ(p.moves[4].end, Vec3(90, 1.5, 0));
  EXPECT_EQ(p.moves[4].line, 6u);
}

TEST(gcodeSubprograms, G65ArgumentsBelongToTheCall) {
  const Program p = interpret("G21\n#1=7\nG65 P10 A2\nG0 X#1\nM30\nO10\n#1=[#1*3]\nG0 Y#1\nM99\n");
  ASSERT_EQ(p.moves.size(), 2u);
  EXPECT_EQ(p.moves[0].end.y(), 6);  // inside: A2 tripled
  EXPECT_EQ(p.moves[1].end.x(), 7);  // after: the caller's #1 again
}

TEST(gcodeSubprograms, MistakesAreErrors) {
  EXPECT_EQ(firstError("G21\nM98 P77\nM30\n"), "t.ngc:3: subprogram O77 is called (line 2) but is neither in the file nor a file O77 in the subroutine path");
  EXPECT_EQ(firstError("M98\n"), "t.ngc:1:1: P word (the program number) missing with M98");
  EXPECT_EQ(firstError("G65 A1\n"), "t.ngc:1:1: P word (the program number) missing with G65");
  EXPECT_EQ(firstError("G21\nM98 P7\nM30\nO7\nM99 P40\n"), "t.ngc:5:5: M99 P40: no block N40 in the calling program");
  const std::string deep = firstError("O5\nM98 P5\n");
  EXPECT_NE(deep.find("nested deeper than 200"), std::string::npos) << deep;
  // A count past the controls' most says so, not that it is not whole.
  EXPECT_EQ(firstError("G21\nM98 P7 L100000\nM30\nO7\nM99\n"),
            "t.ngc:2:8: M98 L must be a whole number of runs from 0 to 99999 (it is 100000)");
  EXPECT_EQ(firstError("G21\nG65 P7 L2.5\nM30\nO7\nM99\n"),
            "t.ngc:2:8: G65 L must be a whole number of runs from 0 to 99999 (it is 2.5)");
}

TEST(gcodeSubprograms, M99PReturnsToTheNumberedBlockOfTheCaller) {
  const Program p = interpret("O1\nG21 G90 G0 X0 Y0\nM98 P100\nN10 G1 X1 F100\nN20 G1 X2\nM30\n"
                              "O100\nG1 Y5 F100\nM99 P20\n");
  ASSERT_EQ(p.moves.size(), 3u);
  EXPECT_EQ(p.moves[1].end, Vec3(0, 5, 0));
  EXPECT_EQ(p.moves[2].end, Vec3(2, 5, 0));  // N10 is passed over
  EXPECT_EQ(p.moves[2].line, 5u);
}

TEST(gcodeSubprograms, M99EndingAMainProgramIsReadOnce) {
  const InterpretResult r = run("G21 G0 X1\nM99\nG0 X2\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.moves.size(), 1u);
  ASSERT_EQ(r.program.warnings.size(), 1u);
  EXPECT_NE(r.program.warnings[0].message.find("read once"), std::string::npos);
}

TEST(gcodeSubprograms, TheLinesSettingsBelongToTheCallerAndG65LettersAreNotWords) {
  // "#1=5 G65 P100 A2": the caller's #1 becomes 5, the macro's #1 is its A; "#1=7 M99" is the
  // macro's own. G65's F is an argument, not the feed.
  const Program p = interpret(
      "G21 G90\nG1 F100\n#1=1\n#1=5 G65 P100 A2 F7\nG1 Y[#1]\nM2\nO100\nG1 X[#1] Z#9\n#1=7 M99\n");
  ASSERT_EQ(p.moves.size(), 2u);
  EXPECT_EQ(p.moves[0].end, Vec3(2, 0, 7));
  EXPECT_EQ(p.moves[1].end, Vec3(2, 5, 7));
  EXPECT_FLOAT_EQ(p.moves[1].feed, 100.0f);
  // L0 runs nothing, wherever the subprogram stands.
  EXPECT_EQ(interpret("G21\nM98 P100 L0\nG0 Z1\nM30\nO100\nG0 X1\nM99\n").moves.size(), 1u);
}

TEST(gcodeSubprograms, M99PWaitsForTheLastRepeat) {
  const Program p = interpret("O1\nG21 G90 G0 X0 Y0\nM98 P100 L2\nN10 G1 X1 F100\nN20 G1 X2\nM30\n"
                              "O100\nG91 G1 Y5 F100\nG90\nM99 P20\n");
  ASSERT_EQ(p.moves.size(), 4u);
  EXPECT_EQ(p.moves[2].end, Vec3(0, 10, 0));  // both runs
  EXPECT_EQ(p.moves[3].end, Vec3(2, 10, 0));  // then N20
}
