// The cutter-location surface: strips between neighbouring passes, gaps, loops, orientation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "surface_fixtures.h"
#include "isurface/base/diagnostic.h"
#include "isurface/surface/surface_mesh.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

// A raster of `passes` straight lines of `points` evenly spaced samples each, given directly
// as passes (one per line), zig-zag or all one way.
struct Grid {
  Trajectory samples;
  PassSet passes;
};

// Line 0 and one sample a millisecond, for samples given as positions alone.
void timeEveryMillisecond(Trajectory& samples) {
  const std::size_t n = samples.x.size();
  samples.line.assign(n, 0);
  samples.time.resize(n);
  for (std::size_t i = 0; i < n; ++i) samples.time[i] = 0.001 * double(i);
}

Grid planeGrid(int passes, int points, double spacing, double step, bool zigZag,
               const std::function<double(double, double)>& z = {}) {
  Grid g;
  g.passes.pattern = PathPattern::DirectionParallel;
  for (int k = 0; k < passes; ++k) {
    const std::size_t begin = g.samples.x.size();
    for (int i = 0; i < points; ++i) {
      const int along = zigZag && k % 2 == 1 ? points - 1 - i : i;
      const double x = along * spacing, y = k * step;
      g.samples.x.push_back(x);
      g.samples.y.push_back(y);
      g.samples.z.push_back(z ? z(x, y) : 0.0);
    }
    g.passes.passes.push_back({begin, g.samples.x.size()});
  }
  timeEveryMillisecond(g.samples);
  return g;
}

// Square loops of 20 mm stacked 0.5 mm apart in Z (a waterline finish of a vertical wall),
// `samples` on each stretch of a loop.
Trajectory stackedSquareLoops(int levels, int samples) {
  PathSampler path(Vec3(0, -10, 0));
  for (int level = 0; level < levels; ++level) {
    const double z = -0.5 * level;
    if (level > 0) path.lineTo(Vec3(0, -10, z), 500);
    path.lineTo(Vec3(10, -10, z), samples).lineTo(Vec3(10, 10, z), samples).lineTo(Vec3(-10, 10, z), samples);
    path.lineTo(Vec3(-10, -10, z), samples).lineTo(Vec3(0, -10, z), samples);
  }
  return path.take();
}

Vec3 triangleNormal(const Trajectory& s, const SurfaceMesh& m, const std::array<std::uint32_t, 3>& t) {
  const Vec3 a = s.commanded(m.vertexSample[t[0]]), b = s.commanded(m.vertexSample[t[1]]);
  const Vec3 c = s.commanded(m.vertexSample[t[2]]);
  return (b - a).cross(c - a);
}

double longestCrossEdge(const Trajectory& s, const SurfaceMesh& m) {
  double longest = 0;
  for (const auto& t : m.triangles)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = t[e], b = t[(e + 1) % 3];
      if (m.vertexPass[a] != m.vertexPass[b])
        longest = std::max(longest, (s.commanded(m.vertexSample[a]) - s.commanded(m.vertexSample[b])).norm());
    }
  return longest;
}

TEST(surface_mesh, PlaneRasterTrianglesAndNoHoles) {
  const int passes = 10, points = 41;
  for (const bool zigZag : {false, true}) {
    const Grid g = planeGrid(passes, points, 0.25, 0.5, zigZag);
    const SurfaceMesh m = buildSurfaceMesh(g.samples, g.passes);
    ASSERT_EQ(m.vertexSample.size(), std::size_t(passes * points));
    ASSERT_EQ(m.passFirstVertex.size(), std::size_t(passes + 1));
    // Each strip between two passes of n vertices: 2n - 2 triangles.
    EXPECT_EQ(m.triangles.size(), std::size_t((passes - 1) * (2 * points - 2))) << zigZag;
    // Boundary edges only on the outer border of the rectangle.
    const auto border = boundaryEdges(m);
    EXPECT_EQ(border.size(), std::size_t(2 * (points - 1) + 2 * (passes - 1)));
    for (const auto& [a, b] : border) {
      const Vec3 p = g.samples.commanded(m.vertexSample[a]), q = g.samples.commanded(m.vertexSample[b]);
      const bool onBorder = (p.x() == 0 && q.x() == 0) || (p.x() == 10 && q.x() == 10) ||
                            (p.y() == 0 && q.y() == 0) || (p.y() == 4.5 && q.y() == 4.5);
      EXPECT_TRUE(onBorder) << p.transpose() << " - " << q.transpose();
    }
    // Facing +Z, and no diagonal longer than the grid's (a walk that ran one pass backwards
    // would cross the whole strip).
    for (const auto& t : m.triangles) ASSERT_GT(triangleNormal(g.samples, m, t).z(), 0);
    EXPECT_LT(longestCrossEdge(g.samples, m), std::hypot(0.25, 0.5) + 1e-9);
  }
}

TEST(surface_mesh, NeighboursAreTheNearestMatchedVertices) {
  const Grid g = planeGrid(4, 21, 0.25, 0.5, true);
  const SurfaceMesh m = buildSurfaceMesh(g.samples, g.passes);
  for (std::size_t v = 0; v < m.vertexSample.size(); ++v) {
    const std::uint32_t pass = m.vertexPass[v];
    const Vec3 p = g.samples.commanded(m.vertexSample[v]);
    if (pass == 0) {
      EXPECT_EQ(m.previousPassNeighbour[v], kNoVertex);
    } else {
      ASSERT_NE(m.previousPassNeighbour[v], kNoVertex);
      EXPECT_EQ(m.vertexPass[m.previousPassNeighbour[v]], pass - 1);
      // Straight across on this grid.
      EXPECT_NEAR((g.samples.commanded(m.vertexSample[m.previousPassNeighbour[v]]) - p).norm(), 0.5, 1e-9);
    }
    if (pass == 3) {
      EXPECT_EQ(m.nextPassNeighbour[v], kNoVertex);
    } else {
      ASSERT_NE(m.nextPassNeighbour[v], kNoVertex);
      EXPECT_EQ(m.vertexPass[m.nextPassNeighbour[v]], pass + 1);
      EXPECT_NEAR((g.samples.commanded(m.vertexSample[m.nextPassNeighbour[v]]) - p).norm(), 0.5, 1e-9);
    }
  }
}

TEST(surface_mesh, StrideKeepsEveryStrideThSampleAndTheLast) {
  const Grid g = planeGrid(3, 101, 0.1, 0.5, true);
  MeshOptions options;
  options.stride = 7;
  const SurfaceMesh m = buildSurfaceMesh(g.samples, g.passes, options);
  // 0, 7, ..., 98 and 100: 16 per pass.
  ASSERT_EQ(m.vertexSample.size(), 48u);
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t first = m.passFirstVertex[k];
    EXPECT_EQ(m.vertexSample[first], g.passes.passes[k].begin);
    EXPECT_EQ(m.vertexSample[m.passFirstVertex[k + 1] - 1], g.passes.passes[k].end - 1);
    EXPECT_EQ(m.vertexSample[first + 1], g.passes.passes[k].begin + 7);
  }
  EXPECT_TRUE(boundaryEdges(m).size() == 2 * 15 + 2 * 2);
}

TEST(surface_mesh, GapLimitLeavesFarRegionsApart) {
  // Two rasters 10 mm apart in Y: the strip between their neighbouring passes is not made.
  Grid g = planeGrid(6, 21, 0.5, 0.5, true, [](double, double y) { return y > 2 ? 1.0 : 0.0; });
  for (std::size_t i = 0; i < g.samples.size(); ++i)
    if (g.samples.y[i] > 1.2) g.samples.y[i] += 10.0;
  const SurfaceMesh m = buildSurfaceMesh(g.samples, g.passes);
  EXPECT_EQ(m.triangles.size(), 4u * (2 * 21 - 2));  // strips 0-1, 1-2, 3-4, 4-5
  EXPECT_LE(longestCrossEdge(g.samples, m), 2.0);
  for (std::size_t v = m.passFirstVertex[2]; v < m.passFirstVertex[3]; ++v) EXPECT_EQ(m.nextPassNeighbour[v], kNoVertex);
  for (std::size_t v = m.passFirstVertex[3]; v < m.passFirstVertex[4]; ++v)
    EXPECT_EQ(m.previousPassNeighbour[v], kNoVertex);
  // A larger limit bridges them.
  MeshOptions wide;
  wide.gapLimit = 20;
  EXPECT_EQ(buildSurfaceMesh(g.samples, g.passes, wide).triangles.size(), 5u * (2 * 21 - 2));
}

TEST(surface_mesh, PassesOfDifferentLengthsOnlyMeetWhereTheyOverlap) {
  // The second pass covers only x in [5, 10] of the first's [0, 10].
  Grid g = planeGrid(2, 21, 0.5, 0.5, false);
  Trajectory& s = g.samples;
  for (std::size_t i = g.passes.passes[1].begin; i < g.passes.passes[1].end; ++i) s.x[i] = 5.0 + 0.5 * s.x[i];
  const SurfaceMesh m = buildSurfaceMesh(s, g.passes);
  EXPECT_GT(m.triangles.size(), 20u);
  EXPECT_LE(longestCrossEdge(s, m), 2.0);
  for (const auto& t : m.triangles)
    for (const std::uint32_t v : t) EXPECT_GE(s.x[m.vertexSample[v]], 3.0);
}

TEST(surface_mesh, AThinnedMeshWhoseStepsAreLongerThanTheGapStillJoinsItsPasses) {
  // Passes 0.3 mm apart, a vertex every 4 mm along them (a long raster thinned for a small
  // view); the passes of the two zig-zag directions are thinned from opposite ends, so their
  // vertices do not line up across.
  Grid g = planeGrid(10, 1003, 0.05, 0.3, true);
  MeshOptions thinned;
  thinned.stride = 80;
  const SurfaceMesh m = buildSurfaceMesh(g.samples, g.passes, thinned);
  double area = 0;
  for (const auto& t : m.triangles) area += 0.5 * triangleNormal(g.samples, m, t).norm();
  EXPECT_NEAR(area, 50.1 * 2.7, 0.5) << "the whole 50.1 x 2.7 mm plane";
  // Patches 3 mm apart stay apart however long the steps.
  Grid apart = planeGrid(4, 1003, 0.05, 3.0, true);
  EXPECT_TRUE(buildSurfaceMesh(apart.samples, apart.passes, thinned).triangles.empty());
  // A hole of samples left out of geometry (x 20 to 40 mm of the first pass) stays a hole, at
  // the full resolution as thinned.
  Grid holed = planeGrid(2, 1001, 0.05, 0.3, false);
  for (std::size_t i = 0; i < 1001; ++i)
    if (holed.samples.x[i] > 20.0 && holed.samples.x[i] < 40.0) holed.samples.x[i] = std::nan("");
  for (const std::size_t stride : {1u, 80u}) {
    MeshOptions options;
    options.stride = stride;
    const SurfaceMesh m = buildSurfaceMesh(holed.samples, holed.passes, options);
    for (const auto& t : m.triangles) {
      double low = 1e9, high = -1e9;
      for (const std::uint32_t v : t) low = std::min(low, holed.samples.x[m.vertexSample[v]]), high = std::max(high, holed.samples.x[m.vertexSample[v]]);
      EXPECT_FALSE(low < 21.0 && high > 39.0) << "a triangle over the hole, stride " << stride;
    }
  }
}

TEST(surface_mesh, NonFiniteSamplesAreNeverVertices) {
  Grid g = planeGrid(3, 21, 0.5, 0.5, true);
  g.samples.x[5] = std::numeric_limits<double>::quiet_NaN();
  g.samples.z[30] = std::numeric_limits<double>::infinity();
  const SurfaceMesh m = buildSurfaceMesh(g.samples, g.passes);
  EXPECT_EQ(m.vertexSample.size(), 61u);
  for (const std::uint32_t sample : m.vertexSample) {
    EXPECT_NE(sample, 5u);
    EXPECT_NE(sample, 30u);
  }
  for (const auto& t : m.triangles) EXPECT_TRUE(triangleNormal(g.samples, m, t).allFinite());
}

TEST(surface_mesh, StandstillAddsNoDegenerateTriangles) {
  Grid g = planeGrid(2, 11, 0.5, 0.5, false);
  // Repeat a sample of the first pass three times (the machine standing still).
  Trajectory& s = g.samples;
  for (auto* channel : {&s.x, &s.y, &s.z, &s.time}) channel->insert(channel->begin() + 4, 2, (*channel)[4]);
  std::vector<std::uint32_t> lines = s.line.toVector();
  lines.insert(lines.begin(), 2, 0);
  s.line = lines;
  g.passes.passes[0].end += 2;
  g.passes.passes[1].begin += 2;
  g.passes.passes[1].end += 2;
  const SurfaceMesh m = buildSurfaceMesh(s, g.passes);
  EXPECT_EQ(m.vertexSample.size(), 22u);
  EXPECT_EQ(m.triangles.size(), 20u);
  for (const auto& t : m.triangles) EXPECT_GT(triangleNormal(s, m, t).norm(), 1e-6);
}

TEST(surface_mesh, ClosedLoopsCloseAround) {
  const Trajectory s = concentricLoops(6, 10.0, 0.5, 2000);
  const PassSet passes = splitPasses(s);
  ASSERT_EQ(passes.pattern, PathPattern::ContourParallel);
  ASSERT_EQ(passes.passes.size(), 6u);
  const SurfaceMesh m = buildSurfaceMesh(s, passes);
  // Boundary edges only along the outermost and innermost loops: no seam where loops start.
  for (const auto& [a, b] : boundaryEdges(m)) {
    const std::uint32_t pa = m.vertexPass[a], pb = m.vertexPass[b];
    EXPECT_EQ(pa, pb);
    EXPECT_TRUE(pa == 0 || pa == 5) << pa;
  }
  for (const auto& t : m.triangles) ASSERT_GT(triangleNormal(s, m, t).z(), 0);
  EXPECT_LT(longestCrossEdge(s, m), 0.6);
}

TEST(surface_mesh, LoopsRunningOppositeWaysAreMatched) {
  // Alternating climb and conventional loops: clockwise, then counter-clockwise.
  PathSampler path(Vec3(10, 0, 0));
  for (int k = 0; k < 4; ++k) {
    const double r = 10.0 - 0.5 * k;
    if (k > 0) path.lineTo(Vec3(r, 0, 0), 2000);
    path.arc(Vec3::Zero(), k % 2 == 0 ? -2 * kPi : 2 * kPi, r, 0, 2000);
  }
  const Trajectory s = path.take();
  PassOptions options;
  options.pattern = PathPattern::ContourParallel;
  const PassSet passes = splitPasses(s, options);
  ASSERT_EQ(passes.passes.size(), 4u);
  const SurfaceMesh m = buildSurfaceMesh(s, passes);
  EXPECT_LT(longestCrossEdge(s, m), 0.6);
  for (const auto& t : m.triangles) ASSERT_GT(triangleNormal(s, m, t).z(), 0);
  for (const auto& [a, b] : boundaryEdges(m)) EXPECT_TRUE(m.vertexPass[a] == 0 || m.vertexPass[a] == 3);
}

TEST(surface_mesh, WaterlineWallsFaceOutwards) {
  // Square loops stacked 0.5 mm apart in Z: a vertical wall, faced away from the loops' inside.
  const Trajectory s = stackedSquareLoops(5, 2000);
  const PassSet passes = splitPasses(s);
  ASSERT_EQ(passes.passes.size(), 5u);
  const SurfaceMesh m = buildSurfaceMesh(s, passes);
  ASSERT_GT(m.triangles.size(), 0u);
  std::size_t outwards = 0;
  for (const auto& t : m.triangles) {
    const Vec3 n = triangleNormal(s, m, t);
    const Vec3 c = s.commanded(m.vertexSample[t[0]]);
    outwards += n.x() * c.x() + n.y() * c.y() > 0;
  }
  EXPECT_EQ(outwards, m.triangles.size());
}

// Strips made on two threads give the mesh made one strip after another: the same triangles,
// facing the same way (a wall's strips follow each other across the halves), and neighbours.
namespace {

// Edges that two triangles run the same way: where strips meet facing opposite ways.
std::size_t directedEdgesUsedTwice(const SurfaceMesh& mesh) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) edges.emplace_back(t[e], t[(e + 1) % 3]);
  std::sort(edges.begin(), edges.end());
  return static_cast<std::size_t>(edges.end() - std::unique(edges.begin(), edges.end()));
}

}  // namespace

TEST(surface_mesh, StripsMadeSideBySideGiveTheSameMesh) {
  const Trajectory walls = stackedSquareLoops(8, 800);
  const Grid wave = planeGrid(40, 301, 0.05, 0.3, true, [](double x, double y) { return std::sin(x) * std::cos(y); });
  // An open vertical wall (the plane x = 0, a zig-zag of passes 0.3 mm apart in Z): no inside to
  // face away from, so each strip faces as the strip before it, across the halves too.
  Grid wall = planeGrid(40, 301, 0.05, 0.3, true);
  wall.samples.z = wall.samples.y;
  for (double& z : wall.samples.z) z = -z;
  wall.samples.y = wall.samples.x;
  std::fill(wall.samples.x.begin(), wall.samples.x.end(), 0.0);
  for (const Trajectory* s : std::initializer_list<const Trajectory*>{&walls, &wave.samples, &wall.samples}) {
    const PassSet passes = s == &walls ? splitPasses(*s) : s == &wall.samples ? wall.passes : wave.passes;
    ASSERT_GT(passes.passes.size(), 4u);
    MeshOptions oneThread, twoThreads;
    oneThread.sideBySideVertices = std::numeric_limits<std::size_t>::max();
    twoThreads.sideBySideVertices = 0;
    const SurfaceMesh a = buildSurfaceMesh(*s, passes, oneThread), b = buildSurfaceMesh(*s, passes, twoThreads);
    ASSERT_GT(a.triangles.size(), 1000u);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.nextPassNeighbour, b.nextPassNeighbour);
    EXPECT_EQ(a.previousPassNeighbour, b.previousPassNeighbour);
    EXPECT_EQ(a.vertexSample, b.vertexSample);
    EXPECT_EQ(directedEdgesUsedTwice(a), 0u) << "neighbouring strips face opposite ways";
  }
}

TEST(surface_mesh, NormalsOfATiltedPlane) {
  const Grid g = planeGrid(5, 21, 0.5, 0.5, true, [](double x, double) { return 0.5 * x; });
  const SurfaceMesh m = buildSurfaceMesh(g.samples, g.passes);
  const std::vector<Vec3> positions = meshPositions(g.samples, m);
  const std::vector<Vec3> normals = vertexNormals(positions, m);
  const Vec3 expected = Vec3(-0.5, 0, 1).normalized();
  for (const Vec3& n : normals) EXPECT_NEAR((n - expected).norm(), 0, 1e-9);
}

TEST(surface_mesh, FeedbackSurfaceNeedsFeedback) {
  const Grid g = planeGrid(2, 5, 0.5, 0.5, true);
  MeshOptions options;
  options.feedback = true;
  EXPECT_THROW(buildSurfaceMesh(g.samples, g.passes, options), InputError);
  EXPECT_THROW(meshPositions(g.samples, buildSurfaceMesh(g.samples, g.passes), true), InputError);
}

TEST(surface_mesh, TransitionSurfaceHasNoHoles) {
  const std::string file = sourcePath("samples/transition-surface.nc");
  const Simulated sim = simulateGcode(readFile(file), file);
  PassOptions passOptions;
  passOptions.program = &sim.program;
  const PassSet passes = splitPasses(sim.samples, passOptions);
  ASSERT_EQ(passes.passes.size(), 81u);
  const SurfaceMesh m = buildSurfaceMesh(sim.samples, passes);
  const Trajectory& s = sim.samples;
  // Every boundary edge is on the part's outer border: the first or last pass, or the ends of
  // the passes (x near 0 or 80, where the step-overs were left out).
  std::size_t inside = 0;
  for (const auto& [a, b] : boundaryEdges(m)) {
    const std::uint32_t pa = m.vertexPass[a], pb = m.vertexPass[b];
    const Vec3 p = s.commanded(m.vertexSample[a]), q = s.commanded(m.vertexSample[b]);
    const bool firstOrLast = (pa == 0 && pb == 0) || (pa == 80 && pb == 80);
    const bool atEnds = (p.x() < 0.5 && q.x() < 0.5) || (p.x() > 79.5 && q.x() > 79.5);
    if (!firstOrLast && !atEnds) ++inside;
  }
  EXPECT_EQ(inside, 0u);
  for (const auto& t : m.triangles) ASSERT_GT(triangleNormal(s, m, t).z(), 0);
  EXPECT_LE(longestCrossEdge(s, m), 2.0);
}

// Its speed is measured by bench/surface_bench.cpp, not here: a timed test fails on a slow hour
// of a shared machine, not on a slow mesher.
TEST(surface_mesh, ManySamplesMeshWithoutAGap) {
  // 2 million samples: a zig-zag of 200 passes of 10,000 samples.
  const Grid g = planeGrid(200, 10000, 0.01, 0.5, true);
  const SurfaceMesh m = buildSurfaceMesh(g.samples, g.passes);
  EXPECT_EQ(m.triangles.size(), 199u * (2 * 10000 - 2));
}

}  // namespace

// The spacing of the passes is measured across them, however thinned the mesh: the toolpath's
// fading depends on it.
TEST(surface_mesh, PassSpacingIsMeasuredAcrossThePasses) {
  // 30 passes of 20 mm, 0.1 mm apart, at 600 mm/min: a sample every 0.01 mm along them.
  const Trajectory raster = zigZagRaster(30, 20.0, 0.1, 600.0);
  const PassSet passes = splitPasses(raster);
  ASSERT_EQ(passes.passes.size(), 30u);
  for (const std::size_t stride : {1, 50, 160}) {  // vertices 0.01, 0.5 and 1.6 mm apart
    MeshOptions options;
    options.stride = stride;
    const SurfaceMesh mesh = buildSurfaceMesh(raster, passes, options);
    EXPECT_NEAR(medianPassSpacing(meshPositions(raster, mesh), mesh), 0.1, 0.005) << "stride " << stride;
  }
  EXPECT_EQ(medianPassSpacing({}, SurfaceMesh{}), 0.0);
}

namespace {

// A Koch snowflake at Z 0 (as linuxcnc_flowsnake.ngc engraves one), 1 sample every 5 um, its
// three sides given as three passes: pieces of one curve, no surface between them.
Grid kochSnowflake(int level) {
  std::vector<Vec3> corners = {Vec3(0.25, 1.0, 0), Vec3(3.75, 1.0, 0), Vec3(2.0, 3.95, 0), Vec3(0.25, 1.0, 0)};
  for (int l = 0; l < level; ++l) {
    std::vector<Vec3> finer = {corners.front()};
    for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
      const Vec3 a = corners[i], b = corners[i + 1], d = b - a;
      const Vec3 tip = (a + b) / 2 + Vec3(d.y(), -d.x(), 0) / std::sqrt(12.0);
      finer.insert(finer.end(), {a + d / 3, tip, a + 2 * d / 3, b});
    }
    corners = std::move(finer);
  }
  Grid g;
  g.passes.pattern = PathPattern::ContourParallel;
  const std::size_t perSide = (corners.size() - 1) / 3;
  for (int side = 0; side < 3; ++side) {
    const std::size_t begin = g.samples.x.size();
    for (std::size_t i = side * perSide; i < (side + 1) * perSide; ++i) {
      const Vec3 a = corners[i], b = corners[i + 1];
      const int steps = std::max(1, static_cast<int>((b - a).norm() / 0.005));
      for (int s = 0; s < steps; ++s) {
        const Vec3 p = a + (b - a) * (double(s) / steps);
        g.samples.x.push_back(p.x()), g.samples.y.push_back(p.y()), g.samples.z.push_back(p.z());
      }
    }
    g.passes.passes.push_back({begin, g.samples.x.size()});
  }
  timeEveryMillisecond(g.samples);
  return g;
}

}  // namespace

// Passes that cross and double back over each other are no surface: no triangles between them,
// and the reason says so rather than that they lie too far apart.
TEST(surface_mesh, PiecesOfOneEngravedCurveMakeNoSurface) {
  const Grid koch = kochSnowflake(4);
  const SurfaceMesh mesh = buildSurfaceMesh(koch.samples, koch.passes);
  EXPECT_EQ(mesh.foldedStrips(), 2u);
  EXPECT_TRUE(mesh.triangles.empty()) << mesh.triangles.size();
  for (std::size_t v = 0; v < mesh.vertexSample.size(); ++v) {
    EXPECT_EQ(mesh.nextPassNeighbour[v], kNoVertex);
    EXPECT_EQ(mesh.previousPassNeighbour[v], kNoVertex);
  }
  EXPECT_NE(whyNoTriangles(koch.passes, 2.0, mesh.foldedStrips()).find("cross and double back"), std::string::npos);
  // Passes side by side, flat or curved, zig-zag or one way, fold nowhere.
  for (const bool zigZag : {true, false}) {
    const Grid relief = planeGrid(20, 200, 0.1, 0.3, zigZag, [](double x, double y) { return std::sin(x) * std::cos(y); });
    const SurfaceMesh surface = buildSurfaceMesh(relief.samples, relief.passes);
    EXPECT_EQ(surface.foldedStrips(), 0u);
    EXPECT_EQ(surface.triangles.size(), 2u * 19 * 199);
  }
}

// A raster whose passes 5, 10 and 15 are each followed by a pass cut across them (corner to
// corner over the pass and back over the next): that pass crosses and doubles back over the one
// before, so it is left out, but the passes either side of it still make their strip, and the
// note names the lines of what was left out.
TEST(surface_mesh, APassCutAcrossItsNeighboursCostsNoStripOfTheSurface) {
  constexpr int kPasses = 21, kPoints = 201;
  constexpr double kSpacing = 0.1, kStep = 0.5;  // mm
  Grid g;
  g.passes.pattern = PathPattern::DirectionParallel;
  std::vector<std::uint32_t> lines;
  const auto addPass = [&](const std::function<Vec3(double)>& at, std::uint32_t firstLine) {
    const std::size_t begin = g.samples.x.size();
    for (int i = 0; i < kPoints; ++i) {
      const Vec3 p = at(double(i) / (kPoints - 1));
      g.samples.x.push_back(p.x()), g.samples.y.push_back(p.y()), g.samples.z.push_back(p.z());
      lines.push_back(firstLine + static_cast<std::uint32_t>(i / 50));  // 5 lines a pass
    }
    g.passes.passes.push_back({begin, g.samples.x.size()});
  };
  const double length = (kPoints - 1) * kSpacing;
  std::uint32_t line = 10;
  std::vector<std::size_t> crossing;
  for (int k = 0; k < kPasses; ++k) {
    const double y = k * kStep;
    const bool back = k % 2 == 1;
    addPass([&](double u) { return Vec3((back ? 1 - u : u) * length, y, 0.2 * std::sin(y)); }, line);
    line += 5;
    if (k == 5 || k == 10 || k == 15) {
      crossing.push_back(g.passes.passes.size());
      addPass([&](double u) { return Vec3((1 - u) * length, y + 0.8 * (0.5 - u), 0.2 * std::sin(y)); }, line);
      line += 5;
    }
  }
  timeEveryMillisecond(g.samples);
  g.samples.line = lines;

  const SurfaceMesh mesh = buildSurfaceMesh(g.samples, g.passes);
  EXPECT_EQ(mesh.passesLeftOut, crossing);
  EXPECT_TRUE(mesh.foldedPairs.empty());
  // Every strip between the raster's own neighbours is there, and nothing else.
  EXPECT_EQ(mesh.triangles.size(), 2u * (kPasses - 1) * (kPoints - 1));
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t) EXPECT_EQ(std::count(crossing.begin(), crossing.end(), mesh.vertexPass[v]), 0);
  // Each raster pass is matched to its neighbours across the left-out pass.
  const std::uint32_t beforeCrossing = static_cast<std::uint32_t>(mesh.passFirstVertex[crossing[0] - 1]);
  ASSERT_NE(mesh.nextPassNeighbour[beforeCrossing], kNoVertex);
  EXPECT_EQ(mesh.vertexPass[mesh.nextPassNeighbour[beforeCrossing]], crossing[0] + 1);
  // Facing up throughout, the bridged strips too.
  const std::vector<Vec3> positions = meshPositions(g.samples, mesh);
  for (const auto& t : mesh.triangles)
    EXPECT_GT((positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]).z(), 0);

  const std::string note = passesNotJoined(g.samples, g.passes, mesh);
  EXPECT_NE(note.find("3 passes cross and double back"), std::string::npos) << note;
  EXPECT_NE(note.find("lines 40-44"), std::string::npos) << note;  // the pass after raster pass 5
  EXPECT_NE(note.find(kFoldedPassesNote), std::string::npos) << note;
}
