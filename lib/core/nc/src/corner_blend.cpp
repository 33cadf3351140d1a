#include "corner_blend.h"

#include <algorithm>
#include <cmath>

namespace isurface {

namespace {

// rad: below this the directions are one (nothing to blend). Above the largest, a blend run at
// its radius's centripetal limit takes longer than braking into the corner along the path (the
// time a blend costs, against a stop, falls with its radius only for turns below about
// 2 normal share / tangential share of acceleration, 0.8 rad with the generic control's shares);
// blending there would make a tighter tolerance faster. Such corners keep the control's corner
// limit.
constexpr double kSmallestTurn = 1e-7;
constexpr double kLargestTurn = 0.6;

double turnBetween(const Vec3& in, const Vec3& out) { return std::acos(std::clamp(in.dot(out), -1.0, 1.0)); }

}  // namespace

double CornerBlend::reachFor(const Vec3& in, const Vec3& out, double deviation, double longest) {
  const double turn = turnBetween(in, out);
  if (!(turn > kSmallestTurn && turn <= kLargestTurn) || !(deviation > 0) || !(longest > 0)) return 0;
  // An arc of radius R tangent to both lines at `reach` t from the corner misses it by
  // R (1 / cos(h) - 1) with t = R tan(h), h half the turn: t = deviation / tan(h / 2).
  return std::min(deviation / std::tan(0.25 * turn), longest);
}

double CornerBlend::radiusFor(const Vec3& in, const Vec3& out, double reach) {
  return reach / std::tan(0.5 * turnBetween(in, out));
}

std::optional<CornerBlend> CornerBlend::at(const Vec3& corner, const Vec3& in, const Vec3& out, double reach) {
  const double turn = turnBetween(in, out);
  if (!(turn > kSmallestTurn && turn <= kLargestTurn) || !(reach > 0)) return std::nullopt;
  const Vec3 across = out - out.dot(in) * in;
  if (!(across.norm() > 0)) return std::nullopt;
  CornerBlend b;
  b.in_ = in;
  b.inward_ = across.normalized();
  b.radius_ = radiusFor(in, out, reach);
  b.sweep_ = turn;
  b.start_ = corner - reach * in;
  b.centre_ = b.start_ + b.radius_ * b.inward_;
  return b;
}

Vec3 CornerBlend::at(double s) const {
  const double angle = std::clamp(s, 0.0, length()) / radius_;
  return centre_ + radius_ * (std::sin(angle) * in_ - std::cos(angle) * inward_);
}

Vec3 CornerBlend::tangentAt(double s) const {
  const double angle = std::clamp(s, 0.0, length()) / radius_;
  return std::cos(angle) * in_ + std::sin(angle) * inward_;
}

PathSegment shortenedLine(const PathSegment& move, double trimStart, double trimEnd) {
  PathSegment line = move;
  if (!line.arc && line.length > 0 && trimStart + trimEnd > 0) {
    const double kept = std::max(0.0, line.length - trimStart - trimEnd);
    line.start = move.start + trimStart * move.direction;
    line.end = line.start + kept * move.direction;
    line.length = kept;
  }
  return line;
}

}  // namespace isurface
