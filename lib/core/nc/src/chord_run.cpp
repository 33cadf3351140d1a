#include "chord_run.h"

#include <Eigen/Dense>

namespace isurface {

std::array<float, 18> packCurve(const CurveEnd& start, const CurveEnd& end) {
  std::array<float, 18> packed{};
  const Vec3* parts[6] = {&start.offset, &start.knot.tangent, &start.knot.curvature,
                          &end.offset,   &end.knot.tangent,   &end.knot.curvature};
  for (int p = 0; p < 6; ++p)
    for (int a = 0; a < 3; ++a) packed[3 * p + a] = static_cast<float>((*parts[p])[a]);
  return packed;
}

CurveEnd unpackCurveEnd(const std::array<float, 18>& packed, bool atEnd) {
  const int base = atEnd ? 9 : 0;
  CurveEnd e;
  for (int a = 0; a < 3; ++a) {
    e.offset[a] = packed[base + a];
    e.knot.tangent[a] = packed[base + 3 + a];
    e.knot.curvature[a] = packed[base + 6 + a];
  }
  return e;
}

ChordSpline curveOf(const PathSegment& seg, const std::array<float, 18>& packed) {
  const CurveEnd start = unpackCurveEnd(packed, false), end = unpackCurveEnd(packed, true);
  return ChordSpline(seg.start + start.offset, start.knot, seg.end + end.offset, end.knot);
}

void ChordRun::push(std::uint32_t index, const Move& move, const PathSegment& seg) {
  if (points_.empty()) {
    points_.push_back(Point{seg.start, 0.0});
    dropped_ = 0;
    firstChord_ = 0;
    ended_ = false;
  }
  points_.push_back(Point{seg.end, points_.back().along + seg.length});
  FittedChord c;
  c.index = index;
  c.move = move;
  c.seg = seg;
  chords_.push_back(c);
}

void ChordRun::end() { ended_ = true; }

// Point i (of the run) can be fitted once the points within kFitReach after it are known.
bool ChordRun::settled(std::size_t i) const {
  if (ended_) return true;
  const std::size_t last = dropped_ + points_.size() - 1;
  return last - i >= kMostFitPoints || points_.back().along - pointAt(i).along >= kFitReach;
}

CurveEnd ChordRun::fitAt(std::size_t i) const {
  const std::size_t first = dropped_, last = dropped_ + points_.size() - 1;
  CurveEnd e;
  if (i == 0 || i == last) {
    // A corner of the run: kept exactly, in the direction of its chord.
    const Vec3 from = i == 0 ? pointAt(0).position : pointAt(i - 1).position;
    const Vec3 to = i == 0 ? pointAt(1).position : pointAt(i).position;
    e.knot = ChordKnot::straight(from, to);
    return e;
  }
  const Point& centre = pointAt(i);
  std::size_t lo = i - 1, hi = i + 1;
  while (lo > first && i - lo < kMostFitPoints && centre.along - pointAt(lo - 1).along <= kFitReach) --lo;
  while (hi < last && hi - i < kMostFitPoints && pointAt(hi + 1).along - centre.along <= kFitReach) ++hi;
  // Least squares of p(t) = c0 + c1 t + c2 t^2, t the chord length from the point.
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d right = Eigen::Matrix3d::Zero();
  for (std::size_t j = lo; j <= hi; ++j) {
    const double t = pointAt(j).along - centre.along;
    const Eigen::Vector3d powers(1.0, t, t * t);
    normal += powers * powers.transpose();
    right += powers * pointAt(j).position.transpose();
  }
  const Eigen::Matrix3d c = normal.ldlt().solve(right);
  const Vec3 position = c.row(0).transpose(), velocity = c.row(1).transpose();
  const Vec3 acceleration = 2.0 * c.row(2).transpose();
  const double speed = velocity.norm();
  if (!(speed > 0) || !position.allFinite() || !acceleration.allFinite()) {
    e.knot = ChordKnot::through(pointAt(i - 1).position, centre.position, pointAt(i + 1).position);
    return e;
  }
  e.offset = position - centre.position;
  if (!(e.offset.norm() <= largestOffset_)) e.offset = Vec3::Zero();
  e.knot.tangent = velocity / speed;
  e.knot.curvature = (acceleration - acceleration.dot(e.knot.tangent) * e.knot.tangent) / (speed * speed);
  return e;
}

void ChordRun::take(std::vector<FittedChord>& out) {
  while (!chords_.empty()) {
    const std::size_t k = firstChord_;  // run index of chords_.front(): from point k to k + 1
    if (!settled(k + 1)) return;
    FittedChord c = chords_.front();
    const bool single = ended_ && k == 0 && chords_.size() == 1;
    if (!single) {
      c.start = k == 0 ? fitAt(0) : nextStart_;
      c.end = fitAt(k + 1);
      nextStart_ = *c.end;
    }
    out.push_back(c);
    chords_.pop_front();
    ++firstChord_;
    // Points more than the fit's reach behind the next chord's start are no longer needed.
    while (points_.size() > 1 && dropped_ + kMostFitPoints < firstChord_ &&
           pointAt(firstChord_).along - points_.front().along > kFitReach) {
      points_.pop_front();
      ++dropped_;
    }
  }
  if (ended_) {
    points_.clear();
    ended_ = false;
  }
}

}  // namespace isurface
