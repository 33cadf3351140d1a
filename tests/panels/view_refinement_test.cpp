// The surface refined where the camera rests: a close-up of the part in sight, finer than the
// map made for the whole view, that goes when the camera looks beyond it.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "isurface/panels/headless_ui.h"
#include "test_support.h"
#include "ui_driving.h"

using namespace isurface;
using test::settle;

namespace {

// A raster of 60 passes of 100 mm, 0.5 mm apart, at F600: 10,000 samples a pass, 600,000 in
// all, more than an 800 x 600 window's view has pixels: its map keeps every ninth sample or so.
std::string longRaster() {
  const std::string path = (test::scratchDir() / "long-raster.nc").string();
  std::ofstream out(path);
  out << "G21 G90 G17 G94\nG0 Z5\nG0 X0 Y0\nG1 Z0 F600\n";
  for (int p = 0; p < 60; ++p) {
    out << "G1 Y" << 0.5 * p << "\n";
    for (int i = 1; i <= 20; ++i) {
      const double x = 5.0 * (p % 2 == 0 ? i : 20 - i);
      out << "G1 X" << x << " Z" << 0.3 * std::sin(0.1 * x + 0.2 * p) << "\n";
    }
  }
  out << "G0 Z5\nM30\n";
  return path;
}

class ViewRefinementTest : public ::testing::Test {
 protected:
  void SetUp() override {
    settle(ui);  // laid out first, as the window is: the map is made for the view's size
    ui.inspector().open(longRaster());
    ui.inspector().waitUntilIdle();
    settle(ui);
    const auto view = described()["controls"]["view"].get<std::array<float, 4>>();
    cx = (view[0] + view[2]) / 2;
    cy = (view[1] + view[3]) / 2;
    width = view[2] - view[0];
  }
  nlohmann::json described() { return nlohmann::json::parse(ui.inspector().describe()); }
  nlohmann::json closeUp() { return described()["map"]["close_up"]; }
  // Frames as the window draws them while it refines, until it has decided and built what the
  // view needs.
  nlohmann::json refined() {
    for (int frame = 0; frame < 500 && (frame < 2 || ui.inspector().refining()); ++frame) {
      ui.frame();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ui.frame();
    return closeUp();
  }
  void zoom(int notches) {
    ui.mouse(cx, cy, false);
    ui.frame();
    for (int n = 0; n < std::abs(notches); ++n) {
      ui.wheel(notches > 0 ? 1.0f : -1.0f);
      ui.frame();
    }
  }

  panels::HeadlessUi ui{800, 600, app_model::Settings{}};
  float cx = 0, cy = 0, width = 0;
};

}  // namespace

TEST_F(ViewRefinementTest, ZoomingInRefinesTheSurfaceInSightAndZoomingOutTakesItAway) {
  const nlohmann::json map = described()["map"];
  const double vertices = map["vertices"].get<double>();
  ASSERT_GT(vertices, 10'000.0);
  ASSERT_LT(vertices, 200'000.0);  // thinned: not every one of the 600,000 samples
  // The whole part in sight: the map is as fine as the view, nothing to refine.
  EXPECT_FALSE(refined().contains("vertices"));
  zoom(12);
  const nlohmann::json close = refined();
  ASSERT_TRUE(close.contains("vertices")) << close.dump();
  // Finer than the map: at most every fourth sample where the map keeps every ninth or so.
  EXPECT_LE(close["stride"].get<int>(), 4);
  EXPECT_GT(close["vertices"].get<double>(), 1'000.0);
  // Only the part in sight: a box well inside the 100 x 29.5 mm part.
  const double wide = close["upper"][0].get<double>() - close["lower"][0].get<double>();
  const double deep = close["upper"][1].get<double>() - close["lower"][1].get<double>();
  EXPECT_LT(wide * deep, 0.5 * 100 * 29.5);
  zoom(-14);
  EXPECT_FALSE(refined().contains("vertices"));
}

TEST_F(ViewRefinementTest, ACloseUpGoesWhenADragTurnsTheViewAwayFromIt) {
  zoom(12);
  ASSERT_TRUE(refined().contains("vertices")) << described()["camera"].dump();
  const nlohmann::json before = closeUp();
  // Turned by half the view's width (100 degrees), then held still before the button is let go:
  // the frames of the drag follow the pointer, the last ones do not move.
  ui.mouse(cx, cy, true);
  ui.frame();
  for (int step = 1; step <= 10; ++step) {
    ui.mouse(cx + 0.05f * width * step, cy, true);
    ui.frame();
  }
  for (int still = 0; still < 5; ++still) ui.frame();
  ui.mouse(cx + 0.5f * width, cy, false);
  ui.frame();  // the release (drawn as the drag's last frame, with the coarse surface)
  ui.frame();
  // The first frame at full size, before any rest: the old close-up does not cover what is in
  // sight and is not drawn.
  const nlohmann::json after = closeUp();
  EXPECT_TRUE(!after.contains("vertices") || after["lower"] != before["lower"]) << after.dump();
}
