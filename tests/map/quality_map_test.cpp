// The quality map is built by the core without VTK: this test links isurface_map alone (no
// VTK, no OSMesa) and checks what every output of a map relies on: its passes, its surface, the
// values it colours by in the units it shows, and its range policy.
#include <gtest/gtest.h>

#include <cmath>

#include "isurface/map/quality_map.h"

using namespace isurface;

namespace {

// A zig-zag raster of 9 passes along X, 10 mm long and 0.5 mm apart, sampled every millisecond
// at 3000 mm/min, except 1000 mm/min from x = 4 to x = 6 on every pass.
Trajectory slowBandRaster() {
  Trajectory t;
  t.cycle = 0.001;
  for (int pass = 0; pass < 9; ++pass) {
    const double y = 0.5 * pass;
    double travelled = 0;
    while (travelled <= 10.0) {
      const double x = pass % 2 == 0 ? travelled : 10.0 - travelled;
      t.x.push_back(x);
      t.y.push_back(y);
      t.z.push_back(0.1 * std::sin(x));
      const bool slow = x > 4.0 && x < 6.0;
      travelled += (slow ? 1000.0 : 3000.0) / 60.0 * t.cycle;
    }
    if (pass < 8) {  // the step over to the next pass
      for (int k = 1; k <= 10; ++k) {
        t.x.push_back(pass % 2 == 0 ? 10.0 + 0.0 : 0.0);
        t.y.push_back(y + 0.05 * k);
        t.z.push_back(0.1 * std::sin(pass % 2 == 0 ? 10.0 : 0.0));
      }
    }
  }
  t.line.assign(t.x.size(), 0);
  return t;
}

}  // namespace

TEST(qualityMapCore, ASpeedMapOfARasterWithoutVtk) {
  const Trajectory samples = slowBandRaster();
  vis::QualityMapRequest request;
  request.quantity = Quantity::Speed;
  const vis::QualityMap map = vis::buildQualityMap(samples, nullptr, request);
  EXPECT_EQ(map.passes.pattern, PathPattern::DirectionParallel);
  EXPECT_EQ(map.passes.passes.size(), 9u);
  ASSERT_TRUE(map.mesh);
  EXPECT_GT(map.mesh->triangles.size(), 1000u);
  ASSERT_EQ(map.data.scalars.size(), map.data.positions.size());
  EXPECT_EQ(map.style.unit, "mm/min");
  // The slow band and the rest, in mm/min, on the vertices that lie in them.
  double slowest = 1e9, fastest = 0;
  for (std::size_t v = 0; v < map.data.positions.size(); ++v) {
    const double x = map.data.positions[v].x();
    if (x > 4.5 && x < 5.5) slowest = std::min(slowest, double(map.data.scalars[v]));
    if (x > 1.0 && x < 3.0) fastest = std::max(fastest, double(map.data.scalars[v]));
  }
  EXPECT_NEAR(slowest, 1000.0, 20.0);
  EXPECT_NEAR(fastest, 3000.0, 20.0);
  // The 1-99 % range of the values, inside their extent (the path rises and falls by 0.1 mm, so
  // along it the speed is up to 1.005 times that along X).
  EXPECT_GE(map.style.range.lo, 999.0);
  EXPECT_LE(map.style.range.hi, 3000.0 * std::sqrt(1.01));
  EXPECT_LT(map.style.range.lo, map.style.range.hi);
  // A fixed range is the range shown, whatever the values.
  request.fixedRange = ValueRange{2000, 2500};
  const vis::QualityMap fixed = vis::buildQualityMap(samples, nullptr, request);
  EXPECT_EQ(fixed.style.range.lo, 2000);
  EXPECT_EQ(fixed.style.range.hi, 2500);
}
