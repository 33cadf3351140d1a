// The coarse surface drawn while the camera moves: about the vertices asked for, spread over
// the passes as evenly one way as the other, joined into one surface over the whole part.
#include <gtest/gtest.h>

#include <cmath>

#include "isurface/surface/coarse_mesh.h"

using namespace isurface;

namespace {

// A zig-zag raster of `passes` passes of `length` mm, `spacing` mm apart, `perPass` samples each.
Trajectory raster(int passes, double length, double spacing, int perPass) {
  Trajectory t;
  for (int p = 0; p < passes; ++p)
    for (int i = 0; i < perPass; ++i) {
      const double u = length * i / (perPass - 1);
      t.x.push_back(p % 2 == 0 ? u : length - u);
      t.y.push_back(p * spacing);
      t.z.push_back(0.1 * std::sin(u));
      t.time.push_back(double(t.time.size()) * 1e-3);
      t.line.push_back(static_cast<std::uint32_t>(p + 1));
    }
  return t;
}

PassSet passesOf(int passes, int perPass) {
  PassSet set;
  for (int p = 0; p < passes; ++p) set.passes.push_back({std::size_t(p) * perPass, std::size_t(p + 1) * perPass});
  return set;
}

}  // namespace

TEST(coarseMesh, AboutTheVerticesAskedForSpreadEvenlyOverTheWholePart) {
  // 400 passes 0.4 mm apart (160 mm) of 150 mm, 3,000 samples each: 1.2 M samples.
  const Trajectory t = raster(400, 150, 0.4, 3000);
  const PassSet passes = passesOf(400, 3000);
  const SurfaceMesh coarse = buildCoarseSurfaceMesh(t, passes, MeshOptions{}, 30'000);
  const std::size_t vertices = coarse.vertexSample.size();
  EXPECT_GT(vertices, 20'000u);
  EXPECT_LT(vertices, 40'000u);
  // Passes are left out as much as samples along them: about sqrt(30,000 * 160 / 150) = 179
  // passes of 179 vertices, not 400 passes of 75.
  const std::size_t rows = coarse.passFirstVertex.size() - 1;
  EXPECT_GT(rows, 120u);
  EXPECT_LT(rows, 260u);
  // One surface over the whole part: the passes kept are still joined, corner to corner.
  EXPECT_GT(coarse.triangles.size(), vertices);
  double lowX = 1e9, highX = -1e9, lowY = 1e9, highY = -1e9;
  for (const std::uint32_t i : coarse.vertexSample)
    lowX = std::min(lowX, t.x[i]), highX = std::max(highX, t.x[i]), lowY = std::min(lowY, t.y[i]), highY = std::max(highY, t.y[i]);
  EXPECT_LT(lowX, 1.0);
  EXPECT_GT(highX, 149.0);
  EXPECT_LT(lowY, 1.0);
  EXPECT_GT(highY, 158.0);
}

TEST(coarseMesh, FewPassesOrFewSamplesKeepEveryPass) {
  const Trajectory t = raster(6, 50, 1.0, 200);
  const SurfaceMesh coarse = buildCoarseSurfaceMesh(t, passesOf(6, 200), MeshOptions{}, 30'000);
  EXPECT_EQ(coarse.passFirstVertex.size(), 7u);
  EXPECT_EQ(coarse.vertexSample.size(), 1200u);
  const SurfaceMesh none = buildCoarseSurfaceMesh(t, PassSet{}, MeshOptions{}, 30'000);
  EXPECT_TRUE(none.triangles.empty());
}
