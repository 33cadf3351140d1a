// Velocity, acceleration and jerk by finite differences; see kinematics.h for the stencils.
#include "isurface/analysis/kinematics.h"

#include <cmath>
#include <limits>

#include "isurface/base/units.h"

namespace isurface {

namespace {

struct Derivatives {
  double v[3], a[3], j[3];  // mm/s, mm/s^2, mm/s^3
};

// Regular grid. P(k, axis) is the position of sample k. Multiplies by reciprocals of the cycle.
struct RegularGrid {
  double halfInvT, invT2, invT3, halfInvT3, invT;
  static RegularGrid of(double T) {
    return {0.5 / T, 1.0 / (T * T), 1.0 / (T * T * T), 0.5 / (T * T * T), 1.0 / T};
  }

  template <class Pos>
  void derive(std::size_t i, std::size_t n, const Pos& P, Derivatives& d) const {
    for (int ax = 0; ax < 3; ++ax) d.v[ax] = d.a[ax] = d.j[ax] = 0;
    if (n < 2) return;
    if (n == 2) {
      for (int ax = 0; ax < 3; ++ax) d.v[ax] = (P(1, ax) - P(0, ax)) * invT;
      return;
    }
    const std::size_t last = n - 1;
    for (int ax = 0; ax < 3; ++ax) {
      if (i == 0) {
        d.v[ax] = (-3 * P(0, ax) + 4 * P(1, ax) - P(2, ax)) * halfInvT;
      } else if (i == last) {
        d.v[ax] = (P(last - 2, ax) - 4 * P(last - 1, ax) + 3 * P(last, ax)) * halfInvT;
      } else {
        d.v[ax] = (P(i + 1, ax) - P(i - 1, ax)) * halfInvT;
      }
    }
    if (n == 3) {
      for (int ax = 0; ax < 3; ++ax) {
        d.a[ax] = (P(2, ax) - 2 * P(1, ax) + P(0, ax)) * invT2;
        d.v[ax] += P(i, ax) - P(i, ax);
      }
      return;
    }
    for (int ax = 0; ax < 3; ++ax) {
      if (i == 0) {
        d.a[ax] = (2 * P(0, ax) - 5 * P(1, ax) + 4 * P(2, ax) - P(3, ax)) * invT2;
      } else if (i == last) {
        d.a[ax] = (2 * P(last, ax) - 5 * P(last - 1, ax) + 4 * P(last - 2, ax) - P(last - 3, ax)) * invT2;
      } else {
        d.a[ax] = (P(i + 1, ax) - 2 * P(i, ax) + P(i - 1, ax)) * invT2;
      }
      if (i < 2) {
        d.j[ax] = (P(3, ax) - 3 * P(2, ax) + 3 * P(1, ax) - P(0, ax)) * invT3;
      } else if (i + 2 > last) {
        d.j[ax] = (P(last, ax) - 3 * P(last - 1, ax) + 3 * P(last - 2, ax) - P(last - 3, ax)) * invT3;
      } else {
        d.j[ax] = (P(i + 2, ax) - 2 * P(i + 1, ax) + 2 * P(i - 1, ax) - P(i - 2, ax)) * halfInvT3;
      }
    }
    // The central velocity and jerk skip p[i]; a bad sample still gets no values of its own
    // (p - p is 0 for a finite p, NaN otherwise).
    for (int ax = 0; ax < 3; ++ax) {
      const double own = P(i, ax) - P(i, ax);
      d.v[ax] += own;
      d.j[ax] += own;
    }
  }
};

// Any time base: divided differences. H(k) = t[k+1] - t[k].
template <class Pos, class Gap>
void deriveDivided(std::size_t i, std::size_t n, const Pos& P, const Gap& H, Derivatives& d) {
  for (int ax = 0; ax < 3; ++ax) d.v[ax] = d.a[ax] = d.j[ax] = 0;
  if (n < 2) return;
  if (n == 2) {
    const double h = H(0);
    for (int ax = 0; ax < 3; ++ax) d.v[ax] = (P(1, ax) - P(0, ax)) / h;
    return;
  }
  // Jerk: 6 x the third divided difference over nodes k-1..k+2, centred between k and k+1.
  const auto half = [&](std::size_t k, double out[3]) {
    const double g0 = H(k - 1), g1 = H(k), g2 = H(k + 1);
    for (int ax = 0; ax < 3; ++ax) {
      const double da = (P(k, ax) - P(k - 1, ax)) / g0;
      const double db = (P(k + 1, ax) - P(k, ax)) / g1;
      const double dc = (P(k + 2, ax) - P(k + 1, ax)) / g2;
      const double fa = (db - da) / (g0 + g1), fb = (dc - db) / (g1 + g2);
      out[ax] = 6 * (fb - fa) / (g0 + g1 + g2);
    }
  };
  if (n >= 4) {
    if (i < 2) {
      half(1, d.j);
    } else if (i + 2 > n - 1) {
      half(n - 3, d.j);
    } else {
      double before[3], after[3];
      half(i - 1, before);
      half(i, after);
      // Each value belongs to the mean time of its four nodes; interpolate linearly to t_i.
      const double hm2 = H(i - 2), hm1 = H(i - 1), h0 = H(i), h1 = H(i + 1);
      const double w = (hm2 + 2 * hm1 - h0) / (hm2 + hm1 + h0 + h1);
      for (int ax = 0; ax < 3; ++ax) d.j[ax] = before[ax] + w * (after[ax] - before[ax]);
    }
  }
  // Velocity and acceleration from the quadratic through three nodes s..s+2; the acceleration
  // is moved from the nodes' mean time to t_i with the jerk (exact for a cubic).
  const std::size_t s = i == 0 ? 0 : (i + 1 >= n ? n - 3 : i - 1);
  const double h1 = H(s), h2 = H(s + 1);
  double shift;
  if (i == s) {
    shift = -(2 * h1 + h2) / 3;
  } else if (i == s + 1) {
    shift = (h1 - h2) / 3;
  } else {
    shift = (h1 + 2 * h2) / 3;
  }
  for (int ax = 0; ax < 3; ++ax) {
    const double d1 = (P(s + 1, ax) - P(s, ax)) / h1;
    const double d2 = (P(s + 2, ax) - P(s + 1, ax)) / h2;
    const double f2 = (d2 - d1) / (h1 + h2);
    if (i == s) {
      d.v[ax] = d1 - f2 * h1;
    } else if (i == s + 1) {
      d.v[ax] = (h2 * d1 + h1 * d2) / (h1 + h2);
    } else {
      d.v[ax] = d2 + f2 * h2;
    }
    d.a[ax] = 2 * f2;
    // Skipped when the jerk is not finite, so a bad sample two away cannot reach the acceleration.
    if (n >= 4 && shift != 0 && std::isfinite(d.j[ax])) d.a[ax] += shift * d.j[ax];
  }
}

struct PathValues {
  double speed, accel, accelMagnitude, jerk;  // mm/s, mm/s^2 (signed), mm/s^2, mm/s^3
};

PathValues pathValues(const Derivatives& d) {
  const double v2 = d.v[0] * d.v[0] + d.v[1] * d.v[1] + d.v[2] * d.v[2];
  const double vmag = std::sqrt(v2);
  const double dot = d.v[0] * d.a[0] + d.v[1] * d.a[1] + d.v[2] * d.a[2];
  PathValues p;
  p.speed = vmag;
  p.accelMagnitude = std::sqrt(d.a[0] * d.a[0] + d.a[1] * d.a[1] + d.a[2] * d.a[2]);
  p.accel = vmag == 0 ? 0.0 : dot / vmag;
  p.jerk = std::sqrt(d.j[0] * d.j[0] + d.j[1] * d.j[1] + d.j[2] * d.j[2]);
  return p;
}

constexpr double kInfinite = std::numeric_limits<double>::infinity();

// While accumulating, the path maxima are held squared (one square root per new maximum rather
// than three per sample); finished() takes the roots.
void accumulate(KinematicsSummary& s, std::size_t i, const Derivatives& d) {
  const double v2 = d.v[0] * d.v[0] + d.v[1] * d.v[1] + d.v[2] * d.v[2];
  const double a2 = d.a[0] * d.a[0] + d.a[1] * d.a[1] + d.a[2] * d.a[2];
  const double j2 = d.j[0] * d.j[0] + d.j[1] * d.j[1] + d.j[2] * d.j[2];
  ++s.samples;
  // Non-finite values never become maxima: NaN compares false, and an infinite one (a position
  // of inf or 1e300 in a dump) is left out as the docs say, not reported as the maximum.
  if (v2 > s.maxSpeed && v2 < kInfinite) {
    s.maxSpeed = v2;
    s.maxSpeedIndex = i;
  }
  if (a2 > s.maxAccel && a2 < kInfinite) {
    s.maxAccel = a2;
    s.maxAccelIndex = i;
  }
  if (j2 > s.maxJerk && j2 < kInfinite) {
    s.maxJerk = j2;
    s.maxJerkIndex = i;
  }
  for (int ax = 0; ax < 3; ++ax) {
    KinematicsMaxima& m = s.axis[ax];
    const double v = std::fabs(d.v[ax]), a = std::fabs(d.a[ax]), j = std::fabs(d.j[ax]);
    if (v > m.speed && v < kInfinite) m.speed = v;
    if (a > m.accel && a < kInfinite) m.accel = a;
    if (j > m.jerk && j < kInfinite) m.jerk = j;
  }
  s.finiteSamples += static_cast<std::size_t>((v2 - v2) + (a2 - a2) + (j2 - j2) == 0);
}

KinematicsSummary finished(KinematicsSummary s) {
  s.maxSpeed = std::sqrt(s.maxSpeed);
  s.maxAccel = std::sqrt(s.maxAccel);
  s.maxJerk = std::sqrt(s.maxJerk);
  return s;
}

// Calls f(j, derivatives of sample sampleOf(j)) for j = 0..count, from the whole arrays x, y, z
// (and t) of n samples.
template <class SampleOf, class F>
void forSamples(const double* x, const double* y, const double* z, const double* t, std::size_t n,
                double cycleSeconds, std::size_t count, SampleOf&& sampleOf, F&& f) {
  const double* axes[3] = {x, y, z};
  const auto P = [&](std::size_t k, int ax) { return axes[ax][k]; };
  Derivatives d;
  if (t == nullptr) {
    const RegularGrid grid = RegularGrid::of(cycleSeconds);
    for (std::size_t j = 0; j < count; ++j) {
      grid.derive(sampleOf(j), n, P, d);
      f(j, d);
    }
  } else {
    const auto H = [t](std::size_t k) { return t[k + 1] - t[k]; };
    for (std::size_t j = 0; j < count; ++j) {
      deriveDivided(sampleOf(j), n, P, H, d);
      f(j, d);
    }
  }
}

// Calls f(i, derivatives) for every sample.
template <class F>
void forEachSample(const double* x, const double* y, const double* z, const double* t, std::size_t n,
                   double cycleSeconds, F&& f) {
  forSamples(x, y, z, t, n, cycleSeconds, n, [](std::size_t i) { return i; }, f);
}

Kinematics sizedKinematics(std::size_t n, bool perAxis) {
  Kinematics k;
  k.speed.resize(n);
  k.accel.resize(n);
  k.accelMagnitude.resize(n);
  k.jerk.resize(n);
  if (perAxis) {
    for (int ax = 0; ax < 3; ++ax) {
      k.axisVel[ax].resize(n);
      k.axisAcc[ax].resize(n);
      k.axisJerk[ax].resize(n);
    }
  }
  return k;
}

void store(Kinematics& k, std::size_t i, const Derivatives& d, bool perAxis) {
  const PathValues p = pathValues(d);
  k.speed[i] = p.speed;
  k.accel[i] = p.accel;
  k.accelMagnitude[i] = p.accelMagnitude;
  k.jerk[i] = p.jerk;
  if (perAxis) {
    for (int ax = 0; ax < 3; ++ax) {
      k.axisVel[ax][i] = d.v[ax];
      k.axisAcc[ax][i] = d.a[ax];
      k.axisJerk[ax][i] = d.j[ax];
    }
  }
}

}  // namespace

Kinematics deriveKinematicsAt(const double* x, const double* y, const double* z, const double* t, std::size_t n,
                              double cycleSeconds, const std::uint32_t* at, std::size_t count, bool perAxis) {
  Kinematics k = sizedKinematics(count, perAxis);
  forSamples(x, y, z, t, n, cycleSeconds, count, [at](std::size_t j) { return std::size_t(at[j]); },
             [&](std::size_t j, const Derivatives& d) { store(k, j, d, perAxis); });
  return k;
}

Kinematics deriveKinematics(const double* x, const double* y, const double* z, const double* t, std::size_t n,
                            double cycleSeconds, bool perAxis) {
  Kinematics k = sizedKinematics(n, perAxis);
  forEachSample(x, y, z, t, n, cycleSeconds, [&](std::size_t i, const Derivatives& d) { store(k, i, d, perAxis); });
  return k;
}

KinematicsSummary summarizeKinematics(const double* x, const double* y, const double* z, const double* t,
                                      std::size_t n, double cycleSeconds) {
  KinematicsSummary s;
  forEachSample(x, y, z, t, n, cycleSeconds, [&](std::size_t i, const Derivatives& d) { accumulate(s, i, d); });
  return finished(s);
}

KinematicsAccumulator::KinematicsAccumulator(double cycleSeconds, bool withTime)
    : withTime_(withTime) {
  const RegularGrid g = RegularGrid::of(cycleSeconds);
  grid_[0] = g.halfInvT;
  grid_[1] = g.invT2;
  grid_[2] = g.invT3;
  grid_[3] = g.halfInvT3;
  grid_[4] = g.invT;
}

void KinematicsAccumulator::push(double x, double y, double z, double t) {
  double* p = p_[count_ & 7];
  p[0] = x;
  p[1] = y;
  p[2] = z;
  t_[count_ & 7] = t;
  ++count_;
  // Sample i needs samples up to i + 3; until the end is known, evaluate as if it were here.
  if (count_ >= 4) evaluate(count_ - 4, count_);
}

void KinematicsAccumulator::evaluate(std::size_t i, std::size_t n) {
  const auto P = [this](std::size_t k, int ax) { return p_[k & 7][ax]; };
  Derivatives d;
  if (withTime_) {
    const auto H = [this](std::size_t k) { return t_[(k + 1) & 7] - t_[k & 7]; };
    deriveDivided(i, n, P, H, d);
  } else {
    RegularGrid{grid_[0], grid_[1], grid_[2], grid_[3], grid_[4]}.derive(i, n, P, d);
  }
  accumulate(summary_, i, d);
}

KinematicsSummary KinematicsAccumulator::finish() {
  if (!finished_) {
    finished_ = true;
    for (std::size_t i = count_ >= 4 ? count_ - 3 : 0; i < count_; ++i) evaluate(i, count_);
    summary_ = finished(summary_);
  }
  return summary_;
}

}  // namespace isurface
