// A machine written back as JSON in the units and keys parseMachine() reads.
#include <nlohmann/json.hpp>

#include "isurface/base/units.h"
#include "isurface/machine/machine.h"
#include "isurface/base/json_text.h"
#include "kinematics_description.h"

namespace isurface {

namespace {

using json = nlohmann::ordered_json;

const char* plannerName(TrajectoryPlanner p) { return p == TrajectoryPlanner::LinuxCnc29 ? "linuxcnc-2.9" : "generic"; }

json limitsJson(const Machine& m) {
  json axes = json::object();
  const char* names[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    const AxisLimits& a = m.axes[i];
    axes[names[i]] = {{"max_velocity_mm_min", mmPerSToMmPerMin(a.maxVelocity)},
                      {"max_acceleration_mm_s2", a.maxAcceleration},
                      {"max_jerk_mm_s3", a.maxJerk},
                      {"position_gain_1_s", a.positionGain},
                      {"velocity_feed_forward", a.velocityFeedForward},
                      {"velocity_loop_time_constant_s", a.velocityLoopTimeConstant}};
  }
  return {{"name", m.name},
          {"cycle_s", m.cycle},
          {"rapid_mm_min", mmPerSToMmPerMin(m.rapidVelocity)},
          {"chord_tolerance_mm", m.chordTolerance},
          {"axes", axes},
          {"control", {{"planner", plannerName(m.control.planner)},
                       {"acceleration_rise_time_s", m.control.accelerationRiseTime},
                       {"chord_smoothing", m.control.chordSmoothing}}}};
}

const char* planeName(Plane p) { return p == Plane::XY ? "G17" : p == Plane::ZX ? "G18" : "G19"; }

}  // namespace

// A name or a folder that is not UTF-8 is written with replacement characters, not refused.
std::string machineLimitsJson(const Machine& m) { return jsonText(limitsJson(m)); }

std::string machineDescriptionJson(const Machine& m) {
  json root = limitsJson(m);
  root["reference_positions_mm"] = {{"g28", {m.g28Position.x(), m.g28Position.y(), m.g28Position.z()}},
                                    {"g30", {m.g30Position.x(), m.g30Position.y(), m.g30Position.z()}}};
  json control = {{"planner", plannerName(m.control.planner)},
                  {"acceleration_rise_time_s", m.control.accelerationRiseTime},
                  {"chord_smoothing", m.control.chordSmoothing},
                  {"dialect", m.control.fanuc ? "fanuc" : "linuxcnc"},
                  {"units_at_power_on", m.control.inch ? "inch" : "mm"}};
  if (m.control.modesNamed) {
    control["plane_at_power_on"] = planeName(m.control.plane);
    control["distance_at_power_on"] = m.control.incremental ? "G91" : "G90";
  }
  // Folders were made absolute when read: written so, they still hold wherever the file goes.
  if (!m.control.subroutinePath.empty()) control["subroutine_path"] = m.control.subroutinePath;
  root["control"] = control;
  if (m.kinematics) root["kinematics"] = kinematicsJson(*m.kinematics);
  if (!m.toolDiameters.empty()) {
    // Diameters in mm: the table's own units are not kept once read.
    json diameters = json::object();
    for (const auto& [tool, diameter] : m.toolDiameters) diameters[std::to_string(tool)] = diameter;
    root["tools"] = {{"units", "mm"}, {"diameters", diameters}};
  }
  return jsonText(root, 2) + "\n";
}

}  // namespace isurface
