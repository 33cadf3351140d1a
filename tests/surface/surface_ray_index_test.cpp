// Picking the surface: the grid's first hit against every triangle tried, on surfaces of several
// shapes, and the sample a hit stands for.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "isurface/surface/passes.h"
#include "isurface/surface/surface_mesh.h"
#include "isurface/surface/surface_ray_index.h"
#include "surface_fixtures.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

// The nearest triangle along the ray by trying them all (the definition the grid must meet).
std::optional<double> bruteForce(const std::vector<Vec3>& p, const SurfaceMesh& mesh, const Vec3& origin,
                                 const Vec3& through) {
  const Vec3 d = through - origin;
  std::optional<double> best;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = p[t[0]], ab = p[t[1]] - a, ac = p[t[2]] - a;
    const Vec3 q = d.cross(ac);
    const double det = ab.dot(q);
    if (std::fabs(det) < 1e-300) continue;
    const Vec3 s = origin - a;
    const double u = s.dot(q) / det;
    const Vec3 r = s.cross(ab);
    const double v = d.dot(r) / det;
    const double hit = ac.dot(r) / det;
    if (u < 0 || v < 0 || u + v > 1 || hit < 0) continue;
    if (!best || hit < *best) best = hit;
  }
  return best;
}

struct Surface {
  Trajectory samples;
  SurfaceMesh mesh;
  std::vector<Vec3> positions;
};

Surface surfaceOf(Trajectory samples, std::size_t stride = 1) {
  Surface s;
  s.samples = std::move(samples);
  const PassSet passes = splitPasses(s.samples);
  MeshOptions options;
  options.stride = stride;
  s.mesh = buildSurfaceMesh(s.samples, passes, options);
  s.positions = meshPositions(s.samples, s.mesh);
  for (Vec3& p : s.positions) p = p.cast<float>().cast<double>();  // as the index keeps them
  return s;
}

// Rays from random points above (and, for some, beside or below) the surface towards random
// points on its footprint: the grid finds the same first hit as trying every triangle.
void expectSameHitsAsBruteForce(const Surface& s, double low, double span, unsigned seed) {
  ASSERT_FALSE(s.mesh.triangles.empty());
  const SurfaceRayIndex index(s.positions, std::make_shared<SurfaceMesh>(s.mesh));
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> across(low - 0.2 * span, low + 1.2 * span), height(-40, 60);
  int hits = 0, misses = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Vec3 origin(across(random), across(random), height(random));
    const Vec3 through(across(random), across(random), 0.5 * height(random) / 60);
    const auto expected = bruteForce(s.positions, s.mesh, origin, through);
    const auto got = index.firstHit(origin, through);
    ASSERT_EQ(expected.has_value(), got.has_value()) << "trial " << trial;
    if (!expected) {
      ++misses;
      continue;
    }
    ++hits;
    const Vec3 want = origin + *expected * (through - origin);
    EXPECT_LT((got->point - want).norm(), 1e-6) << "trial " << trial;
  }
  EXPECT_GT(hits, 40);
  EXPECT_GT(misses, 10);
}

TEST(SurfaceRayIndex, RasterOverADomeAgreesWithEveryTriangleTried) {
  const auto dome = [](double x, double y) {
    const double r2 = (x - 25) * (x - 25) + (y - 25) * (y - 25);
    return r2 < 400 ? std::sqrt(900 - r2) - 22.4 : 0.0;
  };
  expectSameHitsAsBruteForce(surfaceOf(zigZagRaster(51, 50, 1.0, 3000, dome, 101)), 0, 50, 1);
}

TEST(SurfaceRayIndex, ConcentricLoopsAgreeWithEveryTriangleTried) {
  // Loops about the origin: a surface the grid cannot align with.
  Surface s = surfaceOf(concentricLoops(16, 30, 1.5, 3000));
  for (Vec3& p : s.positions) p.z() = static_cast<float>(0.02 * p.x() * p.y() / 30);  // warped: no ray runs flat
  expectSameHitsAsBruteForce(s, -30, 60, 2);
}

TEST(SurfaceRayIndex, FlatSurfaceIsHitFromAboveAndBelowButNotAlongItsPlane) {
  const Surface s = surfaceOf(zigZagRaster(11, 10, 1.0, 3000, {}, 11));
  const SurfaceRayIndex index(s.positions, std::make_shared<SurfaceMesh>(s.mesh));
  const auto down = index.firstHit(Vec3(4.3, 5.7, 100), Vec3(4.3, 5.7, 0));
  ASSERT_TRUE(down);
  EXPECT_NEAR((down->point - Vec3(4.3, 5.7, 0)).norm(), 0, 1e-9);
  const auto up = index.firstHit(Vec3(4.3, 5.7, -100), Vec3(4.3, 5.7, -99));
  ASSERT_TRUE(up);
  EXPECT_NEAR(up->point.z(), 0, 1e-9);
  EXPECT_FALSE(index.firstHit(Vec3(-5, 5, 1e-3), Vec3(20, 5, 1e-3)));  // above it, parallel
  EXPECT_FALSE(index.firstHit(Vec3(30, 30, 10), Vec3(40, 40, 0)));    // beside it
  EXPECT_FALSE(index.firstHit(Vec3(4, 4, 10), Vec3(4, 4, 10)));       // no direction
  EXPECT_FALSE(index.firstHit(Vec3(4, 4, 10), Vec3(4, 4, std::nan(""))));
}

TEST(SurfaceRayIndex, TheNearerOfTwoLayersIsHit) {
  // A roughing level at z = -2 and the finish at z = 0 over the same footprint, one program.
  Trajectory both = zigZagRaster(11, 10, 1.0, 3000, [](double, double) { return -2.0; }, 11);
  const Trajectory finish = zigZagRaster(11, 10, 1.0, 3000, {}, 11);
  Surface lower = surfaceOf(both), upper = surfaceOf(finish);
  // One mesh of both layers: the upper's vertices after the lower's.
  SurfaceMesh mesh = lower.mesh;
  std::vector<Vec3> positions = lower.positions;
  const auto offset = static_cast<std::uint32_t>(positions.size());
  positions.insert(positions.end(), upper.positions.begin(), upper.positions.end());
  for (auto t : upper.mesh.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const SurfaceRayIndex index(positions, std::make_shared<SurfaceMesh>(mesh));
  const auto fromAbove = index.firstHit(Vec3(3.2, 4.1, 50), Vec3(3.3, 4.2, 0));
  ASSERT_TRUE(fromAbove);
  EXPECT_NEAR(fromAbove->point.z(), 0, 1e-9);
  EXPECT_GE(fromAbove->triangle, lower.mesh.triangles.size());
  const auto fromBelow = index.firstHit(Vec3(3.2, 4.1, -50), Vec3(3.3, 4.2, -3));
  ASSERT_TRUE(fromBelow);
  EXPECT_NEAR(fromBelow->point.z(), -2, 1e-9);
}

TEST(SurfaceRayIndex, HitOnAThinnedSurfaceNamesTheNearestSampleNotAVertex) {
  // 0.1 mm samples, every 8th a vertex: the hit's sample is the nearest of all samples.
  const Surface s = surfaceOf(zigZagRaster(6, 20, 1.0, 3000, {}, 201), 8);
  ASSERT_LT(s.mesh.vertexSample.size(), s.samples.size() / 4);
  const SurfaceRayIndex index(s.positions, std::make_shared<SurfaceMesh>(s.mesh));
  for (double x : {0.05, 3.33, 7.71, 12.26, 19.94}) {
    const auto hit = index.firstHit(Vec3(x, 2.02, 10), Vec3(x, 2.02, 0));
    ASSERT_TRUE(hit) << x;
    const std::size_t sample = sampleAtHit(s.samples, s.mesh, *hit);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < s.samples.size(); ++k) best = std::min(best, (s.samples.commanded(k) - hit->point).norm());
    EXPECT_NEAR((s.samples.commanded(sample) - hit->point).norm(), best, 1e-12) << x;
    EXPECT_NEAR(s.samples.commanded(sample).y(), 2.0, 1e-9) << x;
  }
}

TEST(SurfaceRayIndex, EmptyMeshAndBadPositionsAreNoHits) {
  const std::vector<Vec3> none;
  EXPECT_FALSE(SurfaceRayIndex(none, std::make_shared<SurfaceMesh>()).firstHit(Vec3(0, 0, 1), Vec3(0, 0, 0)));
  EXPECT_FALSE(SurfaceRayIndex(none, nullptr).firstHit(Vec3(0, 0, 1), Vec3(0, 0, 0)));
  Surface s = surfaceOf(zigZagRaster(3, 2, 1.0, 3000, {}, 3));
  for (Vec3& p : s.positions) p = Vec3::Constant(std::nan(""));
  EXPECT_FALSE(SurfaceRayIndex(s.positions, std::make_shared<SurfaceMesh>(s.mesh)).firstHit(Vec3(1, 1, 1), Vec3(1, 1, 0)));
}

}  // namespace
