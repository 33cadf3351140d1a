// The blend arcs of the linuxcnc-2.9 control where a line meets an arc, an arc a line and two
// arcs: where they lie, their radius and speed, and the corners LinuxCNC leaves unblended.
#include <gtest/gtest.h>

#include <cmath>

#include "linuxcnc_arc_blend.h"

namespace isurface::linuxcnc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTolerance = 0.01;  // mm, G64 P

AxisBounds bounds() { return {Vec3(100, 100, 100), Vec3(1000, 1000, 1000), 0.001}; }

Segment queued(Segment s) {
  s.nominalLength = s.target;
  s.requested = 40;  // mm/s
  s.maxVelocity = 100;
  s.maxAcceleration = 1000;
  s.tolerance = kTolerance;
  s.term = Term::Parabolic;
  return s;
}

Segment line(const Vec3& from, const Vec3& to) {
  Segment s;
  s.start = from;
  s.end = to;
  s.target = (to - from).norm();
  s.direction = (to - from) / s.target;
  return queued(s);
}

// An arc in the XY plane about `centre` of `radius` mm from `startAngle` over `sweep` rad
// (> 0 counter-clockwise), rising `rise` mm.
Segment arc(const Vec3& centre, double radius, double startAngle, double sweep, double rise = 0) {
  Segment s;
  s.shape = Shape::Arc;
  s.arc.centre = centre;
  s.arc.startAngle = startAngle;
  s.arc.sweep = sweep;
  s.arc.startRadius = s.arc.endRadius = radius;
  s.arc.startW = centre.z();
  s.arc.endW = centre.z() + rise;
  s.start = s.arc.at(0);
  s.end = s.arc.at(1);
  s.target = s.arc.length();
  return queued(s);
}

// The radius a blend limited by the tolerance has at half-angle `theta` (blendComputeParameters
// with d = cos(theta) T / (1 - sin(theta)), R = tan(theta) d).
double toleranceRadius(double theta) { return kTolerance * std::sin(theta) / (1.0 - std::sin(theta)); }

double distanceToLine(const Vec3& p, const Segment& l) {
  return (p - l.start - l.direction * (p - l.start).dot(l.direction)).norm();
}

double angleBetween(const Vec3& a, const Vec3& b) { return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)); }

TEST(linuxcncArcBlend, aLineIntoAnArcTurningTheSameWayGetsAnArcTangentToBothWithinTheTolerance) {
  // +X into a counter-clockwise arc of 5 mm whose start tangent is 30 degrees to the left.
  const double kink = kPi / 6;
  const Vec3 corner(10, 0, 0);
  const Vec3 centre = corner + 5.0 * Vec3(-std::sin(kink), std::cos(kink), 0);
  const Segment prev = line(Vec3(0, 0, 0), corner);
  const Segment next = arc(centre, 5.0, kink - kPi / 2, kPi / 2);
  ASSERT_LT((next.start - corner).norm(), 1e-12);

  const std::optional<BlendArc> blend = arcBlend(prev, next, bounds());
  ASSERT_TRUE(blend.has_value());
  const Segment& b = blend->segment;
  // The corner's half-angle, less a quarter of the arc the blend may take (a sixth of 90
  // degrees in the secant approximation of the arc's inner side).
  const double theta = (kPi - kink) / 2 - (kPi / 6) / 4;
  const double radius = toleranceRadius(theta);
  EXPECT_NEAR(b.radius, radius, 1e-9);
  EXPECT_NEAR(b.maxVelocity, std::sqrt(kNormalShare * 1000 * radius), 1e-6);
  EXPECT_DOUBLE_EQ(b.maxAcceleration, 1000);

  // It leaves the line and joins the circle, tangent to both, and stays within G64 P.
  EXPECT_NEAR(blend->arcStart.y(), 0.0, 1e-12);
  EXPECT_GT(blend->arcStart.x(), 9.9);
  EXPECT_LT(blend->arcStart.x(), 10.0);
  EXPECT_NEAR((blend->arcEnd - centre).norm(), 5.0, 1e-9);
  EXPECT_NEAR(distanceToLine(b.centre, prev), radius, 1e-9);
  EXPECT_NEAR((b.centre - centre).norm(), 5.0 - radius, 1e-9);  // inside the circle
  EXPECT_LE((b.centre - corner).norm() - radius, kTolerance);
  EXPECT_LT(angleBetween(blendArcTangent(b, false), Vec3::UnitX()), 1e-6);
  EXPECT_LT(angleBetween(blendArcTangent(b, true), blend->nextArc.tangentAt(0)), 1e-6);
  EXPECT_NEAR((b.pointAt(b.target) - blend->arcEnd).norm(), 0.0, 1e-12);

  // The arc now starts where the blend ends and still ends where it did.
  EXPECT_NEAR((blend->nextArc.at(0) - blend->arcEnd).norm(), 0.0, 1e-12);
  EXPECT_NEAR((blend->nextArc.at(1) - next.end).norm(), 0.0, 1e-9);
  EXPECT_LT(blend->nextArc.length(), next.target);
  EXPECT_FALSE(blend->consumesPrevious);
}

TEST(linuxcncArcBlend, anArcIntoALineTurningTheOtherWayGetsAnArcOutsideItsCircle) {
  // A clockwise arc of 5 mm ending along +X, then a line 40 degrees to the left.
  const double kink = 40 * kPi / 180;
  const Vec3 corner(10, 0, 0);
  const Vec3 centre(10, -5, 0);
  const Segment prev = arc(centre, 5.0, kPi, -kPi / 2);
  const Segment next = line(corner, corner + 10.0 * Vec3(std::cos(kink), std::sin(kink), 0));
  ASSERT_LT((prev.end - corner).norm(), 1e-12);

  const std::optional<BlendArc> blend = arcBlend(prev, next, bounds());
  ASSERT_TRUE(blend.has_value());
  const Segment& b = blend->segment;
  // No secant on the arc's outer side: the corner's own half-angle.
  const double radius = toleranceRadius((kPi - kink) / 2);
  EXPECT_NEAR(b.radius, radius, 1e-9);
  EXPECT_NEAR(distanceToLine(b.centre, next), radius, 1e-9);
  EXPECT_NEAR((b.centre - centre).norm(), 5.0 + radius, 1e-9);
  EXPECT_LE((b.centre - corner).norm() - radius, kTolerance);
  EXPECT_NEAR((blend->arcStart - centre).norm(), 5.0, 1e-9);
  EXPECT_NEAR(distanceToLine(blend->arcEnd, next), 0.0, 1e-12);
  EXPECT_LT(angleBetween(blendArcTangent(b, false), blend->prevArc.tangentAt(1)), 1e-6);
  EXPECT_LT(angleBetween(blendArcTangent(b, true), next.direction), 1e-6);
  EXPECT_NEAR((blend->prevArc.at(0) - prev.start).norm(), 0.0, 1e-9);
  EXPECT_NEAR((blend->prevArc.at(1) - blend->arcStart).norm(), 0.0, 1e-12);
}

TEST(linuxcncArcBlend, twoArcsMeetingAtAKinkGetAnArcTangentToBothCircles) {
  const double kink = 40 * kPi / 180;
  const Vec3 corner(0, 0, 0);
  const Vec3 centre1(0, 5, 0), centre2 = corner + 5.0 * Vec3(-std::sin(kink), std::cos(kink), 0);
  const Segment prev = arc(centre1, 5.0, -kPi, kPi / 2);  // counter-clockwise, ending along +X
  const Segment next = arc(centre2, 5.0, kink - kPi / 2, kPi / 2);
  ASSERT_LT((prev.end - corner).norm(), 1e-12);
  ASSERT_LT((next.start - corner).norm(), 1e-12);

  const std::optional<BlendArc> blend = arcBlend(prev, next, bounds());
  ASSERT_TRUE(blend.has_value());
  const Segment& b = blend->segment;
  EXPECT_GT(b.radius, 0.0);
  EXPECT_NEAR((b.centre - centre1).norm(), 5.0 - b.radius, 1e-9);
  EXPECT_NEAR((b.centre - centre2).norm(), 5.0 - b.radius, 1e-9);
  EXPECT_LE((b.centre - corner).norm() - b.radius, kTolerance);
  EXPECT_LE(b.maxVelocity * b.maxVelocity / b.radius, kNormalShare * 1000 * (1 + 1e-9));
  EXPECT_NEAR((blend->prevArc.at(1) - blend->arcStart).norm(), 0.0, 1e-12);
  EXPECT_NEAR((blend->nextArc.at(0) - blend->arcEnd).norm(), 0.0, 1e-12);
}

TEST(linuxcncArcBlend, cornersLinuxcncLeavesToATangentOrParabolicJunctionGetNoArc) {
  const Vec3 corner(10, 0, 0);
  const Segment arcAlongX = arc(Vec3(10, 5, 0), 5.0, -kPi / 2, kPi / 2);  // starts along +X
  // Tangent already.
  EXPECT_FALSE(arcBlend(line(Vec3(0, 0, 0), corner), arcAlongX, bounds()).has_value());
  // A plunge into an arc in XY: not in one plane.
  EXPECT_FALSE(arcBlend(line(Vec3(10, 0, 5), corner), arcAlongX, bounds()).has_value());
  // A helix cannot be cut.
  const Segment helix = arc(Vec3(10, -5, 0), 5.0, kPi, -kPi / 2, 1.0);
  EXPECT_FALSE(arcBlend(helix, line(helix.end, helix.end + Vec3(5, 5, 0)), bounds()).has_value());
  // Reversal, and an arc of no sweep.
  const Segment back = arc(Vec3(10, 5, 0), 5.0, -kPi / 2, -kPi / 2);
  EXPECT_FALSE(arcBlend(line(Vec3(20, 0, 0), corner), back, bounds()).has_value());
  EXPECT_FALSE(arcBlend(line(Vec3(0, 0, 0), corner), arc(Vec3(10, 5, 0), 5.0, 0.3, 0.0), bounds()).has_value());
  // Two lines are not this function's.
  EXPECT_FALSE(arcBlend(line(Vec3(0, 0, 0), corner), line(corner, Vec3(10, 10, 0)), bounds()).has_value());
}

TEST(linuxcncArcBlend, aShortLineBeforeTheArcBecomesTheBlendsLead) {
  // 0.01 mm of line at 10 mm/s lasts one cycle: under ARC_BLEND_GAP_CYCLES, so it is consumed.
  const double kink = kPi / 4;
  const Vec3 corner(10, 0, 0);
  const Segment prev = line(Vec3(9.98, 0, 0), corner);
  const Segment next = arc(corner + 5.0 * Vec3(-std::sin(kink), std::cos(kink), 0), 5.0, kink - kPi / 2, kPi / 2);
  const std::optional<BlendArc> blend = arcBlend(prev, next, bounds());
  ASSERT_TRUE(blend.has_value());
  EXPECT_TRUE(blend->consumesPrevious);
  const Segment& b = blend->segment;
  EXPECT_NEAR(b.lead, (blend->arcStart - prev.start).norm(), 1e-12);
  EXPECT_NEAR((b.pointAt(0) - prev.start).norm(), 0.0, 1e-12);
  EXPECT_NEAR(b.target, b.lead + b.radius * b.angle, 1e-12);
}

}  // namespace
}  // namespace isurface::linuxcnc
