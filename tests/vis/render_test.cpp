// The tolerance of the screenshot tests is shown to catch real regressions, on the reference
// image itself. (The bundled samples rendered through the command line and compared with their
// references: tests/cli/render_cli_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>

#include "render_references.h"

using namespace isurface::test;

TEST_F(ToleranceCatches, AMissingLegend) {
  Image damaged = reference;
  // The legend stands at the right edge: paint it over with the background beside it.
  for (int y = 0; y < damaged.height; ++y)
    for (int x = damaged.width * 88 / 100; x < damaged.width; ++x)
      std::copy(damaged.at(damaged.width - 1, y), damaged.at(damaged.width - 1, y) + 3, damaged.at(x, y));
  EXPECT_FALSE(matches(compareImages(reference, damaged)));
}

TEST_F(ToleranceCatches, AHoleInTheSurface) {
  Image damaged = reference;
  // A 40x40 pixel hole in the middle of the surface showing the background.
  const int cx = damaged.width / 2, cy = damaged.height / 2;
  for (int y = cy - 20; y < cy + 20; ++y)
    for (int x = cx - 20; x < cx + 20; ++x) damaged.at(x, y)[0] = damaged.at(x, y)[1] = damaged.at(x, y)[2] = 235;
  EXPECT_FALSE(matches(compareImages(reference, damaged)));
}
