#include "isurface/nc/servo_response.h"

#include <algorithm>
#include <cmath>

#include "isurface/base/units.h"
#include "isurface/nc/servo.h"

namespace isurface {

namespace {

// One plane of two axes driven round a circle at a steady speed; the deviation is measured
// over the last revolution, once the start's transient has died away.
double circleResponse(const Machine& machine, int first, int second) {
  constexpr double kRadius = 5.0;       // mm
  constexpr double kSpeed = 20.0;       // mm/s: a normal acceleration of 80 mm/s^2
  constexpr int kRevolutions = 3;
  const double omega = kSpeed / kRadius;  // rad/s
  const double period = 2 * kPi / omega;
  const long steps = static_cast<long>(std::ceil(kRevolutions * period / machine.cycle));
  const long measuredFrom = static_cast<long>(std::floor((kRevolutions - 1) * period / machine.cycle));
  AxisServo a(machine.axes[first], machine.cycle, kRadius), b(machine.axes[second], machine.cycle, 0.0);
  double worst = 0;  // mm
  for (long k = 0; k <= steps; ++k) {
    const double angle = omega * machine.cycle * double(k);
    const double ca = std::cos(angle), sa = std::sin(angle);
    const double fa = a.step(kRadius * ca), fb = b.step(kRadius * sa);
    if (k < measuredFrom) continue;
    worst = std::max(worst, std::fabs((fa - kRadius * ca) * ca + (fb - kRadius * sa) * sa));
  }
  return 1000.0 * worst / (kSpeed * kSpeed / kRadius);
}

}  // namespace

double servoDeviationPerNormalAcceleration(const Machine& machine) {
  return std::max({circleResponse(machine, 0, 1), circleResponse(machine, 0, 2), circleResponse(machine, 1, 2)});
}

}  // namespace isurface
