// Quality prediction: regions where neighbouring passes disagree, found, bounded and ranked.
#include <gtest/gtest.h>

#include "surface_fixtures.h"
#include "isurface/analysis/quality_regions.h"

using namespace isurface;
using namespace isurface::test;

namespace {

// A raster of passes along X at 3000 mm/min in which one pass slows to 2000 mm/min between
// x = 20 and x = 30: the passes beside it disagree there, and only there.
Trajectory rasterWithOneSlowPatch() {
  PathSampler path(Vec3(0, 0, 0));
  for (int k = 0; k < 8; ++k) {
    const double y = k * 0.5;
    path.line(static_cast<std::uint32_t>(10 + 3 * k));
    if (k > 0) path.lineTo(Vec3(k % 2 ? 50 : 0, y, 0), 3000);
    const bool forward = k % 2 == 0;
    const double end = forward ? 50 : 0;
    auto at = [&](double x) { return Vec3(x, y, 0); };
    path.line(static_cast<std::uint32_t>(11 + 3 * k));
    const bool slow = k == 4;
    path.lineTo(at(forward ? 20 : 30), 3000);
    path.line(static_cast<std::uint32_t>(12 + 3 * k));
    path.lineTo(at(forward ? 30 : 20), slow ? 2000 : 3000);
    path.lineTo(at(end), 3000);
  }
  return path.take();
}

}  // namespace

TEST(qualityRegions, OneSlowPassMakesOneRegionWhereItDiffers) {
  const Trajectory t = rasterWithOneSlowPatch();
  const PassSet passes = splitPasses(t);
  ASSERT_EQ(passes.passes.size(), 8u);
  const SurfaceMesh mesh = buildSurfaceMesh(t, passes);
  QualityThresholds thresholds;
  thresholds.speedInconsistency = 500;   // mm/min: the patch differs by 1000
  thresholds.accelInconsistency = 1e9;   // only speed counts here
  thresholds.jerk = 1e12;
  const QualityReport report = findQualityRegions(t, mesh, thresholds);
  ASSERT_EQ(report.regions.size(), 1u);
  const QualityRegion& r = report.regions.front();
  EXPECT_NEAR(r.maxSpeedInconsistency, 1000, 1);
  EXPECT_GT(r.lower.x(), 19.0);
  EXPECT_LT(r.upper.x(), 31.0);
  EXPECT_NEAR(r.lower.y(), 1.5, 1e-9);  // the slow pass and both of its neighbours
  EXPECT_NEAR(r.upper.y(), 2.5, 1e-9);
  EXPECT_GT(r.area, 9.0);               // about 10 mm x 1 mm
  EXPECT_LT(r.area, 11.0);
  EXPECT_EQ(t.line[r.worstSample] % 3, 0u) << "the worst sample lies in a patch move (line 12 + 3k)";
}

TEST(qualityRegions, NothingBeyondTheThresholdsGivesNoRegion) {
  const Trajectory t = zigZagRaster(6, 40, 0.5, 3000);
  const SurfaceMesh mesh = buildSurfaceMesh(t, splitPasses(t));
  QualityThresholds thresholds;
  thresholds.jerk = 1e12;
  thresholds.accelInconsistency = 1e9;
  EXPECT_TRUE(findQualityRegions(t, mesh, thresholds).regions.empty());
}
