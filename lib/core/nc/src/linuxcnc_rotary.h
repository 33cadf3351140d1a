#pragma once
// What LinuxCNC 2.9's canon gives a straight move of X Y Z with A B C (emccanon's
// getStraightVelocity and getStraightAcceleration): each axis's time at its own limit, the
// longest of them sets the speed along the move's length, which is that of X Y Z, or of A B C
// for the rotary axes alone. Units: mm, deg, s.
#include <array>
#include <string>

#include "isurface/machine/machine.h"

namespace isurface::linuxcnc {

// The limits of the program's A, B and C (index 0..2) on the machine; an axis the machine
// lacks has none (present false).
struct RotaryLimits {
  std::array<bool, 3> present{};
  std::array<double, 3> velocity{};      // deg/s
  std::array<double, 3> acceleration{};  // deg/s^2
  std::array<int, 3> kinematicsIndex{-1, -1, -1};  // in FiveAxisKinematics::rotary
};
RotaryLimits rotaryLimits(const Machine& m);

struct StraightLimits {
  double length = 0;        // mm along X Y Z, or deg along A B C when only they move
  double velocity = 0;      // along that length, per s
  double acceleration = 0;  // per s^2
  bool linear = false;      // X Y Z move
  bool angular = false;     // A B C turn
};
// `move`: X Y Z displacement (mm); `turn`: A B C displacement (deg).
StraightLimits straightLimits(const Machine& m, const RotaryLimits& r, const Vec3& move, const Vec3& turn);

// The cap an arc of `length` mm puts on its speed and acceleration so that the rotary axes it
// turns by `turn` deg keep their limits over the same time.
void capByRotary(const RotaryLimits& r, const Vec3& turn, double length, double& velocity, double& acceleration);

}  // namespace isurface::linuxcnc
