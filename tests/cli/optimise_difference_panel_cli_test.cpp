// A re-optimised region in a headless snapshot (isurface-cli ui-snapshot --optimize-lines): the
// difference map takes the place of the new run's map beside the old one; bad views refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "test_support.h"
#include "image_compare.h"

using namespace isurface::test;

namespace {

// Mean absolute channel difference (0..255) over a rectangle of two images of the same size.
double meanDifferenceIn(const Image& a, const Image& b, int x0, int y0, int x1, int y1) {
  double sum = 0;
  std::size_t n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x, ++n)
      for (int c = 0; c < 3; ++c) sum += std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c]));
  return n ? sum / (3.0 * double(n)) : 0.0;
}

}  // namespace

TEST(optimiseDifferencePanel, SnapshotShowsTheDifferenceInPlaceOfTheNewMap) {
  const std::string sideBySide = (scratchDir() / "optimise-side.png").string();
  const std::string difference = (scratchDir() / "optimise-difference.png").string();
  const std::string common = "ui-snapshot " + sourcePath("samples/transition-surface.nc") +
                             " --optimize-lines 105-400 --size 1280x800 -o ";
  const CommandResult a = runCli(common + sideBySide);
  ASSERT_EQ(a.exitCode, 0) << a.err;
  const CommandResult b = runCli(common + difference + " --optimize-view difference");
  ASSERT_EQ(b.exitCode, 0) << b.err;
  const Image left = readPng(sideBySide), right = readPng(difference);
  ASSERT_EQ(left.width, 1280);
  ASSERT_EQ(right.width, 1280);
  // The window's layout puts the view beside the main one at 44-70 % of the width, under the
  // toolbar: there the speed map gives way to the difference map; the main view stays.
  EXPECT_GT(meanDifferenceIn(left, right, 600, 200, 880, 480), 10.0);
  EXPECT_LT(meanDifferenceIn(left, right, 260, 200, 540, 480), 1.0);

  EXPECT_EQ(runCli(common + difference + " --optimize-view sideways").exitCode, 2);
  EXPECT_EQ(runCli("ui-snapshot " + sourcePath("samples/transition-surface.nc") + " --optimize-view difference -o " +
                   (scratchDir() / "never.png").string())
                .exitCode,
            2);
  EXPECT_FALSE(fileExists((scratchDir() / "never.png").string()));
}
