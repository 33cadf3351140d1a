#pragma once
// One segment of LinuxCNC 2.9's motion queue: a line (possibly several program lines joined by
// its naive-CAM detector), an arc or helix, or a blend arc it inserted at a corner, with the
// planning state its trajectory planner keeps per segment. Units: mm, s.
#include <cstdint>

#include "isurface/gcode/arc.h"
#include "isurface/machine/machine.h"

namespace isurface::linuxcnc {

enum class Term : std::uint8_t { Stop, Exact, Parabolic, Tangent };
enum class Shape : std::uint8_t { Line, Arc, Blend };

// The fraction of acceleration an arc may spend along its path; the rest is kept for the
// centripetal part (LinuxCNC's BLEND_ACC_RATIO_TANGENTIAL and _NORMAL).
constexpr double kTangentialShare = 0.5;
constexpr double kNormalShare = 0.8660254037844386;

// The program move a segment's samples are reported under: LinuxCNC reports lines it joined
// under the last, and a blend arc under the line after it.
struct SegmentPart {
  std::uint32_t block;
  std::uint32_t line;
  float feed;
};

struct Segment {
  Shape shape = Shape::Line;
  // Line: start..end. Arc: `arc`. Blend: a straight lead of `lead` mm from `start` along
  // `direction`, then LinuxCNC's spherical arc about `centre` from `centre + rStart` to
  // `centre + rEnd` over `angle` rad, run at `radius` (|rStart|) mm per rad.
  Vec3 start = Vec3::Zero(), end = Vec3::Zero(), direction = Vec3::Zero();
  ArcGeometry arc;
  Vec3 centre = Vec3::Zero(), rStart = Vec3::Zero(), rEnd = Vec3::Zero();
  double radius = 0, angle = 0, lead = 0;
  // deg, the program's A B C at both ends, turned in proportion to the progress (LinuxCNC's
  // PmLine9 and PmCircle9); equal on a blend, which LinuxCNC never makes where they turn.
  Vec3 rotaryStart = Vec3::Zero(), rotaryEnd = Vec3::Zero();

  double target = 0;         // mm, length
  double nominalLength = 0;  // mm, before blends trimmed it
  double progress = 0;       // mm
  double requested = 0;      // mm/s, the feed (the axis-limited speed for rapids)
  double maxVelocity = 0;    // mm/s
  double maxAcceleration = 0;// mm/s^2
  double tolerance = 0;      // mm, G64 P (0: none)
  double finalVelocity = 0;  // mm/s, set by the look-ahead
  double velocity = 0;       // mm/s, now
  double kinkVelocity = -1;  // mm/s, < 0: none
  double kinkReduction = 0, kinkReductionBefore = 0;  // share of acceleration kept for a kink
  double blendVelocity = 0, terminalVelocity = 0;  // mm/s
  double cycle = 0;          // s, of this segment's next update (shorter in a split cycle)
  Term term = Term::Parabolic;
  bool traverse = false;     // a rapid
  bool blendBefore = false;  // a parabolic blend with the previous segment
  bool finalized = false, active = false, splitting = false, remove = false;
  bool blendingNext = false, onFinalDeceleration = false, ramp = false, atPeak = false;
  SegmentPart part{};

  bool curved() const { return shape != Shape::Line; }
  // A, B or C turn on it (LinuxCNC's tcRotaryMotionCheck).
  bool rotates() const { return rotaryStart != rotaryEnd; }
  Vec3 pointAt(double s) const;   // s in mm along the segment, 0..target
  Vec3 rotaryAt(double s) const;  // deg
  Vec3 startTangent() const;
  Vec3 endTangent() const;
};

// LinuxCNC's accelerations of a segment: the whole (less what kinks keep, halved in a
// parabolic blend) and along the path (an arc's share of it).
double overallAcceleration(const Segment& s);
double tangentialAcceleration(const Segment& s);

// The speed and acceleration a straight move in direction `d` (unit) may have: the tightest
// axis's limit projected on the path (the machine's axis limits, as LinuxCNC's canon does).
double lineVelocityLimit(const Machine& m, const Vec3& d);
double lineAccelerationLimit(const Machine& m, const Vec3& d);

// The largest value of an axis box on the plane with unit normal `n` (a speed or an
// acceleration any direction in the plane may take).
double inscribedInPlane(const Vec3& n, const Vec3& bounds);

}  // namespace isurface::linuxcnc
