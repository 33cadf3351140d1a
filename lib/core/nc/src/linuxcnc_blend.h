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
  Vec3 arcStart, arcEnd;
};
// The blend arc between two lines, or none where LinuxCNC would not make one.
std::optional<BlendArc> lineLineBlend(const Segment& prev, const Segment& next, const AxisBounds& bounds);

enum class Joint { Parabolic, Tangent, Arc, None };
// tpChooseBestBlend: the fastest of a parabolic blend, the tangent kink and `arc` (if any).
Joint chooseBestBlend(Segment& prev, Segment& next, const Segment* arc);

// tpComputeBlendVelocity: the speeds at which a parabolic blend of `tc` into `next` starts
// (`vThis`, `vNext`) and its net speed along the blend.
void parabolicBlendVelocities(const Segment& tc, const Segment& next, double targetThis, double targetNext,
                              double& vThis, double& vNext, double* vNet);

// The speed a segment may at most be commanded: its feed, its limits.
double maxTargetVelocity(const Segment& s);
// sqrt(a L): the peak of a triangle profile over `length` mm at `a` mm/s^2.
double peakVelocity(double a, double length);

}  // namespace isurface::linuxcnc
