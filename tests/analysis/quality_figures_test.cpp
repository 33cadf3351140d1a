// The figures a run is judged by: nearest-rank percentiles, and what a window takes in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <limits>
#include <vector>

#include "isurface/analysis/quality_figures.h"
#include "isurface/analysis/quantities.h"
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

namespace {

// The nearest-rank p99 of `values`, sorted in full.
double p99(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(std::ceil(0.99 * double(values.size()))) - 1];
}

}  // namespace

// The values a run's figures are taken from are derived once and measured in several windows
// (a candidate's region and its whole program): each window's figures are those of the
// definitions in docs/optimising.md, "Quality figures", over that window's samples, computed
// here directly from the samples.
TEST(qualityFigures, OneRunsValuesMeasuredInTwoWindowsAreEachWindowsFigures) {
  std::string text = "G21 G90 G17\nG0 X0 Y0 Z1\nG1 Z0 F3000\n";
  for (int pass = 0; pass < 12; ++pass) {
    const double y = 0.4 * pass;
    text += "G1 Y" + std::to_string(y) + "\n";  // the step-over, at the end the last pass left
    for (int k = 0; k <= 40; ++k) {
      const double x = pass % 2 ? 20 - 0.5 * k : 0.5 * k;
      text += "G1 X" + std::to_string(x) + " Z" + std::to_string(0.3 * std::sin(0.4 * x + 0.2 * pass)) + "\n";
    }
  }
  text += "G0 Z5\nM2\n";
  const Program program = interpretGcode(text, "wavy-raster.nc").program;
  const SurfaceRun run = surfaceRun(std::make_shared<const Trajectory>(simulateRun(program, defaultMachine())), &program);
  const Trajectory& t = *run.samples;
  const SurfaceMesh& mesh = *run.mesh;
  ASSERT_TRUE(t.hasFeedback());
  const FigureValues values = figureValues(t, mesh);
  FigureWindow right;
  right.lower = Vec3(10, -1, -1);
  right.upper = Vec3(30, 10, 1);
  const std::vector<double> speed = sampleQuantity(Quantity::Speed, t), jerk = sampleQuantity(Quantity::Jerk, t);
  const std::vector<float> inconsistency = vertexQuantity(Quantity::SpeedInconsistency, t, mesh);
  const std::vector<float> deviation = vertexQuantity(Quantity::Deviation, t, mesh);
  const long half = std::lround(0.05 / t.cycle);  // samples in half the 100 ms moving average
  for (const FigureWindow& window : {FigureWindow{}, right}) {
    double squares = 0, inconsistencySum = 0;
    std::vector<double> jerks, inconsistencies, deviations;
    for (std::size_t v = 0; v < mesh.vertexSample.size(); ++v) {
      const long i = mesh.vertexSample[v];
      if (t.x[i] < window.lower.x() || t.x[i] > window.upper.x()) continue;
      double sum = 0;
      long n = 0;
      for (long k = std::max(0L, i - half); k <= std::min(long(t.size()) - 1, i + half); ++k, ++n) sum += speed[k];
      squares += std::pow(speed[i] - sum / double(n), 2);
      jerks.push_back(jerk[i]);
      inconsistencies.push_back(inconsistency[v]);
      inconsistencySum += inconsistency[v];
      deviations.push_back(std::fabs(deviation[v]));
    }
    const QualityFigures f = measureQualityFigures(values, t, mesh, window);
    ASSERT_EQ(f.samples, jerks.size());
    EXPECT_NEAR(f.speedFluctuation, std::sqrt(squares / double(jerks.size())), 1e-9 * f.speedFluctuation);
    EXPECT_EQ(f.jerkP99, p99(jerks));
    EXPECT_EQ(f.inconsistencyP99, p99(inconsistencies));
    EXPECT_NEAR(f.inconsistencyMean, inconsistencySum / double(inconsistencies.size()), 1e-9 * f.inconsistencyMean);
    EXPECT_EQ(f.deviationP99, p99(deviations));
    EXPECT_TRUE(f.hasDeviation);
  }
  EXPECT_LT(measureQualityFigures(values, t, mesh, right).samples, measureQualityFigures(values, t, mesh).samples);
  EXPECT_GT(measureQualityFigures(values, t, mesh, right).samples, 0u);
}

// A sample whose speed is not finite (a dump's own "v" channel with gaps) is left out of every
// figure, and only it: not its neighbours in the moving average.
TEST(qualityFigures, SamplesOfNoFiniteSpeedAreLeftOut) {
  const Program program = interpretGcode("G21 G90 G17\nG0 X0 Y0 Z1\nG1 Z0 F2000\nG1 X10\nG1 Y0.5\nG1 X0\nG1 Y1\nG1 X10\nG0 Z5\nM2\n",
                                         "three-passes.nc")
                              .program;
  auto samples = std::make_shared<Trajectory>(simulateRun(program, defaultMachine()));
  const SurfaceRun run = surfaceRun(samples, &program);
  const SurfaceMesh& mesh = *run.mesh;
  ASSERT_GT(mesh.vertexSample.size(), 20u);
  const std::size_t all = measureQualityFigures(*samples, mesh).samples;
  std::vector<double> speed = sampleQuantity(Quantity::Speed, *samples);
  speed[mesh.vertexSample[5]] = std::numeric_limits<double>::quiet_NaN();
  speed[mesh.vertexSample[10]] = std::numeric_limits<double>::infinity();
  speed[mesh.vertexSample[15]] = -std::numeric_limits<double>::infinity();
  samples->extra.emplace_back("v", speed);
  const QualityFigures f = measureQualityFigures(*samples, mesh);
  EXPECT_EQ(f.samples, all - 3);
  EXPECT_TRUE(std::isfinite(f.speedFluctuation));
  EXPECT_GT(f.speedFluctuation, 0.0);
  FigureValues ofAnotherSurface = figureValues(*samples, mesh);
  ofAnotherSurface.jerk.pop_back();
  EXPECT_THROW(measureQualityFigures(ofAnotherSurface, *samples, mesh), std::invalid_argument);
}
