#include "isurface/machine/machine.h"
#include "isurface/base/input_files.h"

#include <algorithm>
#include <set>
#include <cmath>
#include <initializer_list>
#include <vector>
#include <filesystem>
#include <fstream>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <sstream>

#include "isurface/base/bounded_file.h"
#include "isurface/base/diagnostic.h"
#include "isurface/base/units.h"
#include "description_reading.h"
#include "kinematics_description.h"

namespace isurface {

namespace {

using nlohmann::json;
using namespace description_reading;

Machine builtInFallback() {
  Machine m;
  m.name = "built-in";
  return m;
}

// "tools": {"units": "mm" | "inch", "table": "tools.tbl"} or {"units": .., "diameters": {"1": 6}}.
void readTools(const json& tools, const std::string& source, Machine& m) {
  if (!tools.is_object()) fail(source, "tools must be an object");
  rejectUnknownKeys(tools, {"units", "table", "diameters"}, "tools.", source);
  if (tools.contains("units")) {
    const std::string u = tools["units"].is_string() ? tools["units"].get<std::string>() : "";
    if (u != "mm" && u != "inch") fail(source, "tools.units must be \"mm\" or \"inch\"");
    m.toolTableInch = u == "inch";
  }
  if (tools.contains("table") && tools.contains("diameters"))
    fail(source, "tools: give a \"table\" file or \"diameters\", not both");
  if (tools.contains("table")) {
    if (!tools["table"].is_string()) fail(source, "tools.table must be a file name");
    std::filesystem::path table = tools["table"].get<std::string>();
    if (table.is_relative()) table = std::filesystem::path(source).parent_path() / table;
    m.toolDiameters = readToolTable(table.string(), m.toolTableInch);
  }
  if (tools.contains("diameters")) {
    const json& d = tools["diameters"];
    if (!d.is_object()) fail(source, "tools.diameters must map tool numbers to diameters");
    m.toolDiameters.clear();
    for (const auto& [key, value] : d.items()) {
      const std::string where = "tools.diameters." + key;
      if (key.empty() || key.find_first_not_of("0123456789") != std::string::npos || key.size() > 9)
        fail(source, where + ": a tool number must be a whole number");
      if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < 0)
        fail(source, where + " must be a diameter, 0 or more");
      m.toolDiameters[std::stoi(key)] = m.toolTableInch ? value.get<double>() * kMmPerInch : value.get<double>();
    }
  }
}

// The description's JSON; a key given twice in one object is refused (JSON readers differ on
// which one counts, and one of the two values would be dropped without a word).
json parseDescription(const std::string& text, const std::string& source) {
  std::vector<std::set<std::string>> keysOfOpenObjects;
  std::string repeated;
  const json::parser_callback_t noteKeys = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) keysOfOpenObjects.emplace_back();
    if (event == json::parse_event_t::object_end && !keysOfOpenObjects.empty()) keysOfOpenObjects.pop_back();
    if (event == json::parse_event_t::key && !keysOfOpenObjects.empty() &&
        !keysOfOpenObjects.back().insert(parsed.get<std::string>()).second && repeated.empty())
      repeated = parsed.get<std::string>();
    return true;
  };
  json root;
  try {
    root = json::parse(text, noteKeys);
  } catch (const json::exception& e) {  // malformed text, or a number beyond a double
    fail(source, std::string("not valid JSON: ") + e.what());
  }
  if (!repeated.empty()) fail(source, "key \"" + repeated + "\" is given twice in one object: give it once");
  return root;
}

Machine parseOnto(const Machine& base, const std::string& text, const std::string& source) {
  const json root = parseDescription(text, source);
  if (!root.is_object()) fail(source, "a machine description must be a JSON object");
  rejectUnknownKeys(root,
                    {"name", "cycle_s", "rapid_mm_min", "chord_tolerance_mm", "axes", "control", "tools",
                     "reference_positions_mm", "kinematics"},
                    "", source);
  Machine m = base;
  if (root.contains("name")) {
    if (!root["name"].is_string()) fail(source, "name must be a string");
    m.name = root["name"].get<std::string>();
  }
  m.cycle = number(root, "cycle_s", m.cycle, source, "");
  requirePositive(m.cycle, source, "cycle_s");
  if (m.cycle > 0.1) fail(source, "cycle_s must be at most 0.1 s");
  // NC interpolation cycles run from about 0.1 to 10 ms; a far shorter one only multiplies the
  // samples of every simulation (1e-12 s would take hours for a few millimetres).
  if (m.cycle < 1e-5) fail(source, "cycle_s must be at least 1e-05 s (10 us)");
  // Checked as written (mm/min), then kept in mm/s.
  const double rapid = number(root, "rapid_mm_min", mmPerSToMmPerMin(m.rapidVelocity), source, "");
  requirePositive(rapid, source, "rapid_mm_min");
  m.rapidVelocity = mmPerMinToMmPerS(rapid);
  m.chordTolerance = number(root, "chord_tolerance_mm", m.chordTolerance, source, "");
  requirePositive(m.chordTolerance, source, "chord_tolerance_mm");

  if (root.contains("axes")) {
    const json& axes = root["axes"];
    if (!axes.is_object()) fail(source, "axes must be an object with x, y, z");
    static const char* names[3] = {"x", "y", "z"};
    for (const auto& [key, value] : axes.items())
      if (key != "x" && key != "y" && key != "z")
        fail(source, "axes." + key + ": unknown axis (this machine model has x, y, z)");
    for (int i = 0; i < 3; ++i) {
      if (!axes.contains(names[i])) continue;
      const json& a = axes[names[i]];
      const std::string where = std::string("axes.") + names[i] + ".";
      if (!a.is_object()) fail(source, where.substr(0, where.size() - 1) + " must be an object");
      rejectUnknownKeys(a,
                        {"max_velocity_mm_min", "max_acceleration_mm_s2", "max_jerk_mm_s3", "position_gain_1_s",
                         "velocity_feed_forward", "velocity_loop_time_constant_s"},
                        where, source);
      AxisLimits& limits = m.axes[i];
      const double velocity = number(a, "max_velocity_mm_min", mmPerSToMmPerMin(limits.maxVelocity), source, where);
      requirePositive(velocity, source, where + "max_velocity_mm_min");
      limits.maxVelocity = mmPerMinToMmPerS(velocity);
      limits.maxAcceleration = number(a, "max_acceleration_mm_s2", limits.maxAcceleration, source, where);
      requirePositive(limits.maxAcceleration, source, where + "max_acceleration_mm_s2");
      if (a.contains("max_jerk_mm_s3") && a["max_jerk_mm_s3"].is_null()) {
        limits.maxJerk = 0;
      } else {
        limits.maxJerk = number(a, "max_jerk_mm_s3", limits.maxJerk, source, where);
        if (limits.maxJerk < 0) fail(source, where + "max_jerk_mm_s3 must be >= 0 (0 or null: not limited)");
        // The jerk filter lasts about twice acceleration / jerk: beyond a second it is no machine.
        if (limits.maxJerk > 0 && limits.maxJerk < limits.maxAcceleration)
          fail(source, where + "max_jerk_mm_s3 must be 0 (not limited) or at least max_acceleration_mm_s2 per second (got " +
                           std::to_string(limits.maxJerk) + ")");
      }
      limits.positionGain = number(a, "position_gain_1_s", limits.positionGain, source, where);
      requirePositive(limits.positionGain, source, where + "position_gain_1_s");
      limits.velocityFeedForward = number(a, "velocity_feed_forward", limits.velocityFeedForward, source, where);
      if (limits.velocityFeedForward < 0 || limits.velocityFeedForward > 1)
        fail(source, where + "velocity_feed_forward must be between 0 and 1");
      limits.velocityLoopTimeConstant =
          number(a, "velocity_loop_time_constant_s", limits.velocityLoopTimeConstant, source, where);
      // A velocity loop slower than a second never follows its command: the feedback would freeze.
      if (!(limits.velocityLoopTimeConstant >= 0 && limits.velocityLoopTimeConstant <= 1.0))
        fail(source, where + "velocity_loop_time_constant_s must be from 0 to 1 s");
    }
  }
  bool riseTimeGiven = false;
  if (root.contains("control")) {
    const json& c = root["control"];
    if (!c.is_object()) fail(source, "control must be an object");
    rejectUnknownKeys(c,
                      {"dialect", "planner", "acceleration_rise_time_s", "chord_smoothing", "units_at_power_on",
                       "plane_at_power_on", "distance_at_power_on", "subroutine_path"},
                      "control.", source);
    if (c.contains("planner")) {
      const std::string p = c["planner"].is_string() ? c["planner"].get<std::string>() : "";
      if (p != "generic" && p != "linuxcnc-2.9") fail(source, "control.planner must be \"generic\" or \"linuxcnc-2.9\"");
      m.control.planner = p == "generic" ? TrajectoryPlanner::Generic : TrajectoryPlanner::LinuxCnc29;
    }
    riseTimeGiven = c.contains("acceleration_rise_time_s");
    if (riseTimeGiven) {
      m.control.accelerationRiseTime = number(c, "acceleration_rise_time_s", 0.0, source, "control.");
      if (m.control.accelerationRiseTime < 0 || m.control.accelerationRiseTime > 1.0)
        fail(source, "control.acceleration_rise_time_s must be from 0 to 1 s");
    }
    if (c.contains("chord_smoothing")) {
      if (!c["chord_smoothing"].is_boolean()) fail(source, "control.chord_smoothing must be true or false");
      m.control.chordSmoothing = c["chord_smoothing"].get<bool>();
    }
    if (c.contains("dialect")) {
      const std::string d = c["dialect"].is_string() ? c["dialect"].get<std::string>() : "";
      if (d != "linuxcnc" && d != "fanuc") fail(source, "control.dialect must be \"linuxcnc\" or \"fanuc\"");
      m.control.fanuc = d == "fanuc";
    }
    if (c.contains("units_at_power_on")) {
      const std::string u = c["units_at_power_on"].is_string() ? c["units_at_power_on"].get<std::string>() : "";
      if (u != "mm" && u != "inch") fail(source, "control.units_at_power_on must be \"mm\" or \"inch\"");
      m.control.inch = u == "inch";
    }
    if (c.contains("plane_at_power_on")) {
      const std::string p = c["plane_at_power_on"].is_string() ? c["plane_at_power_on"].get<std::string>() : "";
      if (p != "G17" && p != "G18" && p != "G19") fail(source, "control.plane_at_power_on must be \"G17\", \"G18\" or \"G19\"");
      m.control.plane = p == "G17" ? Plane::XY : p == "G18" ? Plane::ZX : Plane::YZ;
      m.control.modesNamed = true;
    }
    if (c.contains("distance_at_power_on")) {
      const std::string d = c["distance_at_power_on"].is_string() ? c["distance_at_power_on"].get<std::string>() : "";
      if (d != "G90" && d != "G91") fail(source, "control.distance_at_power_on must be \"G90\" or \"G91\"");
      m.control.incremental = d == "G91";
      m.control.modesNamed = true;
    }
    if (c.contains("subroutine_path")) {
      const json& folders = c["subroutine_path"];
      if (!folders.is_array()) fail(source, "control.subroutine_path must be a list of folders");
      m.control.subroutinePath.clear();
      for (const json& f : folders) {
        if (!f.is_string()) fail(source, "control.subroutine_path must be a list of folders");
        std::filesystem::path folder = f.get<std::string>();
        if (folder.is_relative()) folder = std::filesystem::path(source).parent_path() / folder;
        m.control.subroutinePath.push_back(folder.string());
      }
    }
  }
  if (root.contains("tools")) readTools(root["tools"], source, m);
  if (root.contains("kinematics")) m.kinematics = readKinematics(root["kinematics"], source);
  if (root.contains("reference_positions_mm")) {
    const json& refs = root["reference_positions_mm"];
    if (!refs.is_object()) fail(source, "reference_positions_mm must be an object");
    rejectUnknownKeys(refs, {"g28", "g30"}, "reference_positions_mm.", source);
    m.g28Position = position(refs, "g28", m.g28Position, source);
    m.g30Position = position(refs, "g30", m.g30Position, source);
  }
  if (!riseTimeGiven) m.control.accelerationRiseTime = largestRiseTime(m);
  if (m.jerkLimited() && !(m.control.accelerationRiseTime > 0))
    fail(source, "control.acceleration_rise_time_s must be greater than 0 on a machine with a jerk limit");
  // Checked on every axis, given or inherited from the default: a new cycle_s alone can make
  // the default servo diverge.
  static const char* axisNames[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i)
    if (m.axes[i].positionGain * m.cycle > 0.5)
      fail(source, fmt::format("axes.{}.position_gain_1_s is too high for cycle_s ({:g} 1/s x {:g} s must be at most "
                               "0.5 for the servo to settle)",
                               axisNames[i], m.axes[i].positionGain, m.cycle));
  return m;
}

}  // namespace

double largestRiseTime(const Machine& m) {
  if (!m.jerkLimited()) return 0;
  double t = 0;
  for (const AxisLimits& axis : m.axes) t = std::max(t, axis.maxAcceleration / axis.maxJerk);
  return t;
}

Machine defaultMachine() {
  static const Machine machine = parseOnto(builtInFallback(), defaultMachineJson(), "default machine");
  return machine;
}

Machine parseMachine(const std::string& jsonText, const std::string& sourceName) {
  return parseOnto(defaultMachine(), jsonText, sourceName);
}

Machine loadMachine(const std::string& path) {
  noteInputFile(path);
  // A description is a few hundred bytes; a JSON document held in memory takes many times its
  // size, so a huge file (or /dev/zero) is refused at 1 MB.
  return parseMachine(readBoundedFile(path, BoundedRead{1 << 20, "machine description"}), path);
}

}  // namespace isurface
