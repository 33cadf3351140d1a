// G64 P- Q- as LinuxCNC reads them: the blend and naive-CAM tolerances from the move after on,
// in mm; G61 (exact path) told apart from G61.1 (exact stop).
#include <gtest/gtest.h>

#include "isurface/gcode/gcode_interpreter.h"

namespace isurface {
namespace {

TEST(pathBlending, g64ToleranceAppliesFromTheNextMoveOnAndQDefaultsToP) {
  const InterpretResult r = interpretGcode("G21 G90\nG1 X1 F100\nG64 P0.02\nG1 X2\nG64 P0.05 Q0.01\nG1 X3\nG64\nG1 X4\n", "t.ngc");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.program.blending.size(), 3u);
  EXPECT_EQ(r.program.blending[0].firstMove, 1u);
  EXPECT_DOUBLE_EQ(r.program.blending[0].blend, 0.02);
  EXPECT_DOUBLE_EQ(r.program.blending[0].merge, 0.02);
  EXPECT_DOUBLE_EQ(r.program.blending[1].blend, 0.05);
  EXPECT_DOUBLE_EQ(r.program.blending[1].merge, 0.01);
  EXPECT_EQ(r.program.blending[2].firstMove, 3u);
  EXPECT_DOUBLE_EQ(r.program.blending[2].blend, 0.0);
  EXPECT_DOUBLE_EQ(r.program.blending[2].merge, 0.0);
}

TEST(pathBlending, inchToleranceIsInMillimetres) {
  const InterpretResult r = interpretGcode("G20 G90\nG64 P0.001\nG1 X1 F10\n", "t.ngc");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.program.blending.size(), 1u);
  EXPECT_NEAR(r.program.blending[0].blend, 0.0254, 1e-12);
}

TEST(pathBlending, aNegativeToleranceIsRefusedWithItsLine) {
  const InterpretResult r = interpretGcode("G21\nG64 P-1\nG1 X1 F100\n", "t.ngc");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errors.front().line, 2u);
}

TEST(pathBlending, exactPathAndExactStopAreToldApart) {
  const InterpretResult r = interpretGcode("G21\nG61\nG1 X1 F100\nG61.1\nG1 X2\nG64\nG1 X3\n", "t.ngc");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.program.moves.size(), 3u);
  EXPECT_EQ(r.program.moves[0].flags & (kExactStop | kExactPath), kExactStop | kExactPath);
  EXPECT_EQ(r.program.moves[1].flags & (kExactStop | kExactPath), kExactStop);
  EXPECT_EQ(r.program.moves[2].flags & (kExactStop | kExactPath), 0);
}

}  // namespace
}  // namespace isurface
