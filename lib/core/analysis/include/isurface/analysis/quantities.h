#pragma once
// What a quality map can be coloured by: motion parameters per sample, and the two scalars on
// the surface (adjacent-pass inconsistency, predicted deviation).
// Values are in the unit each is shown in (QuantityInfo::unit: mm/min for speeds, um for
// deviations): the one place where internal units (mm, s, mm/s) become display units.
#include <optional>
#include <string>
#include <vector>

#include "isurface/surface/surface_mesh.h"

namespace isurface {

enum class Quantity {
  Speed,               // mm/min, path
  Acceleration,        // mm/s^2, tangential (signed)
  AccelerationMagnitude, // mm/s^2, |a|
  Jerk,                // mm/s^3, |j|
  VelocityX, VelocityY, VelocityZ,          // mm/min
  AccelerationX, AccelerationY, AccelerationZ,  // mm/s^2
  JerkX, JerkY, JerkZ, // mm/s^3
  FollowingError,      // um, |commanded - feedback|
  Line,                // G-code line
  Time,                // s
  Feed,                // mm/min, programmed
  SpeedInconsistency,  // mm/min, |speed - speed of the nearest sample on a neighbouring pass|, the larger of both sides
  AccelerationInconsistency, // mm/s^2, the same for tangential acceleration
  Deviation,           // um, feedback surface from the commanded one along the commanded normal (signed, + outwards)
  // A five-axis run's joints (its joint_x ... joint_c channels): the machine's slides as they move
  // through the rotary table or head, and its rotary axes.
  JointSpeed,          // mm/min, |v| of the X Y Z joints together
  JointVelocityX, JointVelocityY, JointVelocityZ,           // mm/min
  JointAccelerationX, JointAccelerationY, JointAccelerationZ, // mm/s^2
  JointJerkX, JointJerkY, JointJerkZ,                       // mm/s^3
  JointVelocityA, JointVelocityB, JointVelocityC,           // deg/s
  JointAccelerationA, JointAccelerationB, JointAccelerationC, // deg/s^2
  JointJerkA, JointJerkB, JointJerkC,                       // deg/s^3
};

struct QuantityInfo {
  Quantity quantity;
  const char* name;   // command-line name: "speed", "accel", "jerk", "vx", ..., "deviation"
  const char* label;  // "Path speed"
  const char* unit;   // "mm/min"
  bool needsFeedback; // following error, deviation
  bool onSurface;     // needs the mesh (inconsistencies, deviation)
  bool needsJoints = false;  // a five-axis run's joint channels
};

// Whether the samples have what the quantity needs to be offered (feedback, joint channels).
bool quantityAvailable(Quantity q, const Trajectory& samples);

const std::vector<QuantityInfo>& quantityInfos();
const QuantityInfo& quantityInfo(Quantity q);
// Whether values of both signs are usual (a component, a tangential acceleration, a deviation):
// such a quantity reads best on a diverging colour map centred on zero.
bool isSignedQuantity(Quantity q);
std::optional<Quantity> parseQuantity(const std::string& name);

// Values per sample (Quantity::onSurface == false). Throws InputError when the samples lack
// what the quantity needs (e.g. no feedback channels).
std::vector<double> sampleQuantity(Quantity q, const Trajectory& samples);
// Several of them, each as sampleQuantity gives it: the motion is derived once for all.
std::vector<std::vector<double>> sampleQuantities(const std::vector<Quantity>& qs, const Trajectory& samples);
// The same values for samples [first, last) only (clamped to the samples), into `out`: what a
// view of part of a long run needs, without the whole run's values in memory.
void sampleQuantityRange(Quantity q, const Trajectory& samples, std::size_t first, std::size_t last, float* out);

// Values per mesh vertex, for any quantity. Motion parameters are derived only around the
// vertices' samples (memory in proportion to the vertices). Inconsistencies are 0 on vertices
// with no matched neighbour; non-finite values stay NaN (so does the deviation of a vertex
// without a normal).
std::vector<float> vertexQuantity(Quantity q, const Trajectory& samples, const SurfaceMesh& mesh);

// Any other channel of the dump (Trajectory::extra) per vertex; nullopt when there is none by
// that name. Its unit is the dump's.
std::optional<std::vector<float>> vertexExtraChannel(const Trajectory& samples, const SurfaceMesh& mesh,
                                                     const std::string& name);

}  // namespace isurface
