#pragma once
// The machine description a simulation runs against: interpolation cycle, per-axis limits and
// servo gains, path tolerance. Read from JSON (resources/machines/default.json documents it).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/kinematics/five_axis.h"
#include "isurface/machine/tool_table.h"

namespace isurface {

struct AxisLimits {
  double maxVelocity = 400;       // mm/s
  double maxAcceleration = 2000;  // mm/s^2
  double maxJerk = 100000;        // mm/s^3; 0 = not limited
  double positionGain = 40;       // 1/s, proportional position loop
  double velocityFeedForward = 0.95;       // 0..1
  double velocityLoopTimeConstant = 0.002; // s, first-order lag of the velocity loop
};

// Whose trajectory planning a simulation follows: the generic look-ahead planner, or LinuxCNC
// 2.9's (its blends, naive-CAM merging and per-cycle trapezoids; docs/controls.md).
enum class TrajectoryPlanner : unsigned char { Generic, LinuxCnc29 };

// How the control reads G-code and plans motion: the dialect, the units it is in before a
// program says, and its trajectory planner.
struct ControlModes {
  TrajectoryPlanner planner = TrajectoryPlanner::Generic;
  // s, how long the control takes to build up an axis's full acceleration at its jerk limit: the
  // time its jerk filter spreads a change of acceleration over (Fanuc's time constant after
  // interpolation, Siemens' jerk filter time). A setting of the control, not of the axes: lowering
  // an acceleration leaves it as it is. A description that does not give it gets the largest a / j
  // of its own axes; 0 without a jerk limit.
  double accelerationRiseTime = 0;
  // The generic control smooths the path within its tolerance before interpolating, as modern
  // controls' compressors do: corner blends between chords without a jerk limit, a curve through
  // runs of chords with one. Off: each chord is planned as programmed and its junctions braked
  // for, as a control without a compressor (the paper's NC system) runs them.
  bool chordSmoothing = true;
  bool fanuc = false;  // Fanuc and Haas (else RS274/NGC as LinuxCNC reads it)
  bool inch = false;   // G20 at power-on
  Plane plane = Plane::XY;    // G17 at power-on
  bool incremental = false;   // G91 at power-on
  bool modesNamed = false;    // the description names the power-on plane or distance mode
  // Folders of subroutine and subprogram files ("subroutine_path", relative to the description);
  // a program's own folder is searched after them.
  std::vector<std::string> subroutinePath;
};

struct Machine {
  std::string name;
  double cycle = 0.001;           // s, interpolation period
  double rapidVelocity = 400;     // mm/s
  double chordTolerance = 0.01;   // mm, largest distance of a commanded sample from the program
  std::array<AxisLimits, 3> axes; // X, Y, Z
  Vec3 g28Position = Vec3::Zero();
  Vec3 g30Position = Vec3::Zero();
  ControlModes control;
  // Cutter radius compensation's tools ("tools" in the JSON: a LinuxCNC "table" file, relative
  // to the description, or "diameters" by tool number), and the units of a tool table: the
  // control's machine units.
  ToolDiameters toolDiameters;
  bool toolTableInch = false;
  // Five-axis machines: how the rotary axes carry the part or the tool (none: three axes).
  std::optional<FiveAxisKinematics> kinematics;
  // s; a simulated run longer than this is refused: its samples would fill the disk or memory
  // (100 h at 1 ms is 360 million samples). Not part of the description: a command's option.
  double longestRun = 100 * 3600.0;

  bool jerkLimited() const { return axes[0].maxJerk > 0 && axes[1].maxJerk > 0 && axes[2].maxJerk > 0; }
};

// s, the largest a / j of the machine's axes (0 without a jerk limit): the rise time a description
// that does not name one gets.
double largestRiseTime(const Machine& m);

// Parses a machine description. Units in the file are mm, s and mm/min for velocities (as on a
// control panel); every missing key takes the default's value. Throws InputError naming the
// file and the offending key for malformed JSON and impossible values (non-positive cycle,
// limits <= 0, gains out of range).
Machine parseMachine(const std::string& jsonText, const std::string& sourceName);
Machine loadMachine(const std::string& path);

// The machine as JSON that parseMachine() reads back to the same machine: the whole description
// (limits, servo, reference positions, control, tools as diameters in mm), indented for a file.
std::string machineDescriptionJson(const Machine& m);
// Only the name, cycle, rapid, tolerance and axes, on one line (what a dump's metadata keeps).
std::string machineLimitsJson(const Machine& m);

// The built-in default (the text of resources/machines/default.json, compiled in).
Machine defaultMachine();
const std::string& defaultMachineJson();

}  // namespace isurface
