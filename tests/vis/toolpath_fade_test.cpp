// The programmed toolpath drawn over the map fades out where its passes lie closer than a few
// pixels: a 100 M-sample raster's map came out dark grey in the window, its passes 0.6 px apart.
#include <gtest/gtest.h>

#include <string>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/nc/sample_trajectory.h"
#include "isurface/nc/simulator.h"
#include "isurface/vis/offscreen_render.h"
#include "isurface/map/quality_map.h"
#include "isurface/vis/quality_scene.h"

using namespace isurface;

namespace {

// A zig-zag raster of 40 mm passes along X, `step` mm apart in Y, over 40 mm of Y.
std::string raster(double step) {
  std::string text = "G21 G90 G64\nG1 X0 Y0 Z0 F3000\n";
  const int passes = static_cast<int>(40.0 / step) + 1;
  for (int k = 0; k < passes; ++k) {
    text += "G1 X" + std::string(k % 2 == 0 ? "40" : "0") + "\n";
    if (k + 1 < passes) text += "G1 Y" + std::to_string((k + 1) * step) + "\n";
  }
  return text;
}

// The top view of the raster's speed map, 400 x 300 pixels, with and without its toolpath.
std::pair<std::string, std::string> withAndWithoutToolpath(double step) {
  const InterpretResult program = interpretGcode(raster(step), "raster.nc");
  EXPECT_TRUE(program.ok());
  const Machine machine = defaultMachine();
  TrajectorySink sink(machine.cycle, "raster.nc", false);
  simulate(program.program, machine, sink);
  const Trajectory samples = sink.take();
  vis::QualityMapRequest request;
  request.quantity = Quantity::Speed;
  request.view = vis::ViewDirection::Top;
  request.showToolpath = true;
  const vis::QualityMap map = vis::buildQualityMap(samples, &program.program, request);
  vis::QualityScene scene(map.data, map.style);
  const std::string shown = vis::renderSceneToPngBytes(scene, 400, 300);
  scene.setVisibility(true, false, false, false);
  return {shown, vis::renderSceneToPngBytes(scene, 400, 300)};
}

}  // namespace

TEST(toolpathFade, PassesAPixelApartLeaveTheMapAsItIs) {
  // 40 mm in about 250 pixels: passes 0.25 mm apart are 1.5 pixels apart.
  const auto [shown, hidden] = withAndWithoutToolpath(0.25);
  EXPECT_EQ(shown, hidden);
}

TEST(toolpathFade, PassesFarApartAreDrawn) {
  // 1.6 mm: 10 pixels apart (the surface spans passes up to 2 mm apart).
  const auto [shown, hidden] = withAndWithoutToolpath(1.6);
  EXPECT_NE(shown, hidden);
}
