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

TEST(gcodeFanucMacro, GotoStaysInItsProgramAndLoopsEndWithTheirCall) {
  // GOTO 10 in O100 goes to O100's N10, not O200's.
  EXPECT_EQ(xs(fanuc("O1\nG21 G90\nM98 P100\nM98 P200\nM30\nO100\n#1=0\nN10 G1 X[#1] F10\n#1=#1+1\n"
                     "IF [#1 LT 2] GOTO 10\nM99\nO200\nN10 G1 Y5 F10\nM99\n")),
            std::vector<double>({0, 1, 1}));
  // M99 from inside a subprogram's loop ends that loop, not the caller's.
  EXPECT_EQ(xs(fanuc("O1\nG21 G90\n#1=0\nWHILE [#1 LT 2] DO1\nM98 P100\n#1=#1+1\nEND1\nG0 X9\nM30\n"
                     "O100\nWHILE [1] DO1\nG1 X[#1] F10\nM99\nEND1\nM99\n")),
            std::vector<double>({0, 1, 9}));
  // A GOTO out of an inner loop leaves it; the outer loop goes on.
  EXPECT_EQ(xs(fanuc("G21\n#1=0\nWHILE [#1 LT 2] DO1\n#1=#1+1\nWHILE [1] DO2\nGOTO 50\nEND2\nN50 G0 X#1\nEND1\n")),
            std::vector<double>({1, 2}));
}

TEST(gcodeFanucMacro, ALoopNumberAtTheVeryEndOfTheTextIsReadWithinIt) {
  // No newline after the last END1: its number must be read without running past the text.
  std::string text = "G21\n#1=0\nWHILE [#1 LT 2] DO1\n#1=#1+1\nG0 X#1\nEND1";
  EXPECT_EQ(xs(fanuc(text)), std::vector<double>({1, 2}));
  // Errors after THEN count columns from the line's start.
  EXPECT_EQ(fanuc("G21\n#1=1\nN10 IF [#1 EQ 1] THEN G1 X1 I5 F10\n").errors.at(0).str(),
            "t.ngc:3:29: i word with no G2 or G3 to use it");
}

// Fanuc's M98 takes its count of runs in L or K (M98 P2 K3): the K is the call's, not an arc's.
TEST(gcodeFanucMacro, M98CountsItsRunsInLOrK) {
  const std::string sub = "\nM30\nO2\nG91 G1 X1 F100\nG90\nM99\n";
  EXPECT_EQ(xs(fanuc("O1\nG21 G90\nG0 X0\nM98 P2 K3" + sub)), std::vector<double>({0, 1, 2, 3}));
  EXPECT_EQ(xs(fanuc("O1\nG21 G90\nG0 X0\nM98 P2 L3" + sub)), std::vector<double>({0, 1, 2, 3}));
}
