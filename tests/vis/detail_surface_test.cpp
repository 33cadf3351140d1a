// The close-up the window shows where the camera looks: only the part of the surface inside the
// box, finer than the whole map, coloured as the map is.
#include <gtest/gtest.h>

#include <cmath>

#include "isurface/vis/detail_surface.h"
#include "isurface/map/quality_map.h"
#include "isurface/vis/quality_scene.h"
#include "surface_fixtures.h"

using namespace isurface;

namespace {

// 40 passes of 100 mm, 0.5 mm apart, at 1800 mm/min: about 3,300 samples a pass.
Trajectory wavyRaster() {
  return test::zigZagRaster(40, 100.0, 0.5, 1800.0, [](double x, double y) { return 0.5 * std::sin(x * 0.2) * std::cos(y * 0.3); });
}

}  // namespace

TEST(detailSurface, APassIsCutToItsStretchInsideTheBox) {
  const Trajectory t = wavyRaster();
  vis::QualityMapRequest request;
  const vis::QualityMap map = vis::buildQualityMap(t, nullptr, request);
  const PassSet inBox = vis::passesInBox(t, map.passes, Vec3(20, 5, -1), Vec3(30, 10, 1));
  // Passes at y = 5.0, 5.5, ..., 10.0.
  ASSERT_EQ(inBox.passes.size(), 11u);
  for (const Pass& pass : inBox.passes) {
    for (std::size_t i = pass.begin; i < pass.end; ++i) {
      EXPECT_GE(t.x[i], 20.0 - 1e-9);
      EXPECT_LE(t.x[i], 30.0 + 1e-9);
    }
    // Every sample of the pass inside the box is kept: the ones just outside are not.
    EXPECT_TRUE(pass.begin == 0 || t.x[pass.begin - 1] < 20 || t.x[pass.begin - 1] > 30);
    EXPECT_TRUE(pass.end == t.size() || t.x[pass.end] < 20 || t.x[pass.end] > 30 ||
                std::abs(t.y[pass.end] - t.y[pass.begin]) > 0.1);
  }
  EXPECT_TRUE(vis::passesInBox(t, map.passes, Vec3(200, 200, 0), Vec3(210, 210, 0)).passes.empty());
}

TEST(detailSurface, IsFinerThanTheMapInsideTheBoxAndColouredAlike) {
  const Trajectory t = wavyRaster();
  vis::QualityMapRequest request;
  request.quantity = Quantity::Speed;
  request.maxVertices = 5'000;  // the whole map: every ~25th sample
  const vis::QualityMap map = vis::buildQualityMap(t, nullptr, request);
  const Vec3 lower(40, 2, -1), upper(50, 6, 1);
  const auto detail = vis::buildDetailSurface(t, map.passes, request, lower, upper);
  ASSERT_TRUE(detail.has_value());
  // The box holds 9 passes of ~330 samples: 3,000 samples, under the 5,000 asked for: all of them.
  EXPECT_EQ(detail->stride, 1u);
  std::size_t mapVerticesInBox = 0;
  for (const Vec3& p : map.data.positions)
    mapVerticesInBox += p.x() >= lower.x() && p.x() <= upper.x() && p.y() >= lower.y() && p.y() <= upper.y();
  EXPECT_GT(detail->positions.size(), 10 * mapVerticesInBox);
  for (const Vec3& p : detail->positions) {
    EXPECT_GE(p.x(), lower.x() - 1e-9);
    EXPECT_LE(p.x(), upper.x() + 1e-9);
  }
  EXPECT_GT(detail->mesh->triangles.size(), detail->positions.size());
  // A vertex on the same sample as one of the map has the same value.
  ASSERT_EQ(detail->scalars.size(), detail->positions.size());
  std::size_t same = 0;
  for (std::size_t v = 0; v < map.mesh->vertexSample.size(); ++v)
    for (std::size_t w = 0; w < detail->mesh->vertexSample.size(); ++w)
      if (detail->mesh->vertexSample[w] == map.mesh->vertexSample[v]) {
        EXPECT_FLOAT_EQ(detail->scalars[w], map.data.scalars[v]);
        ++same;
      }
  EXPECT_GT(same, 10u);
  // Fewer vertices asked for: thinned along the passes as the map is.
  request.maxVertices = 500;
  EXPECT_GE(vis::buildDetailSurface(t, map.passes, request, lower, upper)->stride, 6u);
  EXPECT_FALSE(vis::buildDetailSurface(t, map.passes, request, Vec3(300, 300, 0), Vec3(310, 310, 0)).has_value());
}

TEST(detailSurface, TheSceneShowsItInsteadOfTheWholeSurfaceAtRest) {
  const Trajectory t = wavyRaster();
  vis::QualityMapRequest request;
  request.maxVertices = 5'000;
  request.coarseVertices = 1'000;
  const vis::QualityMap map = vis::buildQualityMap(t, nullptr, request);
  vis::QualityScene scene(map.data, map.style);
  EXPECT_FALSE(scene.showsDetail());
  const auto detail = vis::buildDetailSurface(t, map.passes, request, Vec3(40, 2, -1), Vec3(50, 6, 1));
  ASSERT_TRUE(detail.has_value());
  scene.setDetailSurface(&*detail);
  EXPECT_TRUE(scene.showsDetail());
  scene.setDetailSurface(nullptr);
  EXPECT_FALSE(scene.showsDetail());
}
