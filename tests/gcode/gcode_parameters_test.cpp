// Parameters and expressions as LinuxCNC reads them (RS274/NGC, its manual's "O Codes" and
// "Numbered / Named Parameters" and "Expressions"), checked against moves worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "gcode_test_support.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

// The end of every move of a program, in order.
std::vector<Vec3> ends(const std::string& text) {
  std::vector<Vec3> out;
  for (const Move& m : interpret(text).moves) out.push_back(m.end);
  return out;
}

// The X of the one move a line makes: an expression evaluated.
double valueOf(const std::string& expression) {
  const std::vector<Vec3> e = ends("G21 G90 G0 X" + expression + "\nM30\n");
  return e.empty() ? NAN : e.back().x();
}

}  // namespace

TEST(gcodeParameters, NumberedAndNamedParametersStandForNumbers) {
  const auto e = ends("G21 G90\n#1=10 #<depth>=2.5 #<_safe>=5\nG0 X#1 Y#1 Z#<_safe>\nG1 Z-#<depth> F100\nM30\n");
  ASSERT_EQ(e.size(), 2u);
  expectNear(e[0], Vec3(10, 10, 5));
  expectNear(e[1], Vec3(10, 10, -2.5));
}

TEST(gcodeParameters, SettingsTakeEffectAfterTheBlock) {
  // Every read on a line sees the values from before it: #2 gets the old #1.
  const auto e = ends("G21 G90\n#1=1\n#1=2 #2=#1 G0 X#1 Y#2\nG0 X#1 Y#2\nM30\n");
  ASSERT_EQ(e.size(), 2u);
  expectNear(e[0], Vec3(1, 0, 0));
  expectNear(e[1], Vec3(2, 1, 0));
}

TEST(gcodeParameters, IndirectParametersAndUnsetOnesAreZero) {
  const auto e = ends("G21 G90\n#5=3\n#3=7.5\nG0 X##5 Y#[2+3] Z#100\nM30\n");
  ASSERT_EQ(e.size(), 1u);
  expectNear(e[0], Vec3(7.5, 3, 0));
}

TEST(gcodeParameters, OperatorsFollowLinuxCncPrecedence) {
  EXPECT_DOUBLE_EQ(valueOf("[1+2*3]"), 7);
  EXPECT_DOUBLE_EQ(valueOf("[2**3**2]"), 64);  // left to right, as LinuxCNC
  EXPECT_DOUBLE_EQ(valueOf("[10-4-3]"), 3);
  EXPECT_DOUBLE_EQ(valueOf("[12/4/3]"), 1);
  EXPECT_DOUBLE_EQ(valueOf("[-7 MOD 3]"), 2);  // the remainder takes the divisor's sign
  EXPECT_DOUBLE_EQ(valueOf("[1+2 EQ 3]"), 1);  // comparisons bind looser than arithmetic
  EXPECT_DOUBLE_EQ(valueOf("[1 LT 2 AND 3 GT 4]"), 0);
  EXPECT_DOUBLE_EQ(valueOf("[1 LT 2 OR 3 GT 4]"), 1);
  EXPECT_DOUBLE_EQ(valueOf("[1 XOR 1]"), 0);
  EXPECT_DOUBLE_EQ(valueOf("[1 NE 1.00001]"), 0);  // equal within 0.0001
  EXPECT_DOUBLE_EQ(valueOf("[2 GE 2] "), 1);
  EXPECT_DOUBLE_EQ(valueOf("[2 le 1]"), 0);  // any case
  EXPECT_DOUBLE_EQ(valueOf("-[1+1]"), -2);
  EXPECT_DOUBLE_EQ(valueOf("[[1 + 2] * [3 - 1]]"), 6);
}

TEST(gcodeParameters, FunctionsTakeAndGiveDegrees) {
  EXPECT_NEAR(valueOf("SIN[30]"), 0.5, 1e-12);
  EXPECT_NEAR(valueOf("COS[60]"), 0.5, 1e-12);
  EXPECT_NEAR(valueOf("TAN[45]"), 1, 1e-12);
  EXPECT_NEAR(valueOf("ASIN[1]"), 90, 1e-12);
  EXPECT_NEAR(valueOf("ACOS[0]"), 90, 1e-12);
  EXPECT_NEAR(valueOf("ATAN[1]/[-1]"), 135, 1e-12);
  EXPECT_DOUBLE_EQ(valueOf("SQRT[16]"), 4);
  EXPECT_DOUBLE_EQ(valueOf("ABS[-3]"), 3);
  EXPECT_NEAR(valueOf("EXP[1]"), std::exp(1.0), 1e-12);
  EXPECT_NEAR(valueOf("LN[EXP[2]]"), 2, 1e-12);
  EXPECT_DOUBLE_EQ(valueOf("ROUND[2.5]"), 3);
  EXPECT_DOUBLE_EQ(valueOf("ROUND[-2.5]"), -3);
  EXPECT_DOUBLE_EQ(valueOf("FIX[-1.5]"), -2);
  EXPECT_DOUBLE_EQ(valueOf("FUP[1.2]"), 2);
  EXPECT_DOUBLE_EQ(valueOf("[EXISTS[#<nope>]]"), 0);
  const auto e = ends("#<here>=1\nG21 G0 X[EXISTS[#<here>]*5]\nM30\n");
  ASSERT_EQ(e.size(), 1u);
  EXPECT_DOUBLE_EQ(e[0].x(), 5);
}

TEST(gcodeParameters, AFanucStyleProgramSetsOffsetsFromParameters) {
  // As a Mastercam post for a Haas/Fanuc control writes it: values held in #5xx.
  const auto e = ends("G20 G90\n#501=1\n#510=0.\n#511=2.\nG0 X#511 Y[#511/2] Z#510\nM30\n");
  ASSERT_EQ(e.size(), 1u);
  expectNear(e[0], Vec3(2 * 25.4, 25.4, 0), 1e-9);
}

TEST(gcodeParameters, BadParametersAndExpressionsNameTheLine) {
  EXPECT_EQ(firstError("G0 X#<undefined>"), "t.ngc:1:5: Named parameter #<undefined> not defined");
  EXPECT_EQ(firstError("#6000=1"), "t.ngc:1:1: Parameter number 6000 out of range (1-5602)");
  EXPECT_EQ(firstError("#1.5=1"), "t.ngc:1:1: Parameter number 1.5 is not an integer");
  EXPECT_EQ(firstError("#1 2"), "t.ngc:1:1: Equal sign missing in parameter setting");
  EXPECT_EQ(firstError("G0 X[1/0]"), "t.ngc:1:5: Attempt to divide by zero");
  EXPECT_EQ(firstError("G0 X[SQRT[-1]]"), "t.ngc:1:5: Attempt to take square root of negative number");
  EXPECT_EQ(firstError("G0 X[ACOS[2]]"), "t.ngc:1:5: Argument to acos out of range: 2");
  EXPECT_EQ(firstError("G0 X[1 FOO 2]"), "t.ngc:1:5: Unknown operation in expression at 'FOO 2]'");
  EXPECT_EQ(firstError("G0 X[-2**0.5]"), "t.ngc:1:5: Attempt to raise negative to non-integer power");
  EXPECT_EQ(firstError("G0 X[10**400]"), "t.ngc:1:5: Expression result is not a finite number");
  EXPECT_EQ(firstError("G0 X" + std::string(100, '[') + "1" + std::string(100, ']')),
            "t.ngc:1:5: Expression nested too deeply");
}

TEST(gcodeParameters, ABadBlockSetsNothing) {
  InterpreterOptions options;
  options.keepGoing = true;
  const InterpretResult r = run("G21 G90\n#1=5\n#1=7 G0 X#<nope>\nG0 X#1\nM30\n", options);
  ASSERT_EQ(r.errors.size(), 1u);
  ASSERT_EQ(r.program.moves.size(), 1u);
  EXPECT_DOUBLE_EQ(r.program.moves[0].end.x(), 5);
}
