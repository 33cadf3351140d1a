// The figures a run is judged by: nearest-rank percentiles, and what a window takes in.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "isurface/analysis/quality_figures.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/workflow/region_optimisation.h"
#include "isurface/workflow/run_inputs.h"

using namespace isurface;

TEST(qualityFigures, PercentilesAreNearestRankOverFiniteValues) {
  std::vector<double> values;
  for (int k = 100; k >= 1; --k) values.push_back(k);
  values.push_back(std::numeric_limits<double>::quiet_NaN());
  values.push_back(std::numeric_limits<double>::infinity());
  std::vector<double> copy = values;
  EXPECT_EQ(percentileOf(copy, 99), 99.0);
  copy = values;
  EXPECT_EQ(percentileOf(copy, 50), 50.0);
  copy = values;
  EXPECT_EQ(percentileOf(copy, 100), 100.0);
  copy = values;
  EXPECT_EQ(percentileOf(copy, 0), 1.0);
  std::vector<double> none{std::numeric_limits<double>::quiet_NaN()};
  EXPECT_EQ(percentileOf(none, 99), 0.0);
}

TEST(qualityFigures, AnEmptyRunHasNoFigures) {
  const QualityFigures f = measureQualityFigures(Trajectory{}, SurfaceMesh{});
  EXPECT_EQ(f.samples, 0u);
  EXPECT_EQ(f.speedFluctuation, 0.0);
  EXPECT_EQ(f.inconsistencyP99, 0.0);
}

// A region's box is taken from its samples, which are interpolated between the program's
// points: its side may fall short of the pass that lies on it by the rounding of the last
// digits. That pass is measured with the region, as the ramps of a re-optimised program treat it.
TEST(qualityFigures, APassOnTheWindowSideIsMeasured) {
  const Program program = interpretGcode("G21 G90 G17\nG0 X0 Y0 Z1\nG1 Z0 F1000\nG1 X10\nG1 Y0.5\nG1 X0\nG1 Y1\nG1 X10\nG0 Z5\nM2\n",
                                         "three-passes.nc")
                              .program;
  const SurfaceRun run = surfaceRun(std::make_shared<const Trajectory>(simulateRun(program, defaultMachine())), &program);
  FigureWindow everything;
  everything.lower = Vec3(-1, -1, -1);
  everything.upper = Vec3(11, 1, 1);
  FigureWindow rounded = everything, narrower = everything;
  rounded.upper.y() = 1 - 4e-14;
  narrower.upper.y() = 0.99;
  const std::size_t all = measureQualityFigures(*run.samples, *run.mesh, everything).samples;
  ASSERT_GT(all, 0u);
  EXPECT_EQ(measureQualityFigures(*run.samples, *run.mesh, rounded).samples, all);
  EXPECT_LT(measureQualityFigures(*run.samples, *run.mesh, narrower).samples, all);
}
