#pragma once
// How far a machine's servos carry the tool off a bend, per unit of normal acceleration: the
// steady-state answer of the servo model (servo.h) on a circle, in any plane of two axes.
#include "isurface/machine/machine.h"

namespace isurface {

// The largest deviation of the encoder's position from the commanded one along the commanded
// path's normal, read at the same instant (as the deviation quantity reads a run), divided by
// the normal acceleration v^2 / R: um per mm/s^2. The worst of the XY, XZ and YZ planes.
// The lag that deviates the path grows with the square of the speed where it bends, so a feed
// at which a bend of radius R deviates by at most d um is sqrt(d / response * R) mm/s.
double servoDeviationPerNormalAcceleration(const Machine& machine);

}  // namespace isurface
