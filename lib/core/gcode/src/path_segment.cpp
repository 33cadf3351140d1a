#include "isurface/gcode/path_segment.h"

#include <algorithm>
#include <cmath>

#include "isurface/base/tolerances.h"

namespace isurface {

PathSegment PathSegment::from(const Program& program, std::size_t moveIndex) {
  return from(program.startOf(moveIndex), program.moves[moveIndex]);
}

PathSegment PathSegment::from(const Vec3& start, const Move& move) {
  PathSegment seg;
  seg.start = start;
  seg.end = move.end;
  if (move.isArc()) {
    seg.arc = true;
    seg.arcGeometry = ArcGeometry::from(seg.start, move);
    seg.length = seg.arcGeometry.length();
  } else if (move.isMotion()) {
    const Vec3 delta = seg.end - seg.start;
    seg.length = delta.norm();
    if (seg.length > 0) seg.direction = delta / seg.length;
  }
  if (!(seg.length > kLengthEpsilon)) seg.length = 0;
  return seg;
}

Vec3 PathSegment::at(double s) const {
  if (length <= 0) return end;
  if (s <= 0) return start;
  if (s >= length) return end;
  if (arc) return arcGeometry.at(s / length);
  return start + direction * s;
}

PathPoint PathSegment::nearest(const Vec3& p) const {
  const PathSegment& seg = *this;
  PathPoint n;
  if (seg.length <= 0) {
    n.distance = (p - seg.end).norm();
    return n;
  }
  if (!seg.arc) {
    const double s = std::clamp((p - seg.start).dot(seg.direction), 0.0, seg.length);
    n.distance = (p - (seg.start + seg.direction * s)).norm();
    n.tangent = seg.direction;
    n.along = s;
    return n;
  }
  // Arcs (possibly helical or spiral): sample every ~10 degrees, then refine between the
  // neighbours of the nearest sample by golden-section search, where distance is unimodal.
  const ArcGeometry& a = seg.arcGeometry;
  const int steps = std::clamp(int(std::ceil(std::abs(a.sweep) / 0.17)), 4, 4096);
  auto dist = [&](double f) { return (p - a.at(f)).norm(); };
  int best = 0;
  double bestD = dist(0);
  for (int k = 1; k <= steps; ++k) {
    const double d = dist(double(k) / steps);
    if (d < bestD) bestD = d, best = k;
  }
  double lo = double(std::max(best - 1, 0)) / steps, hi = double(std::min(best + 1, steps)) / steps;
  constexpr double kGolden = 0.6180339887498949;
  double f1 = hi - kGolden * (hi - lo), f2 = lo + kGolden * (hi - lo);
  double d1 = dist(f1), d2 = dist(f2);
  for (int it = 0; it < 40 && (hi - lo) * seg.length > kSearchResolution; ++it) {
    if (d1 < d2) {
      hi = f2, f2 = f1, d2 = d1;
      f1 = hi - kGolden * (hi - lo), d1 = dist(f1);
    } else {
      lo = f1, f1 = f2, d1 = d2;
      f2 = lo + kGolden * (hi - lo), d2 = dist(f2);
    }
  }
  const double f = d1 < d2 ? f1 : f2;
  n.distance = std::min(bestD, std::min(d1, d2));
  n.tangent = a.tangentAt(f);
  n.along = f * seg.length;
  return n;
}

}  // namespace isurface
