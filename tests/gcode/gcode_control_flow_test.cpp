// LinuxCNC's O-word control flow, checked against moves worked by hand (and, for the realdata
// programs, against rs274 in rs274_differential_test.cpp).
#include <gtest/gtest.h>

#include <chrono>

#include "gcode_test_support.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

std::vector<double> xs(const std::string& text) {
  std::vector<double> out;
  for (const Move& m : interpret(text).moves) out.push_back(m.end.x());
  return out;
}

}  // namespace

TEST(gcodeControlFlow, ASubroutineRunsOnlyWhenCalled) {
  const std::string text =
      "G21 G90\n"
      "o<square> sub\n"
      "  G1 X#1 F100\n"
      "  G1 Y#1\n"
      "o<square> endsub\n"
      "G0 X0 Y0\n"
      "o<square> call [5]\n"
      "o<square> call [7]\n"
      "M2\n";
  const Program p = interpret(text);
  ASSERT_EQ(p.moves.size(), 5u);
  EXPECT_DOUBLE_EQ(p.moves[1].end.x(), 5);
  EXPECT_DOUBLE_EQ(p.moves[2].end.y(), 5);
  EXPECT_DOUBLE_EQ(p.moves[3].end.x(), 7);
  // Every move carries the physical line that made it: the body's lines, once per call.
  EXPECT_EQ(p.moves[1].line, 3u);
  EXPECT_EQ(p.moves[2].line, 4u);
  EXPECT_EQ(p.moves[3].line, 3u);
  // Defined and never called: nothing of it runs.
  EXPECT_EQ(xs("G21\no100 sub\nG0 X9\no100 endsub\nG0 X1\nM2\n"), std::vector<double>({1}));
}

TEST(gcodeControlFlow, CallsHaveTheirOwnParametersAndReturnValues) {
  // 4! by recursion (LinuxCNC's factorial.ngc), then the caller's #1 is its own again.
  const std::string text =
      "o<fact> sub\n"
      "  o<test> if [#1 EQ 0]\n"
      "    o<fact> return [1]\n"
      "  o<test> endif\n"
      "  o<fact> call [#1 - 1]\n"
      "  o<fact> return [#<_value> * #1]\n"
      "o<fact> endsub\n"
      "#1 = 3 #<local> = 2\n"
      "o<fact> call [4]\n"
      "G21 G0 X#<_value> Y#1 Z#<local>\n"
      "M2\n";
  const Program p = interpret(text);
  ASSERT_EQ(p.moves.size(), 1u);
  expectNear(p.moves[0].end, Vec3(24, 3, 2));
}

TEST(gcodeControlFlow, ConditionsChooseOneBranch) {
  const std::string branches =
      "o1 if [#1 LT 0]\n  G0 X-1\n"
      "o1 elseif [#1 EQ 0]\n  G0 X0.5\n"
      "o1 elseif [#1 LT 10]\n  G0 X1\n"
      "o1 else\n  G0 X2\n"
      "o1 endif\n";
  EXPECT_EQ(xs("G21\n#1=-3\n" + branches), std::vector<double>({-1}));
  EXPECT_EQ(xs("G21\n#1=0\n" + branches), std::vector<double>({0.5}));
  EXPECT_EQ(xs("G21\n#1=5\n" + branches), std::vector<double>({1}));
  EXPECT_EQ(xs("G21\n#1=50\n" + branches), std::vector<double>({2}));
}

TEST(gcodeControlFlow, LoopsRepeatBreakAndContinue) {
  EXPECT_EQ(xs("G21\n#1=0\no1 while [#1 LT 3]\n#1=[#1+1]\nG0 X#1\no1 endwhile\nG0 X9\n"),
            std::vector<double>({1, 2, 3, 9}));
  EXPECT_EQ(xs("G21\n#1=5\no1 while [#1 LT 3]\nG0 X#1\no1 endwhile\nG0 X9\n"), std::vector<double>({9}));
  EXPECT_EQ(xs("G21\n#1=5\no2 do\nG0 X#1\n#1=[#1+1]\no2 while [#1 LT 3]\nG0 X9\n"), std::vector<double>({5, 9}));
  EXPECT_EQ(xs("G21\n#1=0\no3 repeat [3]\n#1=[#1+2]\nG0 X#1\no3 endrepeat\n"), std::vector<double>({2, 4, 6}));
  EXPECT_EQ(xs("G21\no3 repeat [0]\nG0 X1\no3 endrepeat\nG0 X2\n"), std::vector<double>({2}));
  // break leaves the loop; continue goes on with its next round; inner loops end with them.
  EXPECT_EQ(xs("G21\n#1=0\no4 while [1]\n#1=[#1+1]\no5 if [#1 EQ 3]\no4 break\no5 endif\nG0 X#1\no4 endwhile\nG0 X9\n"),
            std::vector<double>({1, 2, 9}));
  EXPECT_EQ(xs("G21\n#1=0\no4 while [#1 LT 4]\n#1=[#1+1]\no5 if [#1 EQ 2]\no4 continue\no5 endif\nG0 X#1\no4 endwhile\n"),
            std::vector<double>({1, 3, 4}));
  EXPECT_EQ(xs("G21\n#1=0\no6 repeat [2]\n#2=0\no7 while [1]\n#2=[#2+1]\nG0 X#2\no7 if [#2 EQ 2]\no6 continue\no7 endif\n"
               "o7 endwhile\no6 endrepeat\nG0 X9\n"),
            std::vector<double>({1, 2, 1, 2, 9}));
}

TEST(gcodeControlFlow, ABreakFromInsideAnIfClosesTheIf) {
  // As LinuxCNC's manual reads it: the if is left with the loop, and the do loop after it runs
  // until its condition fails (rs274 2.9.0~pre1 runs it once: rs274_differential_test.cpp).
  EXPECT_EQ(xs("G21 F100\n#<i> = 0\no102 while [#<i> LT 9]\n#<i> = [#<i> + 2]\no202 if [#<i> GT 3]\no102 break\n"
               "o202 endif\nG1 X#<i>\no102 endwhile\n#<d> = 1\no403 do\nG1 X[#<d> * 2.25]\n#<d> = [#<d> + 1]\n"
               "o403 while [#<d> LT 3]\nM2\n"),
            std::vector<double>({2, 2.25, 4.5}));
}

TEST(gcodeControlFlow, ASubroutineDefinedAfterItsCallIsFound) {
  EXPECT_EQ(xs("G21\no<later> call [4]\nG0 X9\nM2\no<later> sub\nG0 X#1\no<later> endsub\n"),
            std::vector<double>({4, 9}));
}

TEST(gcodeControlFlow, MistakesAreErrorsNamingTheLine) {
  EXPECT_EQ(firstError("o1 endwhile\n"), "t.ngc:1:1: o1 endwhile without its while");
  EXPECT_EQ(firstError("G21\no2 else\n"), "t.ngc:2:1: o2 else without its if");
  EXPECT_EQ(firstError("o3 if [1]\nG0 X1\n"), "t.ngc:2: o3 if has no endif");
  EXPECT_EQ(firstError("o4 if [0]\nG0 X1\n"), "t.ngc:2: o4 (line 1) has no endif");
  EXPECT_EQ(firstError("o<nowhere> call\nM2\n").substr(0, 58), "t.ngc:2: o<nowhere> is called (line 1) but defined nowhere");
  EXPECT_EQ(firstError("o5 return\n"), "t.ngc:1:1: o5 return outside a call of it");
  EXPECT_EQ(firstError("o6 if 1\no6 endif\n"), "t.ngc:1:1: o6 needs a condition in [ ]");
  EXPECT_EQ(firstError("o7 jump\n"), "t.ngc:1:1: Unknown O-word keyword 'jump' after o7");
  EXPECT_EQ(firstError("o8 sub\nG0 X1\n"), "t.ngc:2: o8 sub (line 1) has no endsub");
}

TEST(gcodeControlFlow, RunawayProgramsStopWithAnError) {
  const std::string recursion = firstError("o<deep> sub\no<deep> call\no<deep> endsub\no<deep> call\n");
  EXPECT_NE(recursion.find("nested deeper than 200"), std::string::npos) << recursion;
  const auto start = std::chrono::steady_clock::now();
  const std::string loop = firstError("o1 while [1]\no1 endwhile\n");
  EXPECT_NE(loop.find("t.ngc:1: a program that never ends?"), std::string::npos) << loop;
  EXPECT_NE(loop.find("running: o1 while (line 1)"), std::string::npos) << loop;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(60));  // an error, not a hang
}

TEST(gcodeControlFlow, ARecursiveCallHasItsOwnLoopsAndReturnValues) {
  // The inner call's `o101 while` is not its caller's loop, though the label and line are the same.
  const std::string recursion =
      "G21 G90 F100\n"
      "o<r> sub\n"
      "  #<i> = 0\n"
      "  o101 while [#<i> LT 2]\n"
      "    #<i> = [#<i> + 1]\n"
      "    G1 X[#1 * 10 + #<i>]\n"
      "    o102 if [#1 GT 0]\n"
      "      o<r> call [#1 - 1]\n"
      "    o102 endif\n"
      "  o101 endwhile\n"
      "o<r> endsub\n"
      "o<r> call [1]\n"
      "M2\n";
  EXPECT_EQ(xs(recursion), std::vector<double>({11, 1, 2, 12, 1, 2}));  // as rs274
  // A call that returns nothing leaves nothing of an earlier call's value.
  EXPECT_EQ(xs("o1 sub\no1 return [5]\no1 endsub\no2 sub\no2 endsub\no1 call\no2 call\nG21 G0 X#<_value_returned> Y#<_value>\n"),
            std::vector<double>({0}));
  // A setting may not come before an O word: it would be read as the label.
  EXPECT_EQ(firstError("G21\n#1=7 o100 sub\nG0 X1\no100 endsub\n"), "t.ngc:2:6: An O-word must start the block");
}
