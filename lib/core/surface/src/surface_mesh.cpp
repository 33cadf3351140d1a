// The cutter-location surface: a triangle strip between each pass and the next.
#include "isurface/surface/surface_mesh.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <system_error>
#include <limits>

#include <fmt/format.h>

#include "isurface/base/diagnostic.h"

namespace isurface {

namespace {

// Positions of one kind (commanded or feedback) read in place from the sample arrays.
struct PositionSource {
  const Trajectory& s;
  bool feedback;
  Vec3 at(std::size_t i) const { return feedback ? s.feedback(i) : s.commanded(i); }
  bool finiteAt(std::size_t i) const {
    const Vec3 p = at(i);
    return (p - p).sum() == 0;  // NaN and infinities give NaN
  }
};

PositionSource positionSource(const Trajectory& s, bool feedback) {
  if (feedback && !s.hasFeedback())
    throw InputError(Diagnostic{s.source, 0, 0, "no feedback channels (fb_x, fb_y, fb_z) to build the feedback surface on"});
  return {s, feedback};
}

// Two vertices closer than this are one point (mm).
constexpr double kSamePoint = 1e-6;

// Every stride-th finite sample of each pass and its last one; a sample on the point of the
// vertex before it (standstill) adds nothing.
void pickVertices(const PositionSource& p, const PassSet& passes, std::size_t stride, SurfaceMesh& mesh) {
  std::size_t estimate = 0;
  for (const Pass& pass : passes.passes) estimate += pass.size() / stride + 2;
  mesh.vertexSample.reserve(estimate);
  mesh.vertexPass.reserve(estimate);
  mesh.passFirstVertex.reserve(passes.passes.size() + 1);
  const double same2 = kSamePoint * kSamePoint;
  for (std::size_t k = 0; k < passes.passes.size(); ++k) {
    const Pass& pass = passes.passes[k];
    const std::size_t first = mesh.vertexSample.size();
    mesh.passFirstVertex.push_back(first);
    const auto add = [&](std::size_t i, bool last) {
      if (!p.finiteAt(i)) return;
      if (mesh.vertexSample.size() > first) {
        const std::uint32_t previous = mesh.vertexSample.back();
        if ((p.at(i) - p.at(previous)).squaredNorm() <= same2) {
          // The pass's last sample stands for a standstill at its end.
          if (last && mesh.vertexSample.size() > first + 1) mesh.vertexSample.back() = static_cast<std::uint32_t>(i);
          return;
        }
      }
      mesh.vertexSample.push_back(static_cast<std::uint32_t>(i));
      mesh.vertexPass.push_back(static_cast<std::uint32_t>(k));
    };
    if (pass.end <= pass.begin) continue;
    std::size_t i = pass.begin;
    for (; i + 1 < pass.end; i += stride) add(i, false);
    // A loop that ends nearer its first vertex than the vertex before may end a fraction of a
    // sample into the link to the next loop: its first vertex closes it instead.
    const std::size_t last = pass.end - 1;
    if (passes.pattern == PathPattern::ContourParallel && mesh.vertexSample.size() >= first + 3 && p.finiteAt(last)) {
      const Vec3 end = p.at(last);
      if ((end - p.at(mesh.vertexSample[first])).norm() < 0.5 * (end - p.at(mesh.vertexSample.back())).norm()) continue;
    }
    add(last, true);
  }
  mesh.passFirstVertex.push_back(mesh.vertexSample.size());
}

// Walk order over one pass's vertices: open (first to last, or last to first) or closed (a
// cycle starting anywhere, either way round).
struct PassWalk {
  std::uint32_t first = 0;  // first vertex of the pass
  std::size_t count = 0;    // vertices in the walk's cycle (closed) or line (open)
  std::size_t offset = 0;   // closed: where the walk starts
  bool reversed = false;
  bool closed = false;
  std::size_t steps() const { return closed ? count : count - 1; }
  std::uint32_t vertex(std::size_t i) const {
    std::size_t k = closed ? (offset + i) % count : i;
    if (reversed) k = closed ? (count - k) % count : count - 1 - k;
    return first + static_cast<std::uint32_t>(k);
  }
};

using Triangle = std::array<std::uint32_t, 3>;

// A strip's triangles as made (A's edges forward), [begin, end) of a triangle list, and what
// orienting them needs.
struct StripShape {
  std::size_t begin = 0, end = 0;
  Vec3 normal = Vec3::Zero();  // sum of the triangles' (doubled) area vectors
  double areaSum = 0;
  double facingUp = 0, facingDown = 0;  // of the doubled area, |z| of the triangles facing +Z, -Z as made
  bool reversedB = false;      // the walk ran pass B backward
  bool folded = false;         // its triangles folded over one another: none kept (see folds)
  bool leftOut = false;        // its pass A crosses its neighbours and is left out: no strip
  bool wall() const { return !(std::fabs(normal.z()) >= 0.5 * areaSum); }
};

// Of a strip's area: facing up or down at least this much, it is no wall; facing the other way
// by more than this much, it folds (StripBuilder::folds). Measured: every strip of the bundled
// samples, cameo.nc, stellabee1.ngc and eight programs of another generator folds by 0.000;
// those of linuxcnc_flowsnake.ngc (a Koch curve) by 0.37-0.42, of linuxcnc_daisy.ngc up to 0.45.
constexpr double kFacingShare = 0.5;
constexpr double kFoldedShare = 0.1;

class StripBuilder {
 public:
  StripBuilder(const PositionSource& p, const SurfaceMesh& mesh, double gapLimit, std::size_t stride,
               PathPattern pattern, std::vector<float>& bestNext, std::vector<float>& bestPrevious)
      : p_(p), mesh_(mesh), gap2_(gapLimit * gapLimit), gapLimit_(gapLimit), stride_(stride), pattern_(pattern),
        bestNext_(bestNext), bestPrevious_(bestPrevious) {}

  // Triangles between pass k (A) and pass k + 1 (B), appended to `triangles`; the matched
  // vertices of neighbouring passes written into `out` (strips write disjoint vertices' entries,
  // so strips can be made side by side).
  StripShape make(std::size_t k, std::vector<Triangle>& triangles, SurfaceMesh& out) {
    return make(k, k + 1, triangles, out);
  }
  // Triangles between pass kA and a later pass kB.
  StripShape make(std::size_t kA, std::size_t kB, std::vector<Triangle>& triangles, SurfaceMesh& out);
  // Lets go of the neighbours a strip between passes kA and kB matched.
  void forget(std::size_t kA, std::size_t kB, SurfaceMesh& out);
  // Faces a strip's triangles +Z, or, on a wall, the way the strip before it faced (its
  // `previousDirection`); returns how pass B's own edges ended up directed (+1 forward, -1
  // backward, 0 no triangles) for the next strip.
  int orient(std::size_t k, const StripShape& strip, int previousDirection, std::vector<Triangle>& triangles) const;

 private:
  Vec3 pos(std::uint32_t v) const { return p_.at(mesh_.vertexSample[v]); }
  double d2(std::uint32_t a, std::uint32_t b) const { return (pos(a) - pos(b)).squaredNorm(); }
  std::size_t nearest(std::uint32_t first, std::size_t count, const Vec3& to, double* distance2 = nullptr) const;
  bool closedPass(std::uint32_t first, std::size_t count, std::uint32_t otherFirst, std::size_t otherCount) const;
  void match(std::uint32_t a, std::uint32_t b, double dist2, SurfaceMesh& out);
  double outwardness(std::size_t k, const StripShape& strip, const std::vector<Triangle>& triangles) const;
  // Whether a strip that mostly faces up or down (not a wall) has a large share of its area
  // facing the other way as made: its passes are not side by side but cross and double back
  // over each other (pieces of one engraved curve, a wire figure), and the triangles between
  // them are no surface. Between the passes of a finishing program, every triangle faces the
  // same way as made.
  static bool folds(const StripShape& strip) {
    const double facing = strip.facingUp + strip.facingDown;
    return facing > kFacingShare * strip.areaSum && std::min(strip.facingUp, strip.facingDown) > kFoldedShare * facing;
  }
  // Whether triangle t = {a, next on one pass, b} (its cross-pass edges `across` and `other`
  // long, squared) joins passes within the gap limit: both edges within it, or, where the step
  // along the pass is itself longer than the limit but skips no more samples than the stride
  // (not a hole of samples left out of geometry), the other pass's vertex within it of that
  // step. The edges alone would leave a thinned mesh without triangles, its steps (4 mm on a
  // 100 M-sample raster's map in the window) being longer than the passes lie apart.
  bool passesMeet(const Triangle& t, double across, double other) const {
    if (across <= gap2_ && other <= gap2_) return true;
    const bool stepOnA = mesh_.vertexPass[t[0]] == mesh_.vertexPass[t[1]];
    const std::uint32_t from = stepOnA ? t[0] : t[2], to = t[1], facing = stepOnA ? t[2] : t[0];
    const std::uint32_t sampleFrom = mesh_.vertexSample[from], sampleTo = mesh_.vertexSample[to];
    const std::size_t skipped = sampleFrom > sampleTo ? sampleFrom - sampleTo : sampleTo - sampleFrom;
    if (d2(from, to) <= gap2_ || skipped > stride_) return false;
    return distanceToSegment(pos(facing), pos(from), pos(to)) <= gapLimit_;
  }

  const PositionSource& p_;
  const SurfaceMesh& mesh_;
  double gap2_, gapLimit_;
  std::size_t stride_;  // samples between neighbouring vertices of a pass
  PathPattern pattern_;
  std::vector<float>& bestNext_;
  std::vector<float>& bestPrevious_;
};

std::size_t StripBuilder::nearest(std::uint32_t first, std::size_t count, const Vec3& to, double* distance2) const {
  std::size_t best = 0;
  double bestD = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < count; ++i) {
    const double d = (pos(first + static_cast<std::uint32_t>(i)) - to).squaredNorm();
    if (d < bestD) bestD = d, best = i;
  }
  if (distance2 != nullptr) *distance2 = bestD;
  return best;
}

// A pass is a closed loop for this strip when its ends meet much closer than the other pass
// lies (a spiral's revolution ends one step-over from its start, a loop at its start).
bool StripBuilder::closedPass(std::uint32_t first, std::size_t count, std::uint32_t otherFirst,
                              std::size_t otherCount) const {
  if (pattern_ != PathPattern::ContourParallel || count < 3) return false;
  const double ends = (pos(first) - pos(first + static_cast<std::uint32_t>(count - 1))).norm();
  double across2;
  nearest(otherFirst, otherCount, pos(first), &across2);
  return ends <= gapLimit_ && ends < 0.5 * std::sqrt(across2);
}

void StripBuilder::match(std::uint32_t a, std::uint32_t b, double dist2, SurfaceMesh& out) {
  if (dist2 > gap2_) return;
  const float d = static_cast<float>(dist2);
  if (d < bestNext_[a]) bestNext_[a] = d, out.nextPassNeighbour[a] = b;
  if (d < bestPrevious_[b]) bestPrevious_[b] = d, out.previousPassNeighbour[b] = a;
}

void StripBuilder::forget(std::size_t kA, std::size_t kB, SurfaceMesh& out) {
  for (std::size_t v = mesh_.passFirstVertex[kA]; v < mesh_.passFirstVertex[kA + 1]; ++v)
    out.nextPassNeighbour[v] = kNoVertex, bestNext_[v] = std::numeric_limits<float>::infinity();
  for (std::size_t v = mesh_.passFirstVertex[kB]; v < mesh_.passFirstVertex[kB + 1]; ++v)
    out.previousPassNeighbour[v] = kNoVertex, bestPrevious_[v] = std::numeric_limits<float>::infinity();
}

StripShape StripBuilder::make(std::size_t kA, std::size_t kB, std::vector<Triangle>& triangles, SurfaceMesh& out) {
  StripShape shape;
  shape.begin = shape.end = triangles.size();
  const std::uint32_t firstA = static_cast<std::uint32_t>(mesh_.passFirstVertex[kA]);
  const std::uint32_t firstB = static_cast<std::uint32_t>(mesh_.passFirstVertex[kB]);
  std::size_t countA = mesh_.passFirstVertex[kA + 1] - firstA;
  std::size_t countB = mesh_.passFirstVertex[kB + 1] - firstB;
  if (countA < 2 || countB < 2) return shape;

  PassWalk a{firstA, countA}, b{firstB, countB};
  if (closedPass(firstA, countA, firstB, countB) && closedPass(firstB, countB, firstA, countA)) {
    // A loop's last vertex on its first point adds no edge to the cycle.
    const auto cycleCount = [&](std::uint32_t first, std::size_t count) {
      return d2(first, first + static_cast<std::uint32_t>(count - 1)) <= kSamePoint * kSamePoint ? count - 1 : count;
    };
    a.count = cycleCount(firstA, countA);
    b.count = cycleCount(firstB, countB);
    a.closed = b.closed = true;
    // Start at A's first vertex and the nearest of B; B runs the same way round as A when A's
    // vertex a quarter along is nearest a vertex shortly after that one.
    const std::size_t start = nearest(firstB, b.count, pos(firstA));
    const std::size_t quarter = nearest(firstB, b.count, pos(firstA + static_cast<std::uint32_t>(a.count / 4)));
    const std::size_t ahead = (quarter + b.count - start) % b.count;
    b.reversed = ahead > b.count / 2;
    b.offset = b.reversed ? (b.count - start) % b.count : start;
  } else {
    const Vec3 a0 = pos(firstA), a1 = pos(firstA + static_cast<std::uint32_t>(countA - 1));
    const Vec3 b0 = pos(firstB), b1 = pos(firstB + static_cast<std::uint32_t>(countB - 1));
    b.reversed = (a0 - b1).norm() + (a1 - b0).norm() < (a0 - b0).norm() + (a1 - b1).norm();
  }

  const std::size_t stepsA = a.steps(), stepsB = b.steps();
  std::size_t i = 0, j = 0;
  std::uint32_t va = a.vertex(0), vb = b.vertex(0);
  double across = d2(va, vb);  // squared length of the current cross-pass edge
  match(va, vb, across, out);
  Vec3 normal = Vec3::Zero();
  double areaSum = 0;
  while (i < stepsA || j < stepsB) {
    const std::uint32_t nextA = i < stepsA ? a.vertex(i + 1) : va;
    const std::uint32_t nextB = j < stepsB ? b.vertex(j + 1) : vb;
    const double viaA = i < stepsA ? d2(nextA, vb) : std::numeric_limits<double>::infinity();
    const double viaB = j < stepsB ? d2(va, nextB) : std::numeric_limits<double>::infinity();
    Triangle t;
    double other;
    // The pass with steps left is taken when the other has none: comparing the distances alone
    // would not end when both are infinite (coordinates near the double's limit) or NaN.
    if (j >= stepsB || (i < stepsA && viaA <= viaB)) {
      t = {va, nextA, vb};
      other = viaA;
      va = nextA;
      ++i;
    } else {
      t = {va, nextB, vb};
      other = viaB;
      vb = nextB;
      ++j;
    }
    match(va, vb, other, out);
    if (passesMeet(t, across, other)) {
      const Vec3 p0 = pos(t[0]), p1 = pos(t[1]), p2 = pos(t[2]);
      const Vec3 n = (p1 - p0).cross(p2 - p0);
      const double area2 = n.squaredNorm();
      const double scale = std::max({(p1 - p0).squaredNorm(), (p2 - p0).squaredNorm(), (p2 - p1).squaredNorm()});
      if (area2 > 1e-24 * scale * scale && area2 > 0) {
        triangles.push_back(t);
        normal += n;
        (n.z() > 0 ? shape.facingUp : shape.facingDown) += std::fabs(n.z());
        areaSum += std::sqrt(area2);
      }
    }
    across = other;
  }
  shape.end = triangles.size();
  shape.normal = normal;
  shape.areaSum = areaSum;
  shape.reversedB = b.reversed;
  if (folds(shape)) {
    // Not a surface between these passes: its triangles and its matches are let go.
    triangles.resize(shape.begin);
    shape = StripShape{shape.begin, shape.begin};
    shape.folded = true;
    forget(kA, kB, out);
  }
  return shape;
}

// How much strip k's triangles, as made, face away from the centroid of its pass A's vertices
// (> 0 outward).
double StripBuilder::outwardness(std::size_t k, const StripShape& strip, const std::vector<Triangle>& triangles) const {
  const std::uint32_t firstA = static_cast<std::uint32_t>(mesh_.passFirstVertex[k]);
  const std::size_t countA = mesh_.passFirstVertex[k + 1] - firstA;
  Vec3 centre = Vec3::Zero();
  for (std::size_t q = 0; q < countA; ++q) centre += pos(firstA + static_cast<std::uint32_t>(q));
  centre /= double(countA);
  double outward = 0;
  for (std::size_t q = strip.begin; q < strip.end; ++q) {
    const Triangle& tri = triangles[q];
    const Vec3 p0 = pos(tri[0]), p1 = pos(tri[1]), p2 = pos(tri[2]);
    const Vec3 c = (p0 + p1 + p2) / 3.0 - centre;
    outward += (p1 - p0).cross(p2 - p0).dot(Vec3(c.x(), c.y(), 0));
  }
  return outward;
}

int StripBuilder::orient(std::size_t k, const StripShape& strip, int previousDirection,
                         std::vector<Triangle>& triangles) const {
  if (strip.end == strip.begin) return 0;
  // Orientation: as made, A's edges run forward and B's against the walk. Face +Z; a strip
  // that is mostly a wall follows the strip before it through their shared pass, or faces away
  // from the loop it goes round.
  bool flip;
  if (!strip.wall()) flip = strip.normal.z() < 0;
  else if (previousDirection == 0) flip = outwardness(k, strip, triangles) < 0;
  else flip = previousDirection == +1;  // A's edges must run against the way the strip before ran them
  if (flip)
    for (std::size_t q = strip.begin; q < strip.end; ++q) std::swap(triangles[q][1], triangles[q][2]);
  // B's own edges: against the walk as made; the walk runs B forward unless reversed.
  int directionB = strip.reversedB ? +1 : -1;
  if (flip) directionB = -directionB;
  return directionB;
}

// Passes that cross and double back over their neighbour (a pass cut again across the others,
// the link after it) must not cost the strip between the passes either side of them: where
// strip k folds and a pass up to kMostLeftOut passes later lies beside pass k, the two are joined
// and the passes between are left out. Strips keep their place in `shapes` (strip k then joins k
// and that pass, the strips between are empty), and the triangles are put back in strip order.
void joinAcrossCrossingPasses(StripBuilder& strips, std::vector<StripShape>& shapes, SurfaceMesh& mesh) {
  constexpr std::size_t kMostLeftOut = 3;
  const std::size_t count = shapes.size();
  std::vector<Triangle> bridges;
  std::vector<bool> bridged(count, false);
  for (std::size_t k = 0; k < count; ++k) {
    if (!shapes[k].folded) continue;
    bool joined = false;
    for (std::size_t m = k + 2; m <= std::min(k + 1 + kMostLeftOut, count) && !joined; ++m) {
      for (std::size_t j = k + 1; j < m; ++j) strips.forget(j, j + 1, mesh);
      const StripShape bridge = strips.make(k, m, bridges, mesh);
      joined = !bridge.folded && bridge.end > bridge.begin;
      if (joined) {
        shapes[k] = bridge;
        bridged[k] = true;
        for (std::size_t j = k + 1; j < m; ++j) {
          shapes[j] = StripShape{};
          shapes[j].leftOut = true;
          mesh.passesLeftOut.push_back(j);
        }
        k = m - 1;
        break;
      }
      // The strips between stay as made; making them again (into a list let go) gives back
      // their matches.
      strips.forget(k, m, mesh);
      bridges.resize(bridge.begin);
      std::vector<Triangle> again;
      for (std::size_t j = k + 1; j < m; ++j) strips.make(j, again, mesh);
    }
    if (!joined) mesh.foldedPairs.push_back(k);
  }
  if (mesh.passesLeftOut.empty()) return;
  std::vector<Triangle> ordered;
  ordered.reserve(mesh.triangles.size() + bridges.size());
  for (std::size_t k = 0; k < count; ++k) {
    const std::vector<Triangle>& from = bridged[k] ? bridges : mesh.triangles;
    const std::size_t begin = ordered.size();
    ordered.insert(ordered.end(), from.begin() + shapes[k].begin, from.begin() + shapes[k].end);
    shapes[k].begin = begin;
    shapes[k].end = ordered.size();
  }
  mesh.triangles = std::move(ordered);
}

}  // namespace

namespace {

// Why passes made no triangle at `gapLimit` mm, and what the user can do about it.
std::string passesTooFarApart(double gapLimit) {
  return fmt::format("the passes are too far apart to make a surface (gap limit {:g} mm: raise it to join passes "
                     "further apart, --gap-limit or the window's Colour panel)",
                     gapLimit);
}

}  // namespace

std::string whyNoTriangles(const PassSet& passes, double gapLimit, std::size_t foldedStrips) {
  if (passes.passes.empty()) return kNoCuttingPasses;
  if (passes.passes.size() < 2) return "a single cutting pass makes no surface (a surface lies between passes)";
  // Every neighbouring pair folds: no gap would join them into a surface.
  if (foldedStrips + 1 >= passes.passes.size()) return foldedPasses(foldedStrips) + ": the path makes no surface";
  return (foldedStrips > 0 ? foldedPasses(foldedStrips) + "; " : std::string()) + passesTooFarApart(gapLimit);
}

std::string foldedPasses(std::size_t foldedStrips) {
  return fmt::format("{} pair{} of neighbouring passes {}, as pieces of one engraved curve do, instead of lying side "
                     "by side over a surface: not joined",
                     foldedStrips, foldedStrips == 1 ? "" : "s", kFoldedPassesNote);
}

namespace {

// "lines 120-180" (or "line 120", or "samples 500-800" where the samples name no line).
std::string passLines(const Trajectory& samples, const Pass& pass) {
  const std::uint32_t first = samples.line[pass.begin], last = samples.line[pass.end - 1];
  if (first == 0 || last == 0) return fmt::format("samples {}-{}", pass.begin, pass.end - 1);
  const std::uint32_t low = std::min(first, last), high = std::max(first, last);
  return low == high ? fmt::format("line {}", low) : fmt::format("lines {}-{}", low, high);
}

// The first few of `items`, then how many more.
std::string firstFew(const std::vector<std::string>& items) {
  constexpr std::size_t kNamed = 4;
  std::string out;
  for (std::size_t i = 0; i < items.size() && i < kNamed; ++i) out += (i > 0 ? "; " : "") + items[i];
  if (items.size() > kNamed) out += fmt::format("; and {} more", items.size() - kNamed);
  return out;
}

}  // namespace

std::string passesNotJoined(const Trajectory& samples, const PassSet& passes, const SurfaceMesh& mesh) {
  std::string note;
  if (!mesh.passesLeftOut.empty()) {
    std::vector<std::string> where;
    for (std::size_t k : mesh.passesLeftOut) where.push_back(passLines(samples, passes.passes[k]));
    note = fmt::format("{} pass{} {} with the pass before, left out so that the passes either side are joined ({})",
                       where.size(), where.size() == 1 ? "" : "es", kFoldedPassesNote, firstFew(where));
  }
  if (!mesh.foldedPairs.empty()) {
    std::vector<std::string> where;
    for (std::size_t k : mesh.foldedPairs)
      where.push_back(passLines(samples, passes.passes[k]) + " with " + passLines(samples, passes.passes[k + 1]));
    if (!note.empty()) note += "; ";
    note += foldedPasses(mesh.foldedPairs.size()) + " (" + firstFew(where) + ")";
  }
  return note;
}

SurfaceMesh buildSurfaceMesh(const Trajectory& samples, const PassSet& passes, const MeshOptions& options) {
  const PositionSource p = positionSource(samples, options.feedback);
  SurfaceMesh mesh;
  pickVertices(p, passes, std::max<std::size_t>(1, options.stride), mesh);
  const std::size_t vertices = mesh.vertexSample.size();
  mesh.previousPassNeighbour.assign(vertices, kNoVertex);
  mesh.nextPassNeighbour.assign(vertices, kNoVertex);
  mesh.triangles.reserve(2 * vertices);
  std::vector<float> bestNext(vertices, std::numeric_limits<float>::infinity());
  std::vector<float> bestPrevious(vertices, std::numeric_limits<float>::infinity());
  StripBuilder strips(p, mesh, options.gapLimit, std::max<std::size_t>(1, options.stride), passes.pattern, bestNext,
                      bestPrevious);
  const std::size_t count = passes.passes.size() > 1 ? passes.passes.size() - 1 : 0;
  std::vector<StripShape> shapes(count);
  const auto makeStrips = [&](std::size_t from, std::size_t to, std::vector<Triangle>& triangles) {
    for (std::size_t k = from; k < to; ++k) shapes[k] = strips.make(k, triangles, mesh);
  };
  // The strips after the one at half the vertices are made on a second thread, into a list of
  // their own appended after: the same triangles in the same order as made one by one.
  std::size_t middle = count;
  if (vertices >= options.sideBySideVertices) {
    middle = 0;
    while (middle < count && 2 * mesh.passFirstVertex[middle + 1] < vertices) ++middle;
  }
  std::vector<Triangle> later;
  {
    std::future<void> second;
    if (middle < count) {
      try {
        second = std::async(std::launch::async, [&] {
          later.reserve(2 * (vertices - mesh.passFirstVertex[middle]));  // as the whole list: never grown
          makeStrips(middle, count, later);
        });
      } catch (const std::system_error&) {  // no thread to be had: all of them on this one
        middle = count;
      }
    }
    makeStrips(0, middle, mesh.triangles);
    if (second.valid()) second.get();
  }
  const std::size_t offset = mesh.triangles.size();
  mesh.triangles.insert(mesh.triangles.end(), later.begin(), later.end());
  for (std::size_t k = middle; k < count; ++k) shapes[k].begin += offset, shapes[k].end += offset;
  joinAcrossCrossingPasses(strips, shapes, mesh);
  int direction = 0;
  for (std::size_t k = 0; k < count; ++k)
    if (!shapes[k].leftOut) direction = strips.orient(k, shapes[k], direction, mesh.triangles);
  return mesh;
}

double SurfaceMesh::joinedShare() const {
  if (vertexSample.empty()) return 0;
  std::vector<bool> joined(vertexSample.size(), false);
  for (const auto& t : triangles)
    for (std::uint32_t v : t) joined[v] = true;
  return double(std::count(joined.begin(), joined.end(), true)) / double(vertexSample.size());
}

std::vector<Vec3> meshPositions(const Trajectory& samples, const SurfaceMesh& mesh, bool feedback) {
  const PositionSource p = positionSource(samples, feedback);
  std::vector<Vec3> out(mesh.vertexSample.size());
  for (std::size_t v = 0; v < out.size(); ++v) out[v] = p.at(mesh.vertexSample[v]);
  return out;
}

std::vector<Vec3> vertexNormals(const std::vector<Vec3>& positions, const SurfaceMesh& mesh) {
  std::vector<Vec3> normals(positions.size(), Vec3::Zero());
  for (const auto& t : mesh.triangles) {
    // The cross product's length is twice the area: summing it weights by area.
    const Vec3 n = (positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]);
    if (!std::isfinite(n.squaredNorm())) continue;
    normals[t[0]] += n;
    normals[t[1]] += n;
    normals[t[2]] += n;
  }
  for (Vec3& n : normals) {
    const double l = n.norm();
    n = l > 0 ? Vec3(n / l) : Vec3(Vec3::Zero());
  }
  return normals;
}

std::size_t strideWithin(const PassSet& passes, std::size_t maxVertices) {
  std::size_t cutting = 0;
  for (const Pass& pass : passes.passes) cutting += pass.size();
  const std::size_t budget = std::max<std::size_t>(maxVertices, 1);
  return std::max<std::size_t>(1, (cutting + budget - 1) / budget);
}

double medianPassSpacing(const std::vector<Vec3>& positions, const SurfaceMesh& mesh) {
  const std::size_t n = std::min(positions.size(), mesh.nextPassNeighbour.size());
  const std::size_t step = std::max<std::size_t>(1, n / 4096);
  std::vector<double> spacing;
  for (std::size_t v = 0; v < n; v += step) {
    const std::uint32_t next = mesh.nextPassNeighbour[v];
    if (next == kNoVertex || next >= positions.size()) continue;
    // Across the pass only: on a thinned mesh the nearest vertex of the next pass may lie up
    // to half a vertex spacing along it.
    const std::size_t along = v + 1 < n && mesh.vertexPass[v + 1] == mesh.vertexPass[v] ? v + 1 : v - (v > 0);
    if (along == v || mesh.vertexPass[along] != mesh.vertexPass[v]) continue;
    const Vec3 direction = (positions[along] - positions[v]).normalized();
    Vec3 across = positions[next] - positions[v];
    across -= across.dot(direction) * direction;
    const double d = across.norm();
    if (std::isfinite(d) && d > 0) spacing.push_back(d);
  }
  if (spacing.empty()) return 0;
  auto middle = spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2);
  std::nth_element(spacing.begin(), middle, spacing.end());
  return *middle;
}

}  // namespace isurface
