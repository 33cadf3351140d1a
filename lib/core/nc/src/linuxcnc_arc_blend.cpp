#include "linuxcnc_arc_blend.h"

#include <algorithm>
#include <cmath>

namespace isurface::linuxcnc {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kAngleEpsilon = 1e-6;             // rad, TP_ANGLE_EPSILON
constexpr double kLengthFuzz = 2.2204460492503131e-16;  // mm, DOUBLE_FUZZ: the least length a cut keeps
constexpr double kColinear = 1e-8;                 // |u1 -+ u2|^2 below which two unit vectors are colinear
constexpr double kHelixLimit = 1e-6;               // mm^2, the rise of an arc LinuxCNC can still cut
constexpr double kKinkFactor = 0.25;               // BLEND_KINK_FACTOR
constexpr double kArcArcMinTheta = kPi / 12;       // rad, two arcs meeting more sharply get no blend

double sweepOf(const ArcGeometry& g) { return std::abs(g.sweep); }
// The arc's point `a` rad from its start (pmCirclePoint).
Vec3 circlePoint(const ArcGeometry& g, double a) { return g.at(a / sweepOf(g)); }

Vec3 planeNormal(const ArcGeometry& g) {
  Vec3 n = Vec3::Zero();
  n[g.axes.w] = 1.0;
  return n;
}

bool colinear(const Vec3& a, const Vec3& b) {
  return (a - b).squaredNorm() < kColinear || (a + b).squaredNorm() < kColinear;
}

Vec3 unit(const Vec3& v) { return v.norm() > 0 ? Vec3(v.normalized()) : Vec3(Vec3::Zero()); }

// A circle's centre and radius as seen from corner `p` (findSpiralApproximation): a spiral's
// centre moves along the tangent by its radius change per radian.
struct LocalCircle {
  Vec3 centre = Vec3::Zero();
  double radius = 0;  // mm
};

LocalCircle approximate(const ArcGeometry& g, const Vec3& p, const Vec3& uTan) {
  Vec3 centre = g.centre;
  centre[g.axes.w] = g.startW;
  LocalCircle c;
  c.centre = centre + uTan * ((g.endRadius - g.startRadius) / sweepOf(g));
  c.radius = (p - c.centre).norm();
  return c;
}

// Whether the blend lies on the inner side of the arc (arcConvexTest): the arc turns the way
// the corner turns.
bool convexTest(const Vec3& centre, const Vec3& p, const Vec3& u, bool reverse) {
  return reverse != ((p - centre).dot(u) < 0);
}

// The corner (BlendGeom3): tangents at it, their secant approximations, its plane.
struct Corner {
  Vec3 uTan1, uTan2, u1, u2, p, binormal, normal;
  double thetaTan = 0;  // rad
  LocalCircle c1, c2;
  bool convex1 = false, convex2 = false;
  double phi1Max = 0, phi2Max = 0;  // rad, of each arc the blend may take
};

// blendGeom3Init: false where the segments are nearly tangent or reversed.
bool cornerOf(const Segment& prev, const Segment& next, Corner& c) {
  c.uTan1 = c.u1 = prev.endTangent();
  c.uTan2 = c.u2 = next.startTangent();
  if (c.uTan1.norm() < 0.5 || c.uTan2.norm() < 0.5) return false;
  c.p = next.shape == Shape::Line ? next.start : prev.shape == Shape::Line ? prev.end : next.arc.at(0);
  c.thetaTan = std::acos(std::clamp(-c.uTan1.dot(c.uTan2), -1.0, 1.0)) / 2;
  if (kPi / 2 - c.thetaTan < kAngleEpsilon || c.thetaTan < kAngleEpsilon) return false;
  c.binormal = unit(c.uTan1.cross(c.uTan2));
  c.normal = unit(c.uTan2 - c.uTan1);
  return true;
}

// blendInit3FromArcLine/ArcArc for the arc before the corner: how much of it the blend may
// take and, on its inner side, its secant towards the corner in place of its tangent.
void fitPrevArc(const Segment& prev, Corner& c, BlendPlan& plan) {
  c.c1 = approximate(prev.arc, c.p, c.uTan1);
  c.convex1 = convexTest(c.c1.centre, c.p, c.uTan2, false);
  c.phi1Max = std::min(sweepOf(prev.arc) * 2.0 / 3.0, c.convex1 ? c.thetaTan : kPi / 2);
  plan.l1 = c.phi1Max * c.c1.radius;
  if (c.convex1) {
    c.u1 = unit(c.p - circlePoint(prev.arc, sweepOf(prev.arc) - c.phi1Max / 2));
    plan.theta = std::min(plan.theta, c.thetaTan - c.phi1Max / 4);
    plan.l1 = std::sin(c.phi1Max / 4) * c.c1.radius;  // half the chord
  }
}

// The same for the arc after the corner (blendInit3FromLineArc/ArcArc).
void fitNextArc(const Segment& next, Corner& c, BlendPlan& plan) {
  c.c2 = approximate(next.arc, c.p, c.uTan2);
  c.convex2 = convexTest(c.c2.centre, c.p, c.uTan1, true);
  c.phi2Max = std::min(sweepOf(next.arc) / 3.0, c.convex2 ? c.thetaTan : kPi / 2);
  plan.l2 = c.phi2Max * c.c2.radius;
  if (c.convex2) {
    c.u2 = unit(circlePoint(next.arc, c.phi2Max / 2) - c.p);
    plan.theta = std::min(plan.theta, c.thetaTan - c.phi2Max / 4);
    plan.l2 = std::sin(c.phi2Max / 4) * c.c2.radius;
  }
}

// The blend's centre found exactly; false where it falls outside the tolerance.
struct Fit {
  Vec3 centre = Vec3::Zero();
  double along = 0;  // mm, from the corner along the line to where the blend leaves it
};

bool withinTolerance(const Vec3& centre, const Vec3& p, const BlendPlan& plan) {
  return (centre - p).norm() - plan.rPlan <= plan.tolerance;
}

// blendLineArcPostProcess, blendArcLinePostProcess: the centre `rPlan` from the line (unit
// `u` through `p`; `side` -1 before the corner, +1 after it) and `rPlan` from the circle.
bool fitLineCircle(const Corner& c, const Vec3& u, double side, const LocalCircle& circle, bool convex,
                   const BlendPlan& plan, Fit& fit) {
  const double d = (convex ? -plan.rPlan : plan.rPlan) + circle.radius;
  const Vec3 n = unit(c.binormal.cross(u));
  const Vec3 toCircle = circle.centre - c.p;
  const double cu = toCircle.dot(u), cn = toCircle.dot(n);
  // along^2 + 2 cu along + cu^2 - d^2 + (R - cn)^2 = 0, the root nearest the corner.
  const double b = 2.0 * cu, k = cu * cu - d * d + (plan.rPlan - cn) * (plan.rPlan - cn);
  const double discriminant = b * b - 4.0 * k;
  if (!(discriminant >= 0)) return false;
  const double root = std::sqrt(discriminant);
  fit.along = std::min(std::abs((-b + root) / 2.0), std::abs((-b - root) / 2.0));
  fit.centre = c.p + u * (side * fit.along) + n * plan.rPlan;
  return withinTolerance(fit.centre, c.p, plan);
}

// blendArcArcPostProcess: the centre `rPlan` from both circles, on the corner's side.
bool fitCircleCircle(const Corner& c, const BlendPlan& plan, Fit& fit) {
  const double d1 = (c.convex1 ? -plan.rPlan : plan.rPlan) + c.c1.radius;
  const double d2 = (c.convex2 ? -plan.rPlan : plan.rPlan) + c.c2.radius;
  const Vec3 between = c.c2.centre - c.c1.centre;
  const double gap = between.norm();
  if (gap < 1e-12) return false;  // concentric: no single solution
  const double x = (-d1 * d1 + d2 * d2 - gap * gap) / (-2.0 * gap);
  if (d1 * d1 < x * x) return false;  // the circles of the fit do not meet
  const double y = std::sqrt(d1 * d1 - x * x);
  const Vec3 uc = between / gap;
  Vec3 nc = c.binormal.cross(uc);
  if (c.normal.dot(nc) < 0) nc = -nc;
  if (nc.norm() < 1e-12) return false;
  nc.normalize();
  Vec3 offset = uc * x + nc * y;
  // Of the two solutions, the one nearer the corner.
  const Vec3 toFirst = c.c1.centre - c.p;
  if ((toFirst + uc * x - nc * y).norm() < (toFirst + offset).norm()) offset = uc * x - nc * y;
  fit.centre = c.c1.centre + offset;
  return withinTolerance(fit.centre, c.p, plan);
}

// findTrimAngle: the angle of the circle about `centre` between the corner and the blend.
double trimAngle(const Vec3& p, const Vec3& blendCentre, const Vec3& centre) {
  return std::acos(std::clamp(unit(p - centre).dot(unit(blendCentre - centre)), -1.0, 1.0));
}

// pmCircleStretch: the arc keeping its first (`keepStart`) or last `sweep` rad; none for a
// helix or nothing left.
std::optional<ArcGeometry> stretched(const ArcGeometry& g, double sweep, bool keepStart) {
  const double rise = g.endW - g.startW;
  if (!(sweep > kLengthFuzz) || rise * rise > kHelixLimit) return std::nullopt;
  const double sign = g.sweep < 0 ? -1.0 : 1.0;
  const double f = keepStart ? sweep / sweepOf(g) : 1.0 - sweep / sweepOf(g);
  const double radius = g.startRadius + (g.endRadius - g.startRadius) * f;
  const double w = g.startW + rise * f;
  ArcGeometry out = g;
  if (keepStart) {
    out.endRadius = radius;
    out.endW = w;
  } else {
    out.startAngle += sign * (sweepOf(g) - sweep);
    out.startRadius = radius;
    out.startW = w;
    out.centre[g.axes.w] = w;
  }
  out.sweep = sign * sweep;
  return out;
}

// checkTangentAngle: the blend meets the arc within the kink one cycle at its speed allows.
bool tangentEnough(const Vec3& uCircle, const Vec3& uBlend, const BlendPlan& plan, double cycle) {
  const double angle = std::acos(std::clamp(uCircle.dot(uBlend), -1.0, 1.0));
  const double allowed = kNormalShare * kKinkFactor * plan.aMax / (plan.vPlan / cycle);
  return angle <= allowed;
}

// The parts every pairing shares: the corner, and the plan for its radius.
bool startPlan(const Segment& prev, const Segment& next, Corner& c, BlendPlan& plan) {
  if (!cornerOf(prev, next, c)) return false;
  plan.theta = c.thetaTan;
  return true;
}

std::optional<BlendArc> lineArc(const Segment& prev, const Segment& next, const AxisBounds& bounds) {
  Corner c;
  BlendPlan plan;
  if (!startPlan(prev, next, c, plan)) return std::nullopt;
  fitNextArc(next, c, plan);
  plan.l1 = std::min(prev.target, prev.nominalLength / 2.0);
  planKinematics(prev, next, c.binormal, 0.0, bounds, plan);
  if (!colinear(c.binormal, planeNormal(next.arc)) || !planRadius(plan)) return std::nullopt;
  Fit fit;
  if (!fitLineCircle(c, c.u1, -1.0, c.c2, c.convex2, plan, fit)) return std::nullopt;
  const double trim2 = trimAngle(c.p, fit.centre, c.c2.centre);
  if (trim2 > c.phi2Max) return std::nullopt;

  BlendArc blend;
  blend.consumesPrevious = consumesRest(prev, fit.along, plan.vPlan, bounds.cycle);
  const double kept = prev.target - fit.along;
  std::optional<ArcGeometry> nextArc = stretched(next.arc, sweepOf(next.arc) - trim2, false);
  if (!(kept > kLengthFuzz) || !nextArc) return std::nullopt;
  blend.nextArc = *nextArc;
  blend.arcStart = prev.start + prev.direction * kept;
  blend.arcEnd = nextArc->at(0);
  const double lead = blend.consumesPrevious ? kept : 0.0;
  std::optional<Segment> arc = blendSegment(prev, next, plan, blend.arcStart, blend.arcEnd, fit.centre, lead, bounds.cycle);
  if (!arc || !tangentEnough(nextArc->tangentAt(0), blendArcTangent(*arc, true), plan, bounds.cycle))
    return std::nullopt;
  blend.segment = std::move(*arc);
  return blend;
}

std::optional<BlendArc> arcLine(const Segment& prev, const Segment& next, const AxisBounds& bounds) {
  Corner c;
  BlendPlan plan;
  if (!startPlan(prev, next, c, plan)) return std::nullopt;
  fitPrevArc(prev, c, plan);
  plan.l2 = next.nominalLength / 2.0;
  planKinematics(prev, next, c.binormal, 0.0, bounds, plan);
  if (!colinear(c.binormal, planeNormal(prev.arc)) || !planRadius(plan)) return std::nullopt;
  Fit fit;
  if (!fitLineCircle(c, c.u2, 1.0, c.c1, c.convex1, plan, fit)) return std::nullopt;
  const double trim1 = trimAngle(c.p, fit.centre, c.c1.centre);
  if (trim1 > c.phi1Max) return std::nullopt;

  BlendArc blend;
  const double kept = next.target - fit.along;
  std::optional<ArcGeometry> prevArc = stretched(prev.arc, sweepOf(prev.arc) - trim1, true);
  if (!(kept > kLengthFuzz) || !prevArc) return std::nullopt;
  blend.prevArc = *prevArc;
  blend.arcStart = prevArc->at(1);
  blend.arcEnd = next.end - next.direction * kept;
  std::optional<Segment> arc = blendSegment(prev, next, plan, blend.arcStart, blend.arcEnd, fit.centre, 0.0, bounds.cycle);
  if (!arc || !tangentEnough(prevArc->tangentAt(1), blendArcTangent(*arc, false), plan, bounds.cycle))
    return std::nullopt;
  blend.segment = std::move(*arc);
  return blend;
}

std::optional<BlendArc> arcArc(const Segment& prev, const Segment& next, const AxisBounds& bounds) {
  if (!colinear(planeNormal(prev.arc), planeNormal(next.arc))) return std::nullopt;
  Corner c;
  BlendPlan plan;
  if (!startPlan(prev, next, c, plan)) return std::nullopt;
  fitPrevArc(prev, c, plan);
  fitNextArc(next, c, plan);
  if (plan.theta < kArcArcMinTheta) return std::nullopt;
  planKinematics(prev, next, c.binormal, 0.0, bounds, plan);
  if (!colinear(c.binormal, planeNormal(prev.arc)) || !planRadius(plan)) return std::nullopt;
  Fit fit;
  if (!fitCircleCircle(c, plan, fit)) return std::nullopt;
  const double trim1 = trimAngle(c.p, fit.centre, c.c1.centre);
  const double trim2 = trimAngle(c.p, fit.centre, c.c2.centre);
  if (trim1 > c.phi1Max || trim2 > c.phi2Max) return std::nullopt;

  BlendArc blend;
  std::optional<ArcGeometry> prevArc = stretched(prev.arc, sweepOf(prev.arc) - trim1, true);
  std::optional<ArcGeometry> nextArc = stretched(next.arc, sweepOf(next.arc) - trim2, false);
  if (!prevArc || !nextArc) return std::nullopt;
  blend.prevArc = *prevArc;
  blend.nextArc = *nextArc;
  blend.arcStart = prevArc->at(1);
  blend.arcEnd = nextArc->at(0);
  std::optional<Segment> arc = blendSegment(prev, next, plan, blend.arcStart, blend.arcEnd, fit.centre, 0.0, bounds.cycle);
  if (!arc || !tangentEnough(prevArc->tangentAt(1), blendArcTangent(*arc, false), plan, bounds.cycle) ||
      !tangentEnough(nextArc->tangentAt(0), blendArcTangent(*arc, true), plan, bounds.cycle))
    return std::nullopt;
  blend.segment = std::move(*arc);
  return blend;
}

}  // namespace

Vec3 blendArcTangent(const Segment& blend, bool atEnd) {
  // d/da of the slerp from rStart to rEnd (the sine of the sweep divided out).
  const double cosine = std::cos(blend.angle);
  return unit(atEnd ? Vec3(blend.rEnd * cosine - blend.rStart) : Vec3(blend.rEnd - blend.rStart * cosine));
}

std::optional<BlendArc> arcBlend(const Segment& prev, const Segment& next, const AxisBounds& bounds) {
  const bool lineBefore = prev.shape == Shape::Line, lineAfter = next.shape == Shape::Line;
  const bool arcBefore = prev.shape == Shape::Arc, arcAfter = next.shape == Shape::Arc;
  if ((arcBefore && sweepOf(prev.arc) < kAngleEpsilon) || (arcAfter && sweepOf(next.arc) < kAngleEpsilon))
    return std::nullopt;
  if (lineBefore && arcAfter) return lineArc(prev, next, bounds);
  if (arcBefore && lineAfter) return arcLine(prev, next, bounds);
  if (arcBefore && arcAfter) return arcArc(prev, next, bounds);
  return std::nullopt;
}

}  // namespace isurface::linuxcnc
