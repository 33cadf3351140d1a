#pragma once
// The motion of LinuxCNC 2.9's trajectory planner, cycle by cycle, for a machine whose control
// is `linuxcnc-2.9`: its naive-CAM joining of short lines (G64 Q), blend arcs within G64 P,
// parabolic and tangent junctions, exact path (G61) and exact stop (G61.1), the look-ahead over
// 50 segments and the per-cycle trapezoid with split cycles. No jerk limit: version 2.9 has
// none. What it leaves out, and why, is in docs/controls.md. On a machine with rotary axes, as
// 2.9 with tool-centre-point kinematics: X Y Z (the tip) and A B C planned together, the joints
// the kinematics' inverse of every cycle (docs/five-axis.md).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "isurface/base/diagnostic.h"

#include "isurface/gcode/program.h"
#include "isurface/nc/interpolator.h"

namespace isurface {

class LinuxCncMotion {
 public:
  // `start`: the position before the first move, mm. The machine and the sink must outlive it.
  LinuxCncMotion(const Machine& machine, const Vec3& start, SampleSink& sink);
  ~LinuxCncMotion();
  LinuxCncMotion(const LinuxCncMotion&) = delete;
  LinuxCncMotion& operator=(const LinuxCncMotion&) = delete;

  // G64's tolerances from move `blending.firstMove` on (told before that move is added).
  void blendingChanged(const PathBlending& blending);
  // The program's move `index`, which starts at `start`; samples every cycle that no later
  // move can change.
  void add(std::uint64_t index, const Move& move, const Vec3& start);
  // The same with the program's A B C (deg) at the move's end; only on a machine with rotary
  // axes (Machine::kinematics), whose samples then carry the tool tip and the joints.
  void add(std::uint64_t index, const Move& move, const Vec3& start, const Vec3& rotaryEnd);
  // No more moves: the rest of the motion.
  InterpolationSummary finish();

  double pathLength() const;          // mm, of the moves with motion
  // On a machine with rotary axes: each joint that passed its velocity or acceleration limit,
  // with the lines (2.9 does not keep its joints within them under tool-centre-point control).
  std::vector<Diagnostic> jointLimitWarnings(const std::string& source) const;
  std::size_t segments() const;       // moves with motion
  double plannedSeconds() const;      // s, of the samples made so far

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace isurface
