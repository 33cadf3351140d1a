#include "kinematics_description.h"

#include <fmt/format.h>

#include "description_reading.h"

namespace isurface {

namespace {

using namespace description_reading;

constexpr const char* kStructures[] = {"table-table", "head-head", "head-table"};

RotaryAxis readRotary(const json& a, const std::string& where, const std::string& source) {
  if (!a.is_object()) fail(source, where + " must be an object");
  rejectUnknownKeys(a,
                    {"name", "direction", "pivot_mm", "min_deg", "max_deg", "wraps", "max_velocity_deg_s",
                     "max_acceleration_deg_s2", "max_jerk_deg_s3"},
                    where + ".", source);
  RotaryAxis r;
  if (!a.contains("name") || !a["name"].is_string() || a["name"].get<std::string>().size() != 1 ||
      std::string("ABC").find(a["name"].get<std::string>()[0]) == std::string::npos)
    fail(source, where + ".name must be \"A\", \"B\" or \"C\"");
  r.name = a["name"].get<std::string>()[0];
  // A, B and C turn about X, Y and Z unless the description says otherwise (a reversed sense).
  const Vec3 plain = r.name == 'A' ? Vec3::UnitX() : r.name == 'B' ? Vec3::UnitY() : Vec3::UnitZ();
  r.direction = position(a, "direction", plain, source, where + ".");
  if (!(r.direction.norm() > 1e-9)) fail(source, where + ".direction must not be zero");
  r.direction.normalize();
  r.pivot = position(a, "pivot_mm", Vec3::Zero(), source, where + ".");
  r.wraps = a.contains("wraps") && a["wraps"].is_boolean() && a["wraps"].get<bool>();
  if (a.contains("wraps") && !a["wraps"].is_boolean()) fail(source, where + ".wraps must be true or false");
  r.minimum = number(a, "min_deg", r.wraps ? -1e9 : -360, source, where + ".");
  r.maximum = number(a, "max_deg", r.wraps ? 1e9 : 360, source, where + ".");
  if (!(r.minimum < r.maximum)) fail(source, where + ".min_deg must be below max_deg");
  r.maxVelocity = number(a, "max_velocity_deg_s", 0, source, where + ".");
  r.maxAcceleration = number(a, "max_acceleration_deg_s2", 0, source, where + ".");
  r.maxJerk = number(a, "max_jerk_deg_s3", 0, source, where + ".");
  requirePositive(r.maxVelocity, source, where + ".max_velocity_deg_s");
  requirePositive(r.maxAcceleration, source, where + ".max_acceleration_deg_s2");
  if (r.maxJerk < 0) fail(source, where + ".max_jerk_deg_s3 must be 0 (no limit) or more");
  return r;
}

}  // namespace

FiveAxisKinematics readKinematics(const json& k, const std::string& source) {
  if (!k.is_object()) fail(source, "kinematics must be an object");
  rejectUnknownKeys(k, {"structure", "rotary_axes", "tool_length_mm", "tool_centre_point"}, "kinematics.", source);
  FiveAxisKinematics out;
  const std::string structure = k.contains("structure") && k["structure"].is_string() ? k["structure"].get<std::string>() : "";
  if (structure == kStructures[0]) out.structure = KinematicStructure::TableTable;
  else if (structure == kStructures[1]) out.structure = KinematicStructure::HeadHead;
  else if (structure == kStructures[2]) out.structure = KinematicStructure::HeadTable;
  else fail(source, "kinematics.structure must be \"table-table\", \"head-head\" or \"head-table\"");
  if (!k.contains("rotary_axes") || !k["rotary_axes"].is_array() || k["rotary_axes"].size() != 2)
    fail(source, "kinematics.rotary_axes must list the two rotary axes (the carrying one first; for head-table "
                 "the head's first)");
  for (int i = 0; i < 2; ++i)
    out.rotary[i] = readRotary(k["rotary_axes"][i], fmt::format("kinematics.rotary_axes[{}]", i), source);
  if (out.rotary[0].name == out.rotary[1].name) fail(source, "kinematics.rotary_axes name one axis twice");
  if (out.rotary[0].direction.cross(out.rotary[1].direction).norm() < 1e-6)
    fail(source, "kinematics.rotary_axes turn about parallel directions: no tool axis but one can be reached");
  out.toolLength = number(k, "tool_length_mm", 0, source, "kinematics.");
  if (k.contains("tool_centre_point")) {
    if (!k["tool_centre_point"].is_boolean()) fail(source, "kinematics.tool_centre_point must be true or false");
    out.toolCentrePoint = k["tool_centre_point"].get<bool>();
  }
  return out;
}

nlohmann::ordered_json kinematicsJson(const FiveAxisKinematics& k) {
  nlohmann::ordered_json axes = nlohmann::ordered_json::array();
  for (const RotaryAxis& r : k.rotary) {
    nlohmann::ordered_json a = {{"name", std::string(1, r.name)},
                                {"direction", {r.direction.x(), r.direction.y(), r.direction.z()}},
                                {"pivot_mm", {r.pivot.x(), r.pivot.y(), r.pivot.z()}},
                                {"wraps", r.wraps}};
    if (!r.wraps) a["min_deg"] = r.minimum, a["max_deg"] = r.maximum;
    a["max_velocity_deg_s"] = r.maxVelocity;
    a["max_acceleration_deg_s2"] = r.maxAcceleration;
    a["max_jerk_deg_s3"] = r.maxJerk;
    axes.push_back(a);
  }
  return {{"structure", kStructures[static_cast<int>(k.structure)]}, {"rotary_axes", axes}, {"tool_length_mm", k.toolLength},
          {"tool_centre_point", k.toolCentrePoint}};
}

}  // namespace isurface
