#include "linuxcnc_blend.h"

#include <algorithm>
#include <cmath>

namespace isurface::linuxcnc {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kKinkRatio = 0.1;          // ARC_BLEND_KINK_RATIO
constexpr double kGapCycles = 4;            // ARC_BLEND_GAP_CYCLES
constexpr double kBlendDistanceShare = 0.5; // BLEND_DIST_FRACTION
constexpr double kAngleEpsilon = 1e-6;      // rad
constexpr double kMinArcLength = 1e-6;      // mm
constexpr double kMinArcAngle = 1e-3;       // rad

// Half the supplement of the angle between the directions: pi/2 when they go straight on.
double intersectionAngle(const Vec3& u1, const Vec3& u2) { return std::acos(std::clamp(-u1.dot(u2), -1.0, 1.0)) / 2; }

}  // namespace

double peakVelocity(double a, double length) { return std::sqrt(std::max(0.0, a * length)); }

double maxTargetVelocity(const Segment& s) { return std::min(s.requested, s.maxVelocity); }

void setTerm(Segment* prev, Segment* next, Term term) {
  if (next) next->blendBefore = term == Term::Parabolic;
  if (prev) prev->term = term;
}

TangentCheck setUpTangent(Segment& prev, Segment& next, const AxisBounds& bounds) {
  if (prev.term == Term::Stop) return TangentCheck::Refused;
  const Vec3 t1 = prev.endTangent(), t2 = next.startTangent();
  // Within 2 degrees of a reversal: a stop.
  const double sharp = std::pow(kPi * 2.0 / 180.0, 2);
  if ((t1 + t2).squaredNorm() < sharp) {
    setTerm(&prev, &next, Term::Stop);
    return TangentCheck::Refused;
  }
  const double vMax = std::min(std::min(prev.maxVelocity, prev.requested), std::min(next.maxVelocity, next.requested));
  // Worst case: stopping on one and starting on the other within one cycle, at full speed.
  const double instant = vMax / bounds.cycle + next.maxAcceleration;
  const Vec3 change = (t2 - t1) * instant;
  double scale = 0;
  for (int i = 0; i < 3; ++i)
    if (bounds.acceleration[i] > 0) scale = std::max(scale, std::abs(change[i] / bounds.acceleration[i]));
  if (prev.curved() || next.curved()) scale /= kTangentialShare;
  auto kink = [&](double velocity, double reduction) {
    prev.kinkVelocity = velocity;
    prev.kinkReduction = std::max(reduction, prev.kinkReduction);
    next.kinkReductionBefore = std::max(reduction, next.kinkReductionBefore);
  };
  if (scale < kKinkRatio) {
    setTerm(&prev, &next, Term::Tangent);
    kink(vMax, scale);
    return TangentCheck::Tangent;
  }
  kink(vMax * kKinkRatio / scale, kKinkRatio);
  return TangentCheck::Kink;
}

void parabolicBlendVelocities(const Segment& tc, const Segment& next, double targetThis, double targetNext,
                              double& vThis, double& vNext, double* vNet) {
  const double accThis = tangentialAcceleration(tc), accNext = tangentialAcceleration(next);
  // Blending may take at most half of a segment that is not finalized yet.
  auto triangle = [](const Segment& s) {
    return peakVelocity(tangentialAcceleration(s), s.finalized ? s.target : s.target / 2);
  };
  const double reachThis = std::min(triangle(tc), targetThis);
  const double reachNext = std::min(triangle(next), targetNext);
  const double tMaxReachable = std::min(tc.target / reachThis, next.target / reachNext);
  const double tMaxBlend = std::max(reachThis / accThis, reachNext / accNext);
  const double tBlend = std::min(tMaxReachable, tMaxBlend);
  vThis = std::min(reachThis, tBlend * accThis);
  vNext = std::min(reachNext, tBlend * accNext);
  const double theta = intersectionAngle(tc.endTangent(), next.startTangent());
  const double cosTheta = std::cos(theta);
  if (tc.tolerance > 0 && cosTheta > std::cos(kPi / 2 - kMinArcAngle)) {
    const double toleranceVelocity = 2.0 * std::sqrt(accThis * tc.tolerance / cosTheta);
    vThis = std::min(vThis, toleranceVelocity);
    vNext = std::min(vNext, toleranceVelocity);
  }
  if (vNet) *vNet = std::sin(theta) * (vThis + vNext) / 2.0;
}

Joint chooseBestBlend(Segment& prev, Segment& next, const Segment* arc) {
  if (prev.term == Term::Exact || prev.term == Term::Stop) return Joint::None;
  double vThis = 0, vNext = 0, vNet = 0;
  parabolicBlendVelocities(prev, next, maxTargetVelocity(prev), maxTargetVelocity(next), vThis, vNext, &vNet);
  // A parabolic blend halves the acceleration of both segments: counted at half its speed.
  const double performance[3] = {vNet / 2.0, prev.kinkVelocity, arc ? arc->maxVelocity : 0.0};
  const Joint best = static_cast<Joint>(std::max_element(performance, performance + 3) - performance);
  auto removeKink = [&] {
    prev.kinkVelocity = -1;
    prev.kinkReduction = 0;
    next.kinkReductionBefore = 0;
  };
  switch (best) {
    case Joint::Parabolic: removeKink(); setTerm(&prev, &next, Term::Parabolic); break;
    case Joint::Tangent: setTerm(&prev, &next, Term::Tangent); break;
    case Joint::Arc: removeKink(); break;
    case Joint::None: break;
  }
  return best;
}

void planKinematics(const Segment& prev, const Segment& next, const Vec3& binormal, double vAltitude,
                    const AxisBounds& bounds, BlendPlan& plan) {
  plan.phi = kPi - 2 * plan.theta;
  // The tolerance: each side's G64 P (or a quarter of its length), never more than a quarter.
  const double t1 = prev.tolerance > 0 ? prev.tolerance : prev.nominalLength * 0.25;
  const double t2 = next.tolerance > 0 ? next.tolerance : next.nominalLength * 0.25;
  plan.tolerance = std::min({t1, t2, prev.nominalLength * 0.25, next.nominalLength * 0.25});
  plan.aMax = inscribedInPlane(binormal, bounds.acceleration);
  plan.aNormal = plan.aMax * kNormalShare;
  plan.vRequested = std::max(prev.requested, next.requested);
  const double vPlanar = inscribedInPlane(binormal, bounds.velocity);
  plan.vGoal = std::min(plan.vRequested, std::max(vAltitude, vPlanar));
}

bool planRadius(BlendPlan& plan) {
  const double dTolerance = std::cos(plan.theta) * plan.tolerance / (1.0 - std::sin(plan.theta));
  const double dGeometry = std::min({plan.l1, plan.l2, dTolerance});
  const double rGeometry = std::tan(plan.theta) * dGeometry;
  plan.vPlan = std::min(std::sqrt(plan.aNormal * rGeometry), plan.vGoal);
  // As small a radius as reaches the speed a parabolic blend of these lengths would have.
  const double aParabolic = plan.aMax * 0.5;
  const double vTriangle = std::sqrt(2.0 * aParabolic * dGeometry);
  const double sBlend = std::min(vTriangle, plan.vPlan) / aParabolic * plan.vPlan;
  const double rBlend = std::min(sBlend / plan.phi, rGeometry);
  plan.rPlan = std::max(plan.vPlan * plan.vPlan / plan.aNormal, rBlend);
  plan.dPlan = plan.rPlan / std::tan(plan.theta);
  return plan.rPlan >= 1e-12 && plan.rPlan * plan.phi >= kMinArcLength;
}

bool consumesRest(const Segment& prev, double trim, double vPlan, double cycle) {
  if (prev.shape != Shape::Line) return false;
  return (prev.target - trim) / vPlan < kGapCycles * cycle && !prev.blendBefore;
}

std::optional<Segment> blendSegment(const Segment& prev, const Segment& next, const BlendPlan& plan, const Vec3& arcStart,
                                    const Vec3& arcEnd, const Vec3& centre, double lead, double cycle) {
  Segment arc;
  arc.shape = Shape::Blend;
  arc.centre = centre;
  arc.rStart = arcStart - centre;
  arc.rEnd = arcEnd - centre;
  const double r0 = arc.rStart.norm(), r1 = arc.rEnd.norm();
  if (r0 < 1e-12 || r1 < 1e-12) return std::nullopt;  // ARC_MIN_RADIUS
  arc.radius = r0;
  arc.angle = std::acos(std::clamp(arc.rStart.dot(arc.rEnd) / (r0 * r1), -1.0, 1.0));
  if (arc.angle < 1e-6) return std::nullopt;  // ARC_MIN_ANGLE
  arc.lead = lead;
  arc.direction = prev.endTangent();
  arc.start = arcStart - arc.direction * lead;
  arc.end = arcEnd;
  arc.target = arc.lead + arc.radius * arc.angle;
  arc.nominalLength = arc.target;
  arc.requested = plan.vRequested;
  arc.maxVelocity = std::min(plan.vPlan, arc.target / cycle);
  arc.maxAcceleration = plan.aMax;
  arc.tolerance = next.tolerance;
  arc.term = Term::Tangent;
  arc.traverse = prev.traverse;
  arc.finalized = true;
  return arc;
}

std::optional<BlendArc> lineLineBlend(const Segment& prev, const Segment& next, const AxisBounds& bounds) {
  if (prev.shape != Shape::Line || next.shape != Shape::Line) return std::nullopt;
  const Vec3 u1 = prev.direction, u2 = next.direction;
  BlendPlan plan;
  plan.theta = intersectionAngle(u1, u2);
  if (kPi / 2 - plan.theta < kAngleEpsilon || plan.theta < kAngleEpsilon) return std::nullopt;
  const Vec3 binormal = u1.cross(u2).normalized();
  const Vec3 normal = (u2 - u1).normalized();
  const Vec3 corner = next.start;

  // The speed two lines allow: the altitude of the triangle of their speed vectors.
  const double phi = kPi - 2 * plan.theta;
  const double phiEffective = std::min(phi, kPi * 0.49);
  const double v1 = std::min(prev.maxVelocity, next.maxVelocity / std::cos(phiEffective));
  const double v2 = std::min(next.maxVelocity, prev.maxVelocity / std::cos(phiEffective));
  const double base = (u2 * v2 - u1 * v1).norm();
  const double vAltitude = base > 0 ? v1 * v2 * std::sin(phi) / base : 0.0;
  planKinematics(prev, next, binormal, vAltitude, bounds, plan);
  plan.l1 = std::min(prev.target, prev.nominalLength * kBlendDistanceShare);
  plan.l2 = next.target * kBlendDistanceShare;
  if (!planRadius(plan)) return std::nullopt;

  BlendArc blend;
  blend.arcStart = corner - u1 * plan.dPlan;
  blend.arcEnd = corner + u2 * plan.dPlan;
  blend.consumesPrevious = consumesRest(prev, plan.dPlan, plan.vPlan, bounds.cycle);
  const double lead = blend.consumesPrevious ? std::max(0.0, prev.target - plan.dPlan) : 0.0;
  const Vec3 centre = corner + normal * (plan.rPlan / std::sin(plan.theta));
  std::optional<Segment> arc = blendSegment(prev, next, plan, blend.arcStart, blend.arcEnd, centre, lead, bounds.cycle);
  if (!arc) return std::nullopt;
  blend.segment = std::move(*arc);
  return blend;
}

}  // namespace isurface::linuxcnc
