#pragma once
// Synthetic interpolation samples for the pass, mesh and quantity tests: tool paths sampled at
// a constant speed per move, exactly on their geometry, and simulated G-code programs.
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/base/units.h"
#include "isurface/machine/machine.h"
#include "isurface/surface/passes.h"
#include "isurface/nc/simulator.h"
#include "isurface/surface/surface_mesh.h"
#include "isurface/base/trajectory.h"
#include "isurface/nc/sample_trajectory.h"

namespace isurface::test {


// Samples a path move by move at the cycle: each move at its own speed (mm/min).
class PathSampler {
 public:
  explicit PathSampler(const Vec3& start, double cycle = 0.001) : at_(start), cycle_(cycle) {
    t_.cycle = cycle;
    t_.source = "synthetic";
    push(start, 0, 0);
  }

  // A straight move; `feed` is stored in the feed channel when withFeed() was asked for.
  PathSampler& lineTo(const Vec3& end, double speed, double feed = -1) {
    const Vec3 d = end - at_;
    const double length = d.norm();
    const double duration = length / (speed / 60.0);  // s
    // Samples fall every cycle in time, whatever the speed of the move they fall in.
    double tau = cycle_ - sinceLast_;
    for (; tau <= duration; tau += cycle_) push(at_ + d * (tau / duration), feed < 0 ? speed : feed, line_);
    sinceLast_ = duration - (tau - cycle_);
    at_ = end;
    return *this;
  }
  // A counter-clockwise (turn > 0) or clockwise arc about `centre` in the XY plane, radius
  // changing linearly to `endRadius` (a spiral) and z to `endZ`.
  PathSampler& arc(const Vec3& centre, double turn, double endRadius, double endZ, double speed) {
    const double r0 = std::hypot(at_.x() - centre.x(), at_.y() - centre.y());
    const double a0 = std::atan2(at_.y() - centre.y(), at_.x() - centre.x());
    const double z0 = at_.z();
    const int pieces = std::max(8, static_cast<int>(std::fabs(turn) * std::max(r0, endRadius) / 0.01));
    for (int k = 1; k <= pieces; ++k) {
      const double f = double(k) / pieces;
      const double r = r0 + (endRadius - r0) * f, a = a0 + turn * f;
      lineTo(Vec3(centre.x() + r * std::cos(a), centre.y() + r * std::sin(a), z0 + (endZ - z0) * f), speed);
    }
    return *this;
  }
  PathSampler& line(std::uint32_t l) {
    line_ = l;
    return *this;
  }
  PathSampler& withFeed() {
    feed_ = true;
    return *this;
  }
  PathSampler& withFeedback(const std::function<Vec3(const Vec3&)>& offset) {
    feedback_ = offset;
    return *this;
  }
  const Vec3& position() const { return at_; }
  std::size_t size() const { return t_.x.size(); }

  Trajectory take() {
    Trajectory out = std::move(t_);
    if (!feed_) out.feed.clear();
    if (feedback_) {
      const std::size_t n = out.x.size();
      for (std::vector<float>* offset : {&out.fbOffsetX, &out.fbOffsetY, &out.fbOffsetZ}) offset->resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 p = out.commanded(i);
        out.setFeedback(i, p + feedback_(p));
      }
    }
    return out;
  }

 private:
  void push(const Vec3& p, double feed, std::uint32_t l) {
    t_.time.push_back(double(t_.x.size()) * cycle_);
    t_.x.push_back(p.x());
    t_.y.push_back(p.y());
    t_.z.push_back(p.z());
    t_.line.push_back(l);
    t_.feed.push_back(feed);
    if (l != 0) t_.hasLine = true;
  }

  Trajectory t_;
  Vec3 at_;
  double cycle_;
  double sinceLast_ = 0;  // s since the last sample
  std::uint32_t line_ = 0;
  bool feed_ = false;
  std::function<Vec3(const Vec3&)> feedback_;
};

// A zig-zag raster over [0, length] x [0, (passes - 1) * step] at height z(x, y), joined by
// step-overs along Y; `points` cutter locations per pass.
inline Trajectory zigZagRaster(int passes, double length, double step, double speed,
                               const std::function<double(double, double)>& z = {}, int points = 2) {
  const auto height = [&](double x, double y) { return z ? z(x, y) : 0.0; };
  PathSampler path(Vec3(0, 0, height(0, 0)));
  for (int k = 0; k < passes; ++k) {
    const double y = k * step;
    if (k > 0) path.lineTo(Vec3(path.position().x(), y, height(path.position().x(), y)), speed);
    for (int i = 1; i < points; ++i) {
      const double f = double(i) / (points - 1);
      const double x = k % 2 == 0 ? f * length : length - f * length;
      path.lineTo(Vec3(x, y, height(x, y)), speed);
    }
  }
  return path.take();
}

// Concentric circles about the origin from outerRadius inwards, each closed, joined by a
// radial step (counter-clockwise, starting on +X).
inline Trajectory concentricLoops(int loops, double outerRadius, double step, double speed) {
  PathSampler path(Vec3(outerRadius, 0, 0));
  for (int k = 0; k < loops; ++k) {
    const double r = outerRadius - k * step;
    if (k > 0) path.lineTo(Vec3(r, 0, 0), speed);
    path.arc(Vec3::Zero(), 2 * kPi, r, 0, speed);
  }
  return path.take();
}

// A G-code program interpreted and simulated on the default machine, in memory.
struct Simulated {
  Program program;
  Trajectory samples;
};

inline Simulated simulateGcode(const std::string& text, const std::string& name = "test.nc") {
  Simulated out;
  InterpretResult r = interpretGcode(text, name);
  if (!r.ok()) throw std::runtime_error("test program does not interpret: " + r.errors.front().str());
  out.program = std::move(r.program);
  const Machine machine = defaultMachine();
  SampleBuffer buffer;
  simulate(out.program, machine, buffer);
  out.samples = trajectoryFromSamples(buffer.data, machine.cycle, name);
  out.samples.rapidFeed = machine.rapidVelocity * 60.0;
  return out;
}

// mm of path of samples [p.begin, p.end).
inline double pathLengthOf(const Trajectory& s, const Pass& p) {
  double length = 0;
  for (std::size_t i = p.begin; i + 1 < p.end; ++i) {
    const double d = (s.commanded(i + 1) - s.commanded(i)).norm();
    if (std::isfinite(d)) length += d;
  }
  return length;
}

// Edges used by one triangle only, as vertex pairs (smaller first).
inline std::vector<std::pair<std::uint32_t, std::uint32_t>> boundaryEdges(const SurfaceMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = t[e], b = t[(e + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const auto& [edge, count] : uses)
    if (count == 1) out.push_back(edge);
  return out;
}

}  // namespace isurface::test
