// Line plots of a report: the curve is drawn wherever on the run's clock the plot lies.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "image_compare.h"
#include "isurface/vis/line_plot.h"

namespace isurface {
namespace {

// Pixels of the first series' colour (31, 119, 180) in a plot of a speed wave over 3 s of the
// run starting at `start` s.
std::size_t curvePixels(double start) {
  vis::LinePlot plot{"Path speed", "time (s)", "mm/min", {}, {{"speed (mm/min)", {}}}};
  for (int i = 0; i <= 3000; ++i) {
    plot.x.push_back(start + 0.001 * i);
    plot.series[0].y.push_back(2500 + 400 * std::sin(0.006 * i));
  }
  const std::string png = vis::plotToPng(plot, 640, 320);
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("isurface-plot-" + std::to_string(::getpid()) + ".png")).string();
  std::ofstream(path, std::ios::binary) << png;
  const test::Image image = test::readPng(path);
  std::filesystem::remove(path);
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const unsigned char* p = image.at(x, y);
      if (std::abs(p[0] - 31) < 50 && std::abs(p[1] - 119) < 50 && std::abs(p[2] - 180) < 50) ++count;
    }
  return count;
}

TEST(linePlot, drawsTheCurveOfSecondsLateInALongRun) {
  const std::size_t early = curvePixels(0.0);
  EXPECT_GT(early, 500u);
  for (const double start : {414.0, 4827.0, 86000.0}) EXPECT_GT(curvePixels(start), early / 2) << start << " s";
}

}  // namespace
}  // namespace isurface
