#pragma once
// Checks on simulated motion that do not trust the simulator: per-axis velocity, acceleration
// and jerk from finite differences of the written positions, and the distance of every
// commanded sample from the programmed geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

#include "isurface/nc/interpolator.h"
#include "isurface/gcode/path_segment.h"

namespace isurface::test {

struct MotionExtremes {
  double velocityRatio = 0;      // max over samples and axes of |v| / limit
  double accelerationRatio = 0;  // |a| / limit
  double jerkRatio = 0;          // |j| / limit (0 when the machine has no jerk limit)
  double maxSpeed = 0;           // mm/s, path
  double maxDeviation = 0;       // mm, commanded sample to programmed geometry
  bool blocksInOrder = true;     // block indices never go back
  bool linesInOrder = true;      // every sample carries the line of its move
  std::uint64_t samples = 0;
  double duration = 0;           // s
};

// Distance from p to one move's geometry. On an arc the nearest point is searched from the
// point at p's own angle (every turn of it) and both ends, then refined by golden section,
// which also covers helices and spirals.
inline double distanceToSegment(const PathSegment& seg, const Vec3& p) {
  if (!seg.arc) {
    const Vec3 d = seg.end - seg.start;
    const double l2 = d.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - seg.start).dot(d) / l2, 0.0, 1.0) : 0.0;
    return (seg.start + t * d - p).norm();
  }
  const ArcGeometry& g = seg.arcGeometry;
  const double sweep = std::abs(g.sweep);
  if (sweep < 1e-12) return (seg.start - p).norm();
  auto dist = [&](double f) { return (g.at(std::clamp(f, 0.0, 1.0)) - p).norm(); };
  const double pi2 = 6.283185307179586;
  double angle = std::atan2(p[g.axes.v] - g.centre[g.axes.v], p[g.axes.u] - g.centre[g.axes.u]) - g.startAngle;
  if (g.sweep < 0) angle = -angle;
  angle = std::fmod(std::fmod(angle, pi2) + pi2, pi2);
  std::vector<double> candidates = {0.0, 1.0};
  for (double a = angle; a <= sweep + pi2; a += pi2) candidates.push_back(a / sweep);
  for (double a = angle - pi2; a >= -pi2; a -= pi2) candidates.push_back(a / sweep);
  double best = std::numeric_limits<double>::infinity();
  const double bracket = 0.3 / sweep;  // about 17 degrees either side
  for (double c : candidates) {
    double lo = std::max(0.0, c - bracket), hi = std::min(1.0, c + bracket);
    if (lo > hi) continue;
    for (int i = 0; i < 32; ++i) {
      const double m1 = lo + 0.382 * (hi - lo), m2 = lo + 0.618 * (hi - lo);
      if (dist(m1) < dist(m2)) hi = m2;
      else lo = m1;
    }
    best = std::min({best, dist(0.5 * (lo + hi)), dist(c)});
  }
  return best;
}

class MotionChecker : public SampleSink {
 public:
  // `window`: how many samples either side may have been mixed by the filters.
  MotionChecker(const Program& program, const Machine& machine, int window, bool checkGeometry = true)
      : program_(program), machine_(machine), window_(static_cast<std::size_t>(window)), checkGeometry_(checkGeometry) {}

  void consume(const SimSample* s, std::size_t n) override {
    for (std::size_t i = 0; i < n; ++i) add(s[i]);
  }

  MotionExtremes finish() {
    while (next_ < pending_.size()) checkAt(next_++);
    r_.duration = r_.samples > 0 ? (r_.samples - 1) * machine_.cycle : 0;
    return r_;
  }

 private:
  void add(const SimSample& s) {
    const Vec3 p(s.x, s.y, s.z);
    history_.push_back(p);
    if (history_.size() > 4) history_.pop_front();
    const double T = machine_.cycle;
    const std::size_t h = history_.size();
    if (h >= 2) {
      const Vec3 v = (history_[h - 1] - history_[h - 2]) / T;
      r_.maxSpeed = std::max(r_.maxSpeed, v.norm());
      for (int a = 0; a < 3; ++a)
        r_.velocityRatio = std::max(r_.velocityRatio, std::abs(v[a]) / machine_.axes[a].maxVelocity);
    }
    if (h >= 3) {
      const Vec3 acc = (history_[h - 1] - 2 * history_[h - 2] + history_[h - 3]) / (T * T);
      for (int a = 0; a < 3; ++a)
        r_.accelerationRatio = std::max(r_.accelerationRatio, std::abs(acc[a]) / machine_.axes[a].maxAcceleration);
    }
    if (h >= 4 && machine_.jerkLimited()) {
      const Vec3 j = (history_[3] - 3 * history_[2] + 3 * history_[1] - history_[0]) / (T * T * T);
      for (int a = 0; a < 3; ++a)
        r_.jerkRatio = std::max(r_.jerkRatio, std::abs(j[a]) / machine_.axes[a].maxJerk);
    }
    if (r_.samples > 0 && s.block < lastBlock_) r_.blocksInOrder = false;
    if (s.block >= program_.moves.size() || program_.moves[s.block].line != s.line) r_.linesInOrder = false;
    lastBlock_ = s.block;
    ++r_.samples;
    if (checkGeometry_) {
      pending_.push_back(s);
      if (pending_.size() > 2 * window_ + 1) {
        pending_.pop_front();
        if (next_ > 0) --next_;
      }
      while (next_ + window_ < pending_.size()) checkAt(next_++);
    }
  }

  // Checks one sample against every move seen in the window around it.
  void checkAt(std::size_t index) {
    std::uint32_t lo = pending_.front().block, hi = lo;
    for (const SimSample& q : pending_) {
      lo = std::min(lo, q.block);
      hi = std::max(hi, q.block);
    }
    const SimSample& s = pending_[index];
    const Vec3 p(s.x, s.y, s.z);
    double best = std::numeric_limits<double>::infinity();
    for (std::uint32_t b = lo; b <= hi && b < program_.moves.size(); ++b) {
      if (!program_.moves[b].isMotion()) continue;
      const PathSegment seg = PathSegment::from(program_, b);
      best = std::min(best, seg.length > 0 ? distanceToSegment(seg, p) : (seg.end - p).norm());
    }
    if (std::isfinite(best)) r_.maxDeviation = std::max(r_.maxDeviation, best);
  }

  const Program& program_;
  const Machine& machine_;
  std::size_t window_;
  bool checkGeometry_;
  std::deque<Vec3> history_;
  std::deque<SimSample> pending_;
  std::uint32_t lastBlock_ = 0;
  std::size_t next_ = 0;  // first sample in pending_ not yet checked
  MotionExtremes r_;
};

// Limits hold within this factor: finite differences of filtered samples see a little more than
// the continuous signal they sample.
constexpr double kLimitTolerance = 1.05;

inline void expectWithinLimits(const MotionExtremes& r, const Machine& m) {
  EXPECT_LE(r.velocityRatio, kLimitTolerance);
  EXPECT_LE(r.accelerationRatio, kLimitTolerance);
  if (m.jerkLimited()) {
    EXPECT_LE(r.jerkRatio, kLimitTolerance);
  }
  EXPECT_LE(r.maxDeviation, m.chordTolerance * kLimitTolerance);
  EXPECT_TRUE(r.blocksInOrder);
  EXPECT_TRUE(r.linesInOrder);
}

}  // namespace isurface::test
