#pragma once
// Five-axis machine kinematics: where the joints (three linear slides and two rotary axes) put the
// tool tip in the workpiece frame, and back. Rotary axes turn the table (carrying the part) or
// the head (carrying the tool); the outer axis carries the inner one. Lengths in mm, angles in
// degrees, positive turns right-handed about each axis's direction.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "isurface/base/geometry.h"

namespace isurface {

enum class KinematicStructure {
  TableTable,  // both rotary axes in the table: the outer tilts, the inner carries the part
  HeadHead,    // both in the spindle head: the outer carries the inner, which carries the tool
  HeadTable,   // the first axis in the head, the second in the table
};

struct RotaryAxis {
  char name = 'C';                    // the program's word: 'A', 'B' or 'C'
  Vec3 direction = Vec3::UnitZ();     // unit; a turn of +1 deg is right-handed about it
  Vec3 pivot = Vec3::Zero();          // mm, a point of the axis with every rotary axis at 0
  double minimum = -360, maximum = 360;  // deg
  bool wraps = false;                 // a rotary table without end: positions modulo 360, the shortest way
  double maxVelocity = 0, maxAcceleration = 0, maxJerk = 0;  // deg/s, deg/s^2, deg/s^3 (0: no limit)
};

// The two rotary axes in order: for TableTable and HeadHead the outer (carrying) axis first;
// for HeadTable the head's axis first, the table's second.
struct FiveAxisKinematics {
  KinematicStructure structure = KinematicStructure::TableTable;
  std::array<RotaryAxis, 2> rotary;
  // mm from the tip to the point the linear joints position (the spindle's gauge line), along
  // the tool axis; the tool points along machine -Z with the head's axes at 0.
  double toolLength = 0;
  // Tool-centre-point control: the program's X Y Z are the tool tip in the workpiece frame (the
  // control moves the joints through the kinematics). Off, they are the linear joints themselves,
  // and the tip goes where the rotary axes carry it.
  bool toolCentrePoint = true;
};

struct JointPosition {
  Vec3 linear = Vec3::Zero();               // mm, machine X Y Z of the gauge line
  std::array<double, 2> rotary = {0, 0};    // deg, in FiveAxisKinematics::rotary order
};

struct TipPose {
  Vec3 tip = Vec3::Zero();                  // mm, the tool tip in the workpiece frame
  std::array<double, 2> rotary = {0, 0};    // deg
};

// Inverse kinematics with tool-centre-point control: the joints that put the tip where the pose
// says, with the rotary axes at its angles.
JointPosition jointsFor(const FiveAxisKinematics& k, const TipPose& pose);
// Forward kinematics: where the joints put the tip, in the workpiece frame.
TipPose tipOf(const FiveAxisKinematics& k, const JointPosition& joints);
// The tool axis (unit, from the tip towards the spindle) in the workpiece frame at these angles.
Vec3 toolAxis(const FiveAxisKinematics& k, const std::array<double, 2>& rotary);

// The rotary angles (deg) that turn the tool axis to `axis` (workpiece frame, any length): none,
// one or two solutions (each angle in (-180, 180]); every angle of the axis that loses its effect
// at a singular orientation gives the same axis, and 0 is returned for it.
std::vector<std::array<double, 2>> rotaryFor(const FiveAxisKinematics& k, const Vec3& axis);

// Where a rotary axis stops turning the tool relative to the part (the tool axis along it): near
// there a small change of tool axis asks for a large turn of that axis.
struct Singularity {
  char axis = 'C';          // the axis that loses its effect
  double distance = 0;      // deg between the tool axis and the singular orientation
  std::string description;  // for a user: which axis and what it means
};
// The singularity within `withinDeg` of these angles, if any.
std::optional<Singularity> singularityNear(const FiveAxisKinematics& k, const std::array<double, 2>& rotary,
                                           double withinDeg);

// The angle `target` (deg) as a wrapping axis reaches it from `from` the shortest way: target
// plus the whole turns that bring it within 180 deg of `from` (a half turn goes positive).
double shortestWay(double from, double target);

}  // namespace isurface
