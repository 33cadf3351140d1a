// isurface-cli optimize --png-diff: the speed difference, after minus before, on the surface
// before, passes aligned with their replacements.
#include <gtest/gtest.h>

#include "image_compare.h"
#include "test_support.h"

using namespace isurface::test;

TEST(optimizeDifferenceMap, CommandDrawsTheRegionsSpeedChange) {
  const std::string program = (scratchDir() / "transition-optimized.nc").string();
  const std::string png = (scratchDir() / "transition-difference.png").string();
  const CommandResult r = runCli("optimize " + sourcePath("samples/transition-surface.nc") + " --lines 105-400 -o " +
                                 program + " --png-diff " + png);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image image = readPng(png);
  ASSERT_EQ(image.width, 1200);
  ASSERT_EQ(image.height, 800);
  // Diverging colours over the surface (the middle of the picture, left of the legend): the
  // re-fitted passes are faster (red) or slower (blue) in places; most of the surface,
  // unchanged, is the map's white.
  std::size_t red = 0, blue = 0, white = 0;
  for (int y = image.height * 20 / 100; y < image.height * 80 / 100; ++y)
    for (int x = image.width * 15 / 100; x < image.width * 85 / 100; ++x) {
      const unsigned char* p = image.at(x, y);
      if (p[0] - p[2] > 80) ++red;
      if (p[2] - p[0] > 40 && p[2] > 150) ++blue;
      if (p[0] > 215 && p[1] > 215 && p[2] > 215) ++white;
    }
  EXPECT_GT(red, 500u) << png;
  EXPECT_GT(blue, 50u) << png;
  EXPECT_GT(white, 50000u) << png;
}
