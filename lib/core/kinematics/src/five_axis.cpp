#include "isurface/kinematics/five_axis.h"

#include <cmath>

#include <fmt/format.h>

namespace isurface {

namespace {

constexpr double kDegree = kPi / 180.0;

Eigen::Matrix3d turn(const RotaryAxis& axis, double degrees) {
  return Eigen::AngleAxisd(degrees * kDegree, axis.direction.normalized()).toRotationMatrix();
}

// A point turned by `angle` about an axis through `pivot`.
Vec3 turnedAbout(const RotaryAxis& axis, double degrees, const Vec3& p) {
  return turn(axis, degrees) * (p - axis.pivot) + axis.pivot;
}

// Table axes: the part's frame to the machine's (the outer axis carries the inner).
Vec3 partToMachine(const FiveAxisKinematics& k, const std::array<double, 2>& a, const Vec3& p) {
  switch (k.structure) {
    case KinematicStructure::TableTable:
      return turnedAbout(k.rotary[0], a[0], turnedAbout(k.rotary[1], a[1], p));
    case KinematicStructure::HeadTable: return turnedAbout(k.rotary[1], a[1], p);
    case KinematicStructure::HeadHead: break;
  }
  return p;
}

Vec3 machineToPart(const FiveAxisKinematics& k, const std::array<double, 2>& a, const Vec3& p) {
  switch (k.structure) {
    case KinematicStructure::TableTable:
      return turnedAbout(k.rotary[1], -a[1], turnedAbout(k.rotary[0], -a[0], p));
    case KinematicStructure::HeadTable: return turnedAbout(k.rotary[1], -a[1], p);
    case KinematicStructure::HeadHead: break;
  }
  return p;
}

// Head axes: the tip relative to the gauge line point (head pivots are given relative to it).
Vec3 tipFromGauge(const FiveAxisKinematics& k, const std::array<double, 2>& a) {
  const Vec3 tip(0, 0, -k.toolLength);
  switch (k.structure) {
    case KinematicStructure::HeadHead: return turnedAbout(k.rotary[0], a[0], turnedAbout(k.rotary[1], a[1], tip));
    case KinematicStructure::HeadTable: return turnedAbout(k.rotary[0], a[0], tip);
    case KinematicStructure::TableTable: break;
  }
  return tip;
}

// Angle (rad) that turns v about the unit axis u onto c, both taken across u; 0 when v lies
// along u (no turn about u moves it).
double angleAbout(const Vec3& u, const Vec3& v, const Vec3& c) {
  const Vec3 vp = v - v.dot(u) * u, cp = c - c.dot(u) * u;
  if (vp.norm() < 1e-12 || cp.norm() < 1e-12) return 0;
  return std::atan2(u.dot(vp.cross(cp)), vp.dot(cp));
}

// Angles (rad) with R(u1, f1) v1 = R(u2, f2) v2, for unit vectors and non-parallel unit axes:
// the common vector has the components of v1 along u1 and of v2 along u2 (each turn keeps
// its own), and unit length.
std::vector<std::array<double, 2>> twoTurnsMeeting(const Vec3& u1, const Vec3& v1, const Vec3& u2, const Vec3& v2) {
  const double g = u1.dot(u2), alpha = v1.dot(u1), beta = v2.dot(u2);
  const Vec3 n = u1.cross(u2);
  const double across = n.squaredNorm();
  if (across < 1e-12) return {};
  const double x = (alpha - g * beta) / across, y = (beta - g * alpha) / across;
  const double z2 = (1 - x * x - y * y - 2 * g * x * y) / across;
  if (z2 < -1e-12) return {};
  const double z = std::sqrt(std::max(0.0, z2));
  std::vector<std::array<double, 2>> out;
  for (const double s : {1.0, -1.0}) {
    const Vec3 c = x * u1 + y * u2 + s * z * n;
    out.push_back({angleAbout(u1, v1, c), angleAbout(u2, v2, c)});
    if (z < 1e-9) break;  // one solution: the two coincide
  }
  return out;
}

// An angle in (-180, 180].
double principal(double degrees) {
  double a = std::fmod(degrees, 360.0);
  if (a <= -180) a += 360;
  if (a > 180) a -= 360;
  return a;
}

}  // namespace

JointPosition jointsFor(const FiveAxisKinematics& k, const TipPose& pose) {
  JointPosition j;
  j.rotary = pose.rotary;
  j.linear = partToMachine(k, pose.rotary, pose.tip) - tipFromGauge(k, pose.rotary);
  return j;
}

TipPose tipOf(const FiveAxisKinematics& k, const JointPosition& joints) {
  TipPose pose;
  pose.rotary = joints.rotary;
  pose.tip = machineToPart(k, joints.rotary, joints.linear + tipFromGauge(k, joints.rotary));
  return pose;
}

Vec3 toolAxis(const FiveAxisKinematics& k, const std::array<double, 2>& a) {
  // A direction: the rotations alone, without the pivots.
  Eigen::Matrix3d head = Eigen::Matrix3d::Identity(), table = Eigen::Matrix3d::Identity();
  switch (k.structure) {
    case KinematicStructure::TableTable: table = turn(k.rotary[0], a[0]) * turn(k.rotary[1], a[1]); break;
    case KinematicStructure::HeadHead: head = turn(k.rotary[0], a[0]) * turn(k.rotary[1], a[1]); break;
    case KinematicStructure::HeadTable:
      head = turn(k.rotary[0], a[0]);
      table = turn(k.rotary[1], a[1]);
      break;
  }
  return table.transpose() * head * Vec3::UnitZ();
}

std::vector<std::array<double, 2>> rotaryFor(const FiveAxisKinematics& k, const Vec3& axis) {
  if (!(axis.norm() > 0)) return {};
  const Vec3 a = axis.normalized(), z = Vec3::UnitZ();
  const Vec3 u0 = k.rotary[0].direction.normalized(), u1 = k.rotary[1].direction.normalized();
  std::vector<std::array<double, 2>> out;
  // Each structure's equation toolAxis = a as two turns meeting: R(first) v1 = R(second) v2.
  switch (k.structure) {
    case KinematicStructure::TableTable:  // R(u0, -t0) z = R(u1, t1) a
      for (const auto& f : twoTurnsMeeting(u0, z, u1, a)) out.push_back({-f[0], f[1]});
      break;
    case KinematicStructure::HeadHead:  // R(u1, t1) z = R(u0, -t0) a
      for (const auto& f : twoTurnsMeeting(u1, z, u0, a)) out.push_back({-f[1], f[0]});
      break;
    case KinematicStructure::HeadTable:  // R(u0, t0) z = R(u1, t1) a
      for (const auto& f : twoTurnsMeeting(u0, z, u1, a)) out.push_back({f[0], f[1]});
      break;
  }
  for (auto& angles : out)
    for (double& t : angles) t = principal(t / kDegree);
  return out;
}

std::optional<Singularity> singularityNear(const FiveAxisKinematics& k, const std::array<double, 2>& rotary,
                                           double withinDeg) {
  // How fast the tool axis turns with each rotary axis: sin of its angle to where that axis
  // lies along it (1 rad of the axis turns it sin(angle) rad).
  constexpr double kStep = 1e-4;  // deg
  std::optional<Singularity> nearest;
  for (int i = 0; i < 2; ++i) {
    std::array<double, 2> ahead = rotary, behind = rotary;
    ahead[i] += kStep, behind[i] -= kStep;
    const double rate = (toolAxis(k, ahead) - toolAxis(k, behind)).norm() / (2 * kStep * kDegree);
    const double distance = std::asin(std::min(1.0, rate)) / kDegree;
    if (distance > withinDeg || (nearest && nearest->distance <= distance)) continue;
    const char name = k.rotary[i].name;
    nearest = Singularity{name, distance,
                          fmt::format("the tool axis lies within {:.2f} deg of the {} axis: turning {} hardly tilts the "
                                      "tool there, so a small change of tool axis asks for a large turn of {}",
                                      distance, name, name, name)};
  }
  return nearest;
}

double shortestWay(double from, double target) {
  double d = std::fmod(target - from, 360.0);
  if (d <= -180) d += 360;
  if (d > 180) d -= 360;
  return from + d;
}

}  // namespace isurface
