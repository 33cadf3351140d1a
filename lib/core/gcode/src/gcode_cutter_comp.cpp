// Cutter radius compensation: offset lines and arcs, corners joined as LinuxCNC joins them.
#include "gcode_cutter_comp.h"

#include <fmt/format.h>

#include <cmath>

#include "isurface/base/units.h"

namespace isurface::gcode {

namespace {

// A turn this small (radians) is no corner: the next move starts where the tool is. LinuxCNC's
// TOLERANCE_CONCAVE_CORNER.
constexpr double kStraightOn = 0.05;
// Intersections a little outside a circle are still on it (mm, squared where compared so).
constexpr double kMeetTolerance = 1e-9;

Vec2 rotatedLeft(const Vec2& v) { return {-v.y(), v.x()}; }
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Angle from `from` to `to` about `centre` in the arc's direction, 0 .. 2 pi.
double sweepBetween(const Vec2& centre, const Vec2& from, const Vec2& to, bool ccw) {
  const double a = std::atan2(from.y() - centre.y(), from.x() - centre.x());
  const double b = std::atan2(to.y() - centre.y(), to.x() - centre.x());
  double s = ccw ? b - a : a - b;
  while (s < 0) s += kTwoPi;
  while (s >= kTwoPi) s -= kTwoPi;
  return s;
}

Vec2 arcTangent(const Vec2& centre, const Vec2& at, bool ccw) {
  const Vec2 radial = (at - centre).normalized();
  return ccw ? rotatedLeft(radial) : Vec2(-rotatedLeft(radial));
}

// Points where the line through `a` along unit `d` meets the circle (centre, radius).
int lineMeetsCircle(const Vec2& a, const Vec2& d, const Vec2& centre, double radius, Vec2 out[2]) {
  const Vec2 f = a - centre;
  const double b = f.dot(d);
  const double disc = b * b - (f.squaredNorm() - radius * radius);
  if (disc < -kMeetTolerance) return 0;
  const double root = std::sqrt(std::max(disc, 0.0));
  out[0] = a + (-b - root) * d;
  out[1] = a + (-b + root) * d;
  return 2;
}

int circlesMeet(const Vec2& c1, double r1, const Vec2& c2, double r2, Vec2 out[2]) {
  const Vec2 between = c2 - c1;
  const double d = between.norm();
  if (d < kLengthEpsilon) return 0;  // concentric: no corner to meet at
  const double along = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
  const double h2 = r1 * r1 - along * along;
  if (h2 < -kMeetTolerance) return 0;
  const Vec2 unit = between / d;
  const Vec2 foot = c1 + along * unit;
  const double h = std::sqrt(std::max(h2, 0.0));
  out[0] = foot + h * rotatedLeft(unit);
  out[1] = foot - h * rotatedLeft(unit);
  return 2;
}

std::string point(const Vec2& p) { return fmt::format("({:.4f}, {:.4f}) mm", p.x(), p.y()); }

}  // namespace

void CutterCompensation::start(Side side, double radiusMm, Plane plane, const Vec3& tool, bool inch) {
  on_ = true;
  inch_ = inch;
  entered_ = false;
  side_ = side;
  radius_ = radiusMm;
  axes_ = planeAxes(plane);
  tool_ = tool;
}

std::string CutterCompensation::stop(Vec3& tool) {
  on_ = false;
  tool = tool_;
  if (entered_ && open_.arc && !arcEndsWithin(planar(tool_)))
    return fmt::format("Arc move in concave corner cannot be reached by the tool (radius {:.4f} mm) without gouging: "
                       "the last arc would sweep further than programmed", radius_);
  return {};
}

bool CutterCompensation::arcEndsWithin(const Vec2& end) const {
  // LinuxCNC's tolerance on an offset arc that sweeps further than its programmed one: 0.001 in
  // inch programs, 0.0254 in mm ones (compared as radians, as LinuxCNC compares them).
  const double longer = inch_ ? 0.001 : 0.0254;
  return open_.programmedSweep >= kTwoPi ||
         sweepBetween(open_.centre, open_.start, end, open_.ccw) <= open_.programmedSweep + longer;
}

Vec3 CutterCompensation::spatial(const Vec2& p, double w) const {
  Vec3 out;
  out[axes_.u] = p.x();
  out[axes_.v] = p.y();
  out[axes_.w] = w;
  return out;
}

Vec2 CutterCompensation::normal(const Vec2& tangent) const {
  return side_ == kLeft ? rotatedLeft(tangent) : Vec2(-rotatedLeft(tangent));
}

std::string CutterCompensation::line(const Vec3& from, const Vec3& to, bool rapid, CompensationStep& step) {
  const MoveKind kind = rapid ? MoveKind::Rapid : MoveKind::Linear;
  const double w = to[axes_.w];
  const Vec2 tool = planar(tool_), p0 = planar(from), p1 = planar(to);
  if (!entered_) {
    // The entry move: straight to the offset of its own end point.
    const double distance = (p1 - tool).norm();
    if (distance <= radius_)
      return fmt::format("Length of cutter compensation entry move ({:.4f} mm) is not greater than the tool radius ({:.4f} mm)",
                         distance, radius_);
    const Vec2 direction = (p1 - tool) / distance;
    const Vec2 end = p1 + radius_ * normal(direction);
    step.add({kind, spatial(end, w)});
    // An inside corner moves its end back along the programmed direction (as LinuxCNC does),
    // not along the entry move itself.
    open_ = OpenMove{};
    open_.start = tool;
    open_.through = end;
    open_.direction = open_.endTangent = direction;
    entered_ = true;
    tool_ = spatial(end, w);
    return {};
  }
  if (p0 == p1) {  // along the plane's normal only: the tool stays beside the same point
    step.extendsOpenMove = true;
    step.add({kind, spatial(tool, w)});
    tool_ = spatial(tool, w);
    return {};
  }
  NextMove next;
  next.corner = p0;
  next.startTangent = (p1 - p0).normalized();
  next.start = p0 + radius_ * normal(next.startTangent);
  next.end = p1 + radius_ * normal(next.startTangent);
  Vec2 startsAt;
  if (std::string e = turnCorner(next, rapid, step, startsAt); !e.empty()) return e;
  if (cornerTrims_ && (next.end - startsAt).dot(next.startTangent) <= 0)
    return fmt::format("Cutter gouging: the move to {} is too short for the tool (radius {:.4f} mm) after the inside "
                       "corner at {}", point(p1), radius_, point(p0));
  step.add({kind, spatial(next.end, w)});
  open_ = OpenMove{};
  open_.start = startsAt;
  open_.through = next.end;
  open_.direction = open_.endTangent = next.startTangent;
  tool_ = spatial(next.end, w);
  return {};
}

std::string CutterCompensation::arc(const Vec3& from, const Vec3& to, const Vec3& centre, bool ccw, unsigned turns,
                                    CompensationStep& step) {
  if (!entered_)
    return "Cutter compensation entry move must be a straight move (G0 or G1), not an arc";
  const Vec2 p0 = planar(from), p1 = planar(to), o = planar(centre);
  const double r0 = (p0 - o).norm(), r1 = (p1 - o).norm();
  // The tool runs inside the arc when it is on the side the arc turns to.
  const double grow = (side_ == kLeft) == ccw ? -radius_ : radius_;
  if (std::min(r0, r1) + grow <= kLengthEpsilon)
    return fmt::format("Tool radius ({:.4f} mm) not less than arc radius ({:.4f} mm) with cutter compensation",
                       radius_, std::min(r0, r1));
  NextMove next;
  next.arc = true;
  next.corner = p0;
  next.centre = o;
  next.ccw = ccw;
  next.radius = r1 + grow;
  next.toolOutside = grow > 0;
  next.startTangent = arcTangent(o, p0, ccw);
  next.start = o + (p0 - o) * ((r0 + grow) / r0);
  next.end = o + (p1 - o) * ((r1 + grow) / r1);
  next.sweep = p0 == p1 ? kTwoPi : sweepBetween(o, p0, p1, ccw);
  // LinuxCNC places the corner before an arc at the arc's end radius (a centre-format arc's
  // start radius may differ a little): the line before it meets it there.
  next.lineShift = (o + (p0 - o) * (r1 / r0)) - p0;
  Vec2 startsAt;
  if (std::string e = turnCorner(next, false, step, startsAt); !e.empty()) return e;
  if (cornerTrims_ && next.sweep < kTwoPi && sweepBetween(o, startsAt, next.end, ccw) > next.sweep + kStraightOn)
    return fmt::format("Cutter gouging: the arc to {} is too short for the tool (radius {:.4f} mm) after the inside "
                       "corner at {}", point(p1), radius_, point(p0));
  const double w = to[axes_.w];
  step.add({ccw ? MoveKind::ArcCCW : MoveKind::ArcCW, spatial(next.end, w), spatial(o, tool_[axes_.w]), turns});
  open_ = OpenMove{};
  open_.arc = true;
  open_.start = startsAt;
  open_.centre = o;
  open_.radius = next.radius;
  open_.toolOutside = next.toolOutside;
  open_.ccw = ccw;
  open_.sweep = p0 == p1 ? kTwoPi : sweepBetween(o, startsAt, next.end, ccw);
  open_.programmedSweep = next.sweep;
  open_.endTangent = arcTangent(o, p1, ccw);
  tool_ = spatial(next.end, w);
  return {};
}

std::string CutterCompensation::turnCorner(const NextMove& next, bool rapid, CompensationStep& step,
                                           Vec2& startsAt) {
  const Vec2 tool = planar(tool_);
  cornerTrims_ = false;
  const Vec2& before = open_.endTangent;
  const double turn = std::atan2(cross(before, next.startTangent), before.dot(next.startTangent));  // left: > 0
  if (std::fabs(turn) <= kStraightOn) {
    startsAt = tool;
    return {};
  }
  // Turning back (an "h" or an "m" shape) the tool may stay on either side: LinuxCNC goes around
  // the corner, except over the outside of an arc, where it stays above and meets it.
  const bool reverses = std::fabs(turn) >= kPi - kStraightOn;
  const bool overArc = next.arc ? next.toolOutside : open_.arc && open_.toolOutside;
  const bool outside = reverses ? !overArc : side_ * turn < 0;
  if (outside) {
    // LinuxCNC checks an arc before an outside corner when a straight move follows it.
    if (open_.arc && !next.arc && !arcEndsWithin(tool))
      return fmt::format("Arc move in concave corner cannot be reached by the tool (radius {:.4f} mm) without "
                         "gouging: the arc before {} would sweep further than programmed", radius_, point(next.corner));
    // Around the programmed corner at the tool radius; a rapid cannot arc, so it goes straight.
    const double w = tool_[axes_.w];
    if (rapid) step.add({MoveKind::Rapid, spatial(next.start, w)});
    else
      step.add({side_ == kLeft ? MoveKind::ArcCW : MoveKind::ArcCCW, spatial(next.start, w), spatial(next.corner, w), 1});
    startsAt = next.start;
    return {};
  }
  const std::optional<Vec2> meet = insideCorner(next);
  if (!meet)
    return fmt::format("Cutter gouging: the tool (radius {:.4f} mm) does not fit the inside corner at {}",
                       radius_, point(next.corner));
  const bool shortBefore = open_.arc ? !arcEndsWithin(*meet) : (*meet - open_.start).dot(open_.direction) <= 0;
  if (shortBefore)
    return fmt::format("Cutter gouging: the move before the inside corner at {} is too short for the tool (radius {:.4f} mm)",
                       point(next.corner), radius_);
  step.openMoveEnd = *meet;
  startsAt = *meet;
  cornerTrims_ = !reverses;
  return {};
}

std::optional<Vec2> CutterCompensation::insideCorner(const NextMove& next) const {
  Vec2 found[2];
  int count = 0;
  if (!open_.arc && !next.arc) {
    const double denominator = cross(open_.direction, next.startTangent);
    if (std::fabs(denominator) < 1e-12) return std::nullopt;
    found[0] = open_.through + cross(next.start - open_.through, next.startTangent) / denominator * open_.direction;
    count = 1;
  } else if (!open_.arc) {
    count = lineMeetsCircle(open_.through + next.lineShift, open_.direction, next.centre, next.radius, found);
  } else if (!next.arc) {
    count = lineMeetsCircle(next.start, next.startTangent, open_.centre, open_.radius, found);
  } else {
    count = circlesMeet(open_.centre, open_.radius, next.centre, next.radius, found);
  }
  if (count == 0) return std::nullopt;
  // The corner cuts the move before it short: of two meetings, the one that does, and the
  // nearer to the programmed corner where both do (the other is far along the paths).
  const Vec2 tool = planar(tool_);
  auto trims = [&](const Vec2& p) {
    return open_.arc ? sweepBetween(open_.centre, open_.start, p, open_.ccw) <= open_.sweep + kLengthEpsilon
                     : (p - tool).dot(open_.direction) <= kLengthEpsilon;
  };
  if (count == 1) return found[0];
  if (trims(found[0]) != trims(found[1])) return trims(found[0]) ? found[0] : found[1];
  return (found[1] - next.corner).norm() < (found[0] - next.corner).norm() ? found[1] : found[0];
}

}  // namespace isurface::gcode
