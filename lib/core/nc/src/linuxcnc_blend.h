#pragma once
// How LinuxCNC 2.9's planner joins two queued segments (tp.c, blendmath.c): tangent with a
// kink allowance, a parabolic blend (both segments at half acceleration, overlapping in time)
// or a circular blend arc inserted within the G64 tolerance; and the parabolic blend's speeds.
#include <optional>

#include "linuxcnc_segment.h"

namespace isurface::linuxcnc {

struct AxisBounds {
  Vec3 velocity;      // mm/s per axis
  Vec3 acceleration;  // mm/s^2 per axis
  double cycle;       // s
};

// Sets `prev`'s end condition and `next`'s flag that follows from it.
void setTerm(Segment* prev, Segment* next, Term term);

enum class TangentCheck { Refused, Tangent, Kink };
// tpSetupTangent: a junction within the kink allowance becomes tangent (Tangent); a reversal
// becomes a stop (Refused); otherwise the kink speed is noted and a blend may be tried (Kink).
TangentCheck setUpTangent(Segment& prev, Segment& next, const AxisBounds& bounds);

struct BlendArc {
  Segment segment;
  bool consumesPrevious = false;  // the rest of `prev` is short: it becomes the arc's lead
  Vec3 arcStart, arcEnd;          // mm, where it leaves `prev` and joins `next`
  ArcGeometry prevArc, nextArc;   // `prev` and `next` cut to the blend, when they are arcs
};
// The blend arc between two lines, or none where LinuxCNC would not make one.
std::optional<BlendArc> lineLineBlend(const Segment& prev, const Segment& next, const AxisBounds& bounds);

// What a blend arc's radius and speed follow from (blendmath.c's BlendParameters).
struct BlendPlan {
  double theta = 0;               // rad, half the supplement of the corner (pi/2: straight on)
  double phi = 0;                 // rad, the blend arc's sweep
  double tolerance = 0;           // mm, G64 P of both sides (or a quarter of their length)
  double l1 = 0, l2 = 0;          // mm, of `prev` and `next` the blend may take
  double aMax = 0, aNormal = 0;   // mm/s^2, in the corner's plane, and its centripetal share
  double vRequested = 0, vGoal = 0, vPlan = 0;  // mm/s
  double rPlan = 0, dPlan = 0;    // mm, the radius and its distance from the corner
};

// blendParamKinematics: the tolerance, accelerations and goal speed of a blend in the plane
// with unit normal `binormal`; `vAltitude` (mm/s) is the speed two lines allow (0 for arcs).
void planKinematics(const Segment& prev, const Segment& next, const Vec3& binormal, double vAltitude,
                    const AxisBounds& bounds, BlendPlan& plan);
// blendComputeParameters: the radius and speed; false where LinuxCNC gives the arc up.
bool planRadius(BlendPlan& plan);
// blendCheckConsume: a line whose rest after `trim` mm lasts under 4 cycles becomes the lead.
bool consumesRest(const Segment& prev, double trim, double vPlan, double cycle);
// arcFromBlendPoints3 and tpInitBlendArcFromPrev: the blend segment from `arcStart` to
// `arcEnd` about `centre`, with `lead` mm of `prev`'s line before it; none if degenerate.
std::optional<Segment> blendSegment(const Segment& prev, const Segment& next, const BlendPlan& plan, const Vec3& arcStart,
                                    const Vec3& arcEnd, const Vec3& centre, double lead, double cycle);

enum class Joint { Parabolic, Tangent, Arc, None };
// tpChooseBestBlend: the fastest of a parabolic blend, the tangent kink and `arc` (if any).
Joint chooseBestBlend(Segment& prev, Segment& next, const Segment* arc);

// tpComputeBlendVelocity: the speeds at which a parabolic blend of `tc` into `next` starts
// (`vThis`, `vNext`) and its net speed along the blend.
void parabolicBlendVelocities(const Segment& tc, const Segment& next, double targetThis, double targetNext,
                              double& vThis, double& vNext, double* vNet);

// The speed a segment may at most be commanded: its feed, its limits (tcGetMaxTargetVel of a
// move not synchronised with the spindle).
double maxTargetVelocity(const Segment& s);
// sqrt(a L): the peak of a triangle profile over `length` mm at `a` mm/s^2.
double peakVelocity(double a, double length);

}  // namespace isurface::linuxcnc
