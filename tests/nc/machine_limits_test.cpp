// What holds for every machine the simulation models: a tight arc is passed in motion, not at
// a crawl.
#include <gtest/gtest.h>

#include <string>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/machine/machine.h"
#include "isurface/nc/simulator.h"

#include <fmt/format.h>

using namespace isurface;

namespace {

Program interpretText(const std::string& text) {
  InterpretResult r = interpretGcode(text, "limits.nc");
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front().str());
  return r.program;
}

double simulatedTime(const Program& program, const Machine& machine = defaultMachine()) {
  SampleBuffer buffer;
  return simulate(program, machine, buffer).machiningTime;
}

// A line, a half circle of radius r (mm) back in Y, a line back: the arc as a raster links passes.
std::string arcLink(double radius) {
  return fmt::format("G21 G90 G17\nG0 X0 Y0 Z0\nG1 X1 F1700\nG3 X1 Y{:g} I0 J{:g}\nG1 X0\nM2\n", 2 * radius, radius);
}

}  // namespace

TEST(machineLimits, ATightArcIsPassedInMotion) {
  // On the default machine an arc of 0.35 mm took 11.2 s at 6 mm/min, one of 0.4 mm 1 s.
  const double tight = simulatedTime(interpretText(arcLink(0.35)));
  const double wider = simulatedTime(interpretText(arcLink(0.4)));
  EXPECT_LT(tight, 1.5);
  EXPECT_LT(tight, 1.25 * wider);
  // A smaller arc is shorter and never much slower to pass: no cliff at any radius.
  double previous = 0;
  for (double radius = 0.05; radius <= 1.0; radius += 0.05) {
    const double t = simulatedTime(interpretText(arcLink(radius)));
    if (previous > 0) {
      EXPECT_LT(previous, 1.2 * t) << "radius " << radius << " mm";
    }
    previous = t;
  }
}
