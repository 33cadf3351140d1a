// Settings as a small JSON object. Reading never fails (a missing, unreadable or hand-broken file
// means defaults, value by value); writing goes through a temporary file so a crash mid-write
// never leaves a truncated settings file.
#include "isurface/app_model/settings.h"
#include "isurface/machine/machine.h"

#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "isurface/base/bounded_file.h"
#include "isurface/base/diagnostic.h"
#include <sstream>

#include "isurface/io/atomic_file.h"
#include "isurface/base/json_text.h"

namespace isurface::app_model {

namespace {

constexpr std::size_t kMaxRecentFiles = 10;

// Window sizes outside this are a damaged file or a vanished monitor: the default is safer.
constexpr int kMinWindowSide = 200, kMaxWindowSide = 32768;

void readString(const nlohmann::json& json, const char* key, std::string& target) {
  const auto it = json.find(key);
  if (it != json.end() && it->is_string()) target = it->get<std::string>();
}

void readWindowSide(const nlohmann::json& json, const char* key, int& target) {
  const auto it = json.find(key);
  if (it == json.end() || !it->is_number_integer()) return;
  const auto value = it->get<long long>();
  if (value >= kMinWindowSide && value <= kMaxWindowSide) target = static_cast<int>(value);
}

}  // namespace

namespace {

constexpr std::size_t kMaxProgramMachines = 20;

std::string absoluteOf(const std::string& given) {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(given, error);
  return error ? given : absolute.lexically_normal().string();
}

}  // namespace

void Settings::addRecent(const std::string& given) {
  if (given.empty()) return;
  // Absolute: the application may be started from another folder next time.
  const std::string path = absoluteOf(given);
  recentFiles.erase(std::remove(recentFiles.begin(), recentFiles.end(), path), recentFiles.end());
  recentFiles.insert(recentFiles.begin(), path);
  if (recentFiles.size() > kMaxRecentFiles) recentFiles.resize(kMaxRecentFiles);
}

void Settings::rememberMachine(const std::string& given, const std::string& machineJson) {
  if (given.empty()) return;
  const std::string path = absoluteOf(given);
  programMachines.erase(std::remove_if(programMachines.begin(), programMachines.end(),
                                       [&](const auto& entry) { return entry.first == path; }),
                        programMachines.end());
  if (machineJson.empty() || machineJson == machineDescriptionJson(defaultMachine())) return;
  programMachines.insert(programMachines.begin(), {path, machineJson});
  if (programMachines.size() > kMaxProgramMachines) programMachines.resize(kMaxProgramMachines);
}

std::string Settings::machineOf(const std::string& given) const {
  const std::string path = absoluteOf(given);
  for (const auto& [program, machine] : programMachines)
    if (program == path) return machine;
  return {};
}

std::string settingsPath() {
  // The XDG base directory rules ignore an empty or relative XDG_CONFIG_HOME.
  const char* config = std::getenv("XDG_CONFIG_HOME");
  std::string folder;
  if (config && config[0] == '/') {
    folder = config;
  } else {
    const char* home = std::getenv("HOME");
    if (!home || home[0] == '\0') return {};
    folder = std::string(home) + "/.config";
  }
  return folder + "/isurface/settings.json";
}

Settings loadSettings(const std::string& path) {
  Settings settings;
  if (path.empty()) return settings;
  std::string text;
  try {
    // Only a regular file of settings' size: a FIFO or /dev/zero put in its place must not hang
    // or kill the window's start; the defaults are used instead.
    text = readBoundedFile(path, BoundedRead{1 << 20, "settings file", true});
  } catch (const InputError&) {
    return settings;
  }
  return settingsFromText(text);
}

Settings settingsFromText(const std::string& text) {
  Settings settings;
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!json.is_object()) return settings;

  const auto recent = json.find("recent_files");
  if (recent != json.end() && recent->is_array()) {
    // Added oldest first so that the newest ends up in front, duplicates and the cap applied.
    for (auto it = recent->rbegin(); it != recent->rend(); ++it)
      if (it->is_string()) settings.addRecent(it->get<std::string>());
  }
  readString(json, "quantity", settings.quantity);
  readString(json, "color_map", settings.colorMap);
  readWindowSide(json, "window_width", settings.windowWidth);
  readWindowSide(json, "window_height", settings.windowHeight);
  std::string theme, units;
  readString(json, "theme", theme);
  if (theme == "dark" || theme == "light") settings.theme = theme;
  readString(json, "units", units);
  if (units == "auto" || units == "mm" || units == "inch") settings.units = units;
  // A machine that no longer reads as one (edited by hand, an older version's) is left out.
  const auto machines = json.find("program_machines");
  if (machines != json.end() && machines->is_array())
    for (auto it = machines->rbegin(); it != machines->rend(); ++it) {
      if (!it->is_object() || !it->contains("program") || !(*it)["program"].is_string() || !it->contains("machine") ||
          !(*it)["machine"].is_object())
        continue;
      try {
        const Machine m = parseMachine(jsonText((*it)["machine"]), "settings");
        settings.rememberMachine((*it)["program"].get<std::string>(), machineDescriptionJson(m));
      } catch (const InputError&) {
      }
    }
  const auto scale = json.find("ui_scale");
  if (scale != json.end() && scale->is_number() && scale->get<double>() >= 1.0 && scale->get<double>() <= 2.0) {
    settings.uiScale = scale->get<float>();
    settings.uiScaleChosen = true;
  }
  return settings;
}

float uiScaleForScreen(int pixelsWide, int millimetresWide, float contentScale) {
  constexpr double kMillimetresPerInch = 25.4, kUsualDensity = 96;  // pixels an inch
  double scale = std::isfinite(contentScale) && contentScale > 0 ? contentScale : 1.0;
  if (pixelsWide > 0 && millimetresWide > 0)
    scale = std::max(scale, pixelsWide / (millimetresWide / kMillimetresPerInch) / kUsualDensity);
  return static_cast<float>(std::clamp(std::round(scale * 4) / 4, 1.0, 2.0));
}

std::string settingsText(const Settings& settings) {
  nlohmann::json json = {
      {"recent_files", settings.recentFiles},
      {"quantity", settings.quantity},
      {"color_map", settings.colorMap},
      {"window_width", settings.windowWidth},
      {"window_height", settings.windowHeight},
      {"theme", settings.theme},
      {"units", settings.units},
  };
  // A size the screen set is not remembered as the user's: another screen sets its own.
  if (settings.uiScaleChosen) json["ui_scale"] = settings.uiScale;
  if (!settings.programMachines.empty()) {
    nlohmann::json machines = nlohmann::json::array();
    for (const auto& [program, machine] : settings.programMachines)
      machines.push_back({{"program", program}, {"machine", nlohmann::json::parse(machine, nullptr, false)}});
    json["program_machines"] = machines;
  }
  // Invalid UTF-8 in a path is replaced rather than thrown: the rest still gets saved.
  return jsonText(json, 2) + "\n";
}

bool saveSettings(const Settings& settings, const std::string& path) {
  if (path.empty()) return false;
  try {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    writeFileAtomically(path, settingsText(settings));
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace isurface::app_model
