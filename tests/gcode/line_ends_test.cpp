// Line ends from every system: a carriage return alone ends a line, as it did for the author.
#include <gtest/gtest.h>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/gcode/line_ends.h"

using namespace isurface;

TEST(LineEnds, CarriageReturnsAloneEndLines) {
  const InterpretResult r = interpretGcode("G21 G90\rG1 X10 F100\rY20\rM2\r", "mac.nc");
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  ASSERT_EQ(r.program.moves.size(), 2u);
  EXPECT_EQ(r.program.moves[0].end, Vec3(10, 0, 0));
  EXPECT_EQ(r.program.moves[0].line, 2u);
  EXPECT_EQ(r.program.moves[1].end, Vec3(10, 20, 0));
  EXPECT_EQ(r.program.moves[1].line, 3u);
  EXPECT_EQ(r.program.lineCount, 4u);
}

TEST(LineEnds, MixedEndingsCountLikeAnEditor) {
  const InterpretResult r = interpretGcode("G21 G90\r\nG1 X1 F100\nX2\rX3\r\n", "mixed.nc");
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  ASSERT_EQ(r.program.moves.size(), 3u);
  EXPECT_EQ(r.program.moves[2].line, 4u);
  EXPECT_EQ(r.program.moves[2].end.x(), 3.0);
}

TEST(LineEnds, CarriageReturnLineFeedIsOneLineEnd) {
  EXPECT_FALSE(hasLoneCarriageReturn("G1 X1\r\nG1 X2\r\n"));
  EXPECT_TRUE(hasLoneCarriageReturn("G1 X1\rG1 X2"));
  EXPECT_TRUE(hasLoneCarriageReturn("G1 X1\r"));
  EXPECT_EQ(withLineFeeds("a\r\nb\rc\r"), "a\r\nb\nc\n");
}
