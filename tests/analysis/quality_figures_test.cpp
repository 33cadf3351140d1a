// The figures a run is judged by: nearest-rank percentiles, and what a window takes in.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "isurface/analysis/quality_figures.h"

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
