#pragma once
// The blend arcs LinuxCNC 2.9 inserts where a line meets an arc, an arc meets a line, or two
// arcs meet (tp.c tpCreateLineArcBlend, tpCreateArcLineBlend, tpCreateArcArcBlend; blendmath.c
// blendInit3From*, blendLineArcPostProcess, blendArcLinePostProcess, blendArcArcPostProcess).
// An arc is first approximated near the corner by its secant (when the blend lies on its
// inner side), the radius planned as for two lines, and the blend then fitted exactly tangent
// to the line and to the arc's circle. Units: mm, s, rad.
#include <optional>

#include "linuxcnc_blend.h"

namespace isurface::linuxcnc {

// The blend arc between `prev` and `next` when at least one of them is an arc (G2/G3), or
// none where LinuxCNC would refuse one: not in one plane, a helix, a corner too nearly
// tangent or reversed, a fit outside the tolerance, a cut of more of an arc than it allows,
// or a blend whose ends are not tangent enough to the arcs for its speed. The result carries
// the arcs cut to the blend (`prevArc`, `nextArc`); lines are cut to `arcStart`, `arcEnd`.
std::optional<BlendArc> arcBlend(const Segment& prev, const Segment& next, const AxisBounds& bounds);

// The unit tangent of a blend segment's arc at its start or end (arcTangent).
Vec3 blendArcTangent(const Segment& blend, bool atEnd);

}  // namespace isurface::linuxcnc
