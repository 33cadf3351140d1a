// Quantities to colour a quality map by: per sample, and per vertex of the surface.
#include "isurface/analysis/quantities.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "isurface/base/diagnostic.h"
#include "isurface/analysis/kinematics.h"
#include "isurface/base/units.h"

namespace isurface {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Samples derived per call of deriveKinematics: bounds the memory for any number of samples.
constexpr std::size_t kKinematicsChunk = std::size_t(1) << 16;
// The stencils reach two samples either way; three more on each side give every sample of a
// chunk exactly the values a derivation of the whole trajectory would.
constexpr std::size_t kStencilMargin = 3;

bool isKinematic(Quantity q) {
  switch (q) {
    case Quantity::Speed:
    case Quantity::Acceleration:
    case Quantity::AccelerationMagnitude:
    case Quantity::Jerk:
    case Quantity::VelocityX:
    case Quantity::VelocityY:
    case Quantity::VelocityZ:
    case Quantity::AccelerationX:
    case Quantity::AccelerationY:
    case Quantity::AccelerationZ:
    case Quantity::JerkX:
    case Quantity::JerkY:
    case Quantity::JerkZ: return true;
    default: return q >= Quantity::JointSpeed;
  }
}

bool isPerAxis(Quantity q) { return isKinematic(q) && q >= Quantity::VelocityX && q != Quantity::JointSpeed; }

// Which positions a motion quantity is derived from.
enum class Positions { Tip, LinearJoints, RotaryJoints };

Positions positionsOf(Quantity q) {
  if (q < Quantity::JointSpeed) return Positions::Tip;
  return q < Quantity::JointVelocityA ? Positions::LinearJoints : Positions::RotaryJoints;
}

// Three arrays of positions (mm or deg). A rotary joint the machine lacks reads another joint's
// channel: nothing derived from it is asked for (checkSampleQuantity refuses its quantities).
struct PositionArrays {
  const double* axis[3] = {nullptr, nullptr, nullptr};
};

PositionArrays positionArrays(Positions which, const Trajectory& s) {
  PositionArrays p;
  if (which == Positions::Tip) {
    p.axis[0] = s.x.data(), p.axis[1] = s.y.data(), p.axis[2] = s.z.data();
    return p;
  }
  const char* names[2][3] = {{"joint_x", "joint_y", "joint_z"}, {"joint_a", "joint_b", "joint_c"}};
  const int row = which == Positions::LinearJoints ? 0 : 1;
  bool any = false;
  for (int i = 0; i < 3; ++i) {
    const std::vector<double>* channel = s.extraChannel(names[row][i]);
    if (channel && channel->size() == s.size()) {
      p.axis[i] = channel->data();
      any = true;
    }
  }
  if (!any || (row == 0 && !(p.axis[0] && p.axis[1] && p.axis[2])))
    throw InputError(Diagnostic{s.source, 0, 0,
                                "the samples have no joints (joint_x ... joint_c channels): they come from a five-axis "
                                "machine's simulation (docs/five-axis.md)"});
  const double* present = p.axis[0] ? p.axis[0] : p.axis[1] ? p.axis[1] : p.axis[2];
  for (const double*& axis : p.axis)
    if (!axis) axis = present;
  return p;
}

int axisOf(Quantity q, Quantity first) { return static_cast<int>(q) - static_cast<int>(first); }

// 'a', 'b' or 'c': the rotary joint a rotary joint quantity is of.
char jointLetter(Quantity q) { return static_cast<char>('a' + axisOf(q, Quantity::JointVelocityA) % 3); }

// Speeds leave here in mm/min, the unit they are shown in (quantities are display values).
double kinematicValue(Quantity q, const Kinematics& k, std::size_t i) {
  switch (q) {
    case Quantity::Speed: return mmPerSToMmPerMin(k.speed[i]);
    case Quantity::Acceleration: return k.accel[i];
    case Quantity::AccelerationMagnitude: return k.accelMagnitude[i];
    case Quantity::Jerk: return k.jerk[i];
    case Quantity::VelocityX: return mmPerSToMmPerMin(k.axisVel[0][i]);
    case Quantity::VelocityY: return mmPerSToMmPerMin(k.axisVel[1][i]);
    case Quantity::VelocityZ: return mmPerSToMmPerMin(k.axisVel[2][i]);
    case Quantity::AccelerationX: return k.axisAcc[0][i];
    case Quantity::AccelerationY: return k.axisAcc[1][i];
    case Quantity::AccelerationZ: return k.axisAcc[2][i];
    case Quantity::JerkX: return k.axisJerk[0][i];
    case Quantity::JerkY: return k.axisJerk[1][i];
    case Quantity::JerkZ: return k.axisJerk[2][i];
    case Quantity::JointSpeed: return mmPerSToMmPerMin(k.speed[i]);
    default: break;
  }
  if (q >= Quantity::JointVelocityX && q <= Quantity::JointVelocityZ)
    return mmPerSToMmPerMin(k.axisVel[axisOf(q, Quantity::JointVelocityX)][i]);
  if (q >= Quantity::JointAccelerationX && q <= Quantity::JointAccelerationZ)
    return k.axisAcc[axisOf(q, Quantity::JointAccelerationX)][i];
  if (q >= Quantity::JointJerkX && q <= Quantity::JointJerkZ) return k.axisJerk[axisOf(q, Quantity::JointJerkX)][i];
  if (q >= Quantity::JointVelocityA && q <= Quantity::JointVelocityC) return k.axisVel[axisOf(q, Quantity::JointVelocityA)][i];
  if (q >= Quantity::JointAccelerationA && q <= Quantity::JointAccelerationC)
    return k.axisAcc[axisOf(q, Quantity::JointAccelerationA)][i];
  if (q >= Quantity::JointJerkA && q <= Quantity::JointJerkC) return k.axisJerk[axisOf(q, Quantity::JointJerkA)][i];
  switch (q) {
    default: return kNaN;
  }
}

// Derives the samples [first, last) (with their stencil margins) and calls
// take(sample, kinematics, index in kinematics) for each.
template <class Take>
void deriveRange(const Trajectory& s, const PositionArrays& p, bool perAxis, std::size_t first, std::size_t last,
                 Take&& take) {
  const std::size_t n = s.size();
  const std::size_t from = first >= kStencilMargin ? first - kStencilMargin : 0;
  const std::size_t to = std::min(n, last + kStencilMargin);
  const double* t = s.irregularTime ? s.time.data() + from : nullptr;
  const Kinematics k = deriveKinematics(p.axis[0] + from, p.axis[1] + from, p.axis[2] + from, t, to - from, s.cycle,
                                        perAxis);
  for (std::size_t i = first; i < last; ++i) take(i, k, i - from);
}

[[noreturn]] void missing(const Trajectory& s, const std::string& what) {
  throw InputError(Diagnostic{s.source, 0, 0, what});
}

void requireFeedback(const Trajectory& s, Quantity q) {
  if (!s.hasFeedback())
    missing(s, std::string(quantityInfo(q).label) + " needs feedback positions (fb_x, fb_y, fb_z), which the samples do not have");
}

// A channel the writer stored for a derived quantity (docs/biip-format.md names them and their
// units); used instead of deriving it again.
const std::vector<double>* storedChannel(Quantity q, const Trajectory& s) {
  static const std::pair<Quantity, const char*> names[] = {
      {Quantity::Speed, "v"},          {Quantity::Acceleration, "acc"}, {Quantity::Jerk, "jerk"},
      {Quantity::VelocityX, "vx"},     {Quantity::VelocityY, "vy"},     {Quantity::VelocityZ, "vz"},
      {Quantity::AccelerationX, "ax"}, {Quantity::AccelerationY, "ay"}, {Quantity::AccelerationZ, "az"},
      {Quantity::JerkX, "jx"},         {Quantity::JerkY, "jy"},         {Quantity::JerkZ, "jz"}};
  for (const auto& [quantity, name] : names)
    if (quantity == q) return s.extraChannel(name);
  return nullptr;
}

// A quantity that is not derived, read sample by sample: in any order, fastest in order.
class PlainValues {
 public:
  PlainValues(Quantity q, const Trajectory& s)
      : q_(q), s_(s), stored_(storedChannel(q, s)), line_(s.line.cursor()), feed_(s.feed.cursor()) {}
  double operator()(std::size_t i) {
    if (stored_) return (*stored_)[i];
    switch (q_) {
      case Quantity::FollowingError: return 1000.0 * s_.feedbackOffset(i).norm();
      case Quantity::Line: return double(line_[i]);
      case Quantity::Time: return s_.timeAt(i);
      case Quantity::Feed: return feed_[i];
      default: return kNaN;
    }
  }

 private:
  Quantity q_;
  const Trajectory& s_;
  const std::vector<double>* stored_;
  RunChannel<std::uint32_t>::Cursor line_;
  RunChannel<float>::Cursor feed_;
};

void checkSampleQuantity(Quantity q, const Trajectory& s) {
  if (quantityInfo(q).onSurface)
    throw std::invalid_argument(std::string("'") + quantityInfo(q).name + "' is a surface quantity: it needs the mesh");
  if (q == Quantity::FollowingError) requireFeedback(s, q);
  if (q == Quantity::Feed && !s.hasFeed()) missing(s, "the samples have no programmed feed (no 'feed' channel)");
  if (quantityInfo(q).needsJoints && !quantityAvailable(q, s)) {
    positionArrays(positionsOf(q), s);  // says when the samples have no joints at all
    missing(s, std::string(quantityInfo(q).label) + ": the machine has no such joint (no " +
                   (positionsOf(q) == Positions::LinearJoints ? "joint_x" : "joint_" + std::string(1, jointLetter(q))) +
                   " channel)");
  }
}

// Per-sample quantity gathered at the vertices' samples, in double.
std::vector<double> perVertex(Quantity q, const Trajectory& s, const SurfaceMesh& mesh) {
  checkSampleQuantity(q, s);
  const std::vector<std::uint32_t>& at = mesh.vertexSample;
  const std::size_t vertices = at.size();
  std::vector<double> out(vertices, kNaN);
  if (!isKinematic(q) || storedChannel(q, s)) {
    PlainValues value(q, s);
    for (std::size_t v = 0; v < vertices; ++v) out[v] = value(at[v]);
    return out;
  }
  // Each vertex's sample is derived from its own stencil, a chunk of vertices at a time (the
  // map's vertices are a stride apart: deriving every sample between them was most of the work).
  const double* t = s.irregularTime ? s.time.data() : nullptr;
  const PositionArrays p = positionArrays(positionsOf(q), s);
  for (std::size_t v = 0; v < vertices; v += kKinematicsChunk) {
    const std::size_t count = std::min(kKinematicsChunk, vertices - v);
    const Kinematics k = deriveKinematicsAt(p.axis[0], p.axis[1], p.axis[2], t, s.size(), s.cycle, at.data() + v,
                                            count, isPerAxis(q));
    for (std::size_t j = 0; j < count; ++j) out[v + j] = kinematicValue(q, k, j);
  }
  return out;
}

// The larger difference to the matched vertices on the neighbouring passes.
std::vector<double> inconsistency(const std::vector<double>& value, const SurfaceMesh& mesh) {
  std::vector<double> out(value.size(), 0.0);
  for (std::size_t v = 0; v < value.size(); ++v) {
    if (!std::isfinite(value[v])) {
      out[v] = kNaN;
      continue;
    }
    double worst = 0;
    for (const std::uint32_t n : {mesh.previousPassNeighbour[v], mesh.nextPassNeighbour[v]}) {
      if (n == kNoVertex || !std::isfinite(value[n])) continue;
      worst = std::max(worst, std::fabs(value[v] - value[n]));
    }
    out[v] = worst;
  }
  return out;
}

// um, along the commanded surface's normal (signed, + on the side the normal points to).
std::vector<double> deviation(const Trajectory& s, const SurfaceMesh& mesh) {
  requireFeedback(s, Quantity::Deviation);
  const std::vector<Vec3> positions = meshPositions(s, mesh, false);
  const std::vector<Vec3> normals = vertexNormals(positions, mesh);
  std::vector<double> out(positions.size(), kNaN);
  for (std::size_t v = 0; v < positions.size(); ++v) {
    if (normals[v].squaredNorm() == 0) continue;
    out[v] = 1000.0 * (s.feedback(mesh.vertexSample[v]) - positions[v]).dot(normals[v]);
  }
  return out;
}

std::vector<float> toFloat(const std::vector<double>& values) {
  return std::vector<float>(values.begin(), values.end());
}

std::string lowercase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

const std::vector<QuantityInfo>& quantityInfos() {
  static const std::vector<QuantityInfo> infos = {
      {Quantity::Speed, "speed", "Path speed", "mm/min", false, false},
      {Quantity::Acceleration, "accel", "Tangential acceleration", "mm/s^2", false, false},
      {Quantity::AccelerationMagnitude, "accel_mag", "Acceleration magnitude", "mm/s^2", false, false},
      {Quantity::Jerk, "jerk", "Path jerk", "mm/s^3", false, false},
      {Quantity::VelocityX, "vx", "X velocity", "mm/min", false, false},
      {Quantity::VelocityY, "vy", "Y velocity", "mm/min", false, false},
      {Quantity::VelocityZ, "vz", "Z velocity", "mm/min", false, false},
      {Quantity::AccelerationX, "ax", "X acceleration", "mm/s^2", false, false},
      {Quantity::AccelerationY, "ay", "Y acceleration", "mm/s^2", false, false},
      {Quantity::AccelerationZ, "az", "Z acceleration", "mm/s^2", false, false},
      {Quantity::JerkX, "jx", "X jerk", "mm/s^3", false, false},
      {Quantity::JerkY, "jy", "Y jerk", "mm/s^3", false, false},
      {Quantity::JerkZ, "jz", "Z jerk", "mm/s^3", false, false},
      {Quantity::FollowingError, "following_error", "Following error", "\u00b5m", true, false},
      {Quantity::Line, "line", "G-code line", "", false, false},
      {Quantity::Time, "time", "Time", "s", false, false},
      {Quantity::Feed, "feed", "Programmed feed", "mm/min", false, false},
      {Quantity::SpeedInconsistency, "speed_inconsistency", "Speed inconsistency between passes", "mm/min", false, true},
      {Quantity::AccelerationInconsistency, "accel_inconsistency", "Acceleration inconsistency between passes",
       "mm/s^2", false, true},
      {Quantity::Deviation, "deviation", "Deviation of the feedback surface", "\u00b5m", true, true},
      {Quantity::JointSpeed, "joint_speed", "Joint speed (X Y Z slides)", "mm/min", false, false, true},
      {Quantity::JointVelocityX, "joint_vx", "Joint X velocity", "mm/min", false, false, true},
      {Quantity::JointVelocityY, "joint_vy", "Joint Y velocity", "mm/min", false, false, true},
      {Quantity::JointVelocityZ, "joint_vz", "Joint Z velocity", "mm/min", false, false, true},
      {Quantity::JointAccelerationX, "joint_ax", "Joint X acceleration", "mm/s^2", false, false, true},
      {Quantity::JointAccelerationY, "joint_ay", "Joint Y acceleration", "mm/s^2", false, false, true},
      {Quantity::JointAccelerationZ, "joint_az", "Joint Z acceleration", "mm/s^2", false, false, true},
      {Quantity::JointJerkX, "joint_jx", "Joint X jerk", "mm/s^3", false, false, true},
      {Quantity::JointJerkY, "joint_jy", "Joint Y jerk", "mm/s^3", false, false, true},
      {Quantity::JointJerkZ, "joint_jz", "Joint Z jerk", "mm/s^3", false, false, true},
      {Quantity::JointVelocityA, "joint_va", "Joint A velocity", "deg/s", false, false, true},
      {Quantity::JointVelocityB, "joint_vb", "Joint B velocity", "deg/s", false, false, true},
      {Quantity::JointVelocityC, "joint_vc", "Joint C velocity", "deg/s", false, false, true},
      {Quantity::JointAccelerationA, "joint_aa", "Joint A acceleration", "deg/s^2", false, false, true},
      {Quantity::JointAccelerationB, "joint_ab", "Joint B acceleration", "deg/s^2", false, false, true},
      {Quantity::JointAccelerationC, "joint_ac", "Joint C acceleration", "deg/s^2", false, false, true},
      {Quantity::JointJerkA, "joint_ja", "Joint A jerk", "deg/s^3", false, false, true},
      {Quantity::JointJerkB, "joint_jb", "Joint B jerk", "deg/s^3", false, false, true},
      {Quantity::JointJerkC, "joint_jc", "Joint C jerk", "deg/s^3", false, false, true},
  };
  return infos;
}

bool isSignedQuantity(Quantity q) {
  switch (q) {
    case Quantity::Acceleration:
    case Quantity::VelocityX: case Quantity::VelocityY: case Quantity::VelocityZ:
    case Quantity::AccelerationX: case Quantity::AccelerationY: case Quantity::AccelerationZ:
    case Quantity::JerkX: case Quantity::JerkY: case Quantity::JerkZ:
    case Quantity::Deviation:
      return true;
    default:
      return q > Quantity::JointSpeed;
  }
}

const QuantityInfo& quantityInfo(Quantity q) {
  for (const QuantityInfo& info : quantityInfos())
    if (info.quantity == q) return info;
  throw std::invalid_argument("unknown quantity");
}

bool quantityAvailable(Quantity q, const Trajectory& samples) {
  const QuantityInfo& info = quantityInfo(q);
  if (info.needsFeedback && !samples.hasFeedback()) return false;
  if (!info.needsJoints) return true;
  if (positionsOf(q) == Positions::LinearJoints) return samples.extraChannel("joint_x") != nullptr;
  return samples.extraChannel(std::string("joint_") + jointLetter(q)) != nullptr;
}

std::optional<Quantity> parseQuantity(const std::string& name) {
  const std::string wanted = lowercase(name);
  for (const QuantityInfo& info : quantityInfos())
    if (wanted == info.name) return info.quantity;
  return std::nullopt;
}

void sampleQuantityRange(Quantity q, const Trajectory& samples, std::size_t first, std::size_t last, float* out) {
  checkSampleQuantity(q, samples);
  last = std::min(last, samples.size());
  if (first >= last) return;
  if (!isKinematic(q) || storedChannel(q, samples)) {
    PlainValues value(q, samples);
    for (std::size_t i = first; i < last; ++i) out[i - first] = static_cast<float>(value(i));
    return;
  }
  const PositionArrays p = positionArrays(positionsOf(q), samples);
  for (std::size_t from = first; from < last; from += kKinematicsChunk) {
    deriveRange(samples, p, isPerAxis(q), from, std::min(last, from + kKinematicsChunk), [&](std::size_t i, const Kinematics& k, std::size_t local) {
      out[i - first] = static_cast<float>(kinematicValue(q, k, local));
    });
  }
}

std::vector<double> sampleQuantity(Quantity q, const Trajectory& samples) {
  return std::move(sampleQuantities({q}, samples).front());
}

std::vector<std::vector<double>> sampleQuantities(const std::vector<Quantity>& qs, const Trajectory& samples) {
  for (const Quantity q : qs) checkSampleQuantity(q, samples);  // before a channel's memory is taken
  const std::size_t n = samples.size();
  std::vector<std::vector<double>> out(qs.size(), std::vector<double>(n));
  // Derived once for each kind of positions asked for: the tip, the linear or the rotary joints.
  for (const Positions which : {Positions::Tip, Positions::LinearJoints, Positions::RotaryJoints}) {
    std::vector<std::size_t> derived;  // of qs
    bool perAxis = false;
    for (std::size_t j = 0; j < qs.size(); ++j) {
      if (isKinematic(qs[j]) && !storedChannel(qs[j], samples)) {
        if (positionsOf(qs[j]) != which) continue;
        derived.push_back(j);
        perAxis = perAxis || isPerAxis(qs[j]);
      } else if (which == Positions::Tip) {
        PlainValues value(qs[j], samples);
        for (std::size_t i = 0; i < n; ++i) out[j][i] = value(i);
      }
    }
    if (derived.empty()) continue;
    const PositionArrays p = positionArrays(which, samples);
    for (std::size_t first = 0; first < n; first += kKinematicsChunk) {
      deriveRange(samples, p, perAxis, first, std::min(n, first + kKinematicsChunk),
                  [&](std::size_t i, const Kinematics& k, std::size_t local) {
                    for (const std::size_t j : derived) out[j][i] = kinematicValue(qs[j], k, local);
                  });
    }
  }
  return out;
}

std::vector<float> vertexQuantity(Quantity q, const Trajectory& samples, const SurfaceMesh& mesh) {
  switch (q) {
    case Quantity::SpeedInconsistency: return toFloat(inconsistency(perVertex(Quantity::Speed, samples, mesh), mesh));
    case Quantity::AccelerationInconsistency:
      return toFloat(inconsistency(perVertex(Quantity::Acceleration, samples, mesh), mesh));
    case Quantity::Deviation: return toFloat(deviation(samples, mesh));
    default: return toFloat(perVertex(q, samples, mesh));
  }
}

std::optional<std::vector<float>> vertexExtraChannel(const Trajectory& samples, const SurfaceMesh& mesh,
                                                     const std::string& name) {
  const std::vector<double>* channel = samples.extraChannel(name);
  if (channel == nullptr) return std::nullopt;
  std::vector<float> out(mesh.vertexSample.size());
  for (std::size_t v = 0; v < out.size(); ++v) out[v] = static_cast<float>((*channel)[mesh.vertexSample[v]]);
  return out;
}

}  // namespace isurface
