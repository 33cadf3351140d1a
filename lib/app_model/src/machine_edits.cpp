#include "isurface/app_model/machine_edits.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace isurface::app_model {

namespace {

using nlohmann::json;

constexpr const char* kEditedMark = " (edited: ";
constexpr const char* kMore = " and more";
constexpr std::size_t kNamedChanges = 4;  // listed in the name

// Every value of a description by its dotted path ("axes.x.max_velocity_mm_min").
void flatten(const json& value, const std::string& path, std::vector<std::pair<std::string, json>>& out) {
  if (value.is_object()) {
    for (const auto& [key, item] : value.items()) flatten(item, path.empty() ? key : path + "." + key, out);
    return;
  }
  out.emplace_back(path, value);
}

std::vector<std::pair<std::string, json>> flattened(const Machine& m) {
  std::vector<std::pair<std::string, json>> out;
  flatten(json::parse(machineDescriptionJson(m)), "", out);
  return out;
}

// The paths whose values differ (or are in one description only), in the description's order.
std::vector<std::string> differences(const Machine& a, const Machine& b) {
  const auto one = flattened(a), other = flattened(b);
  std::vector<std::string> paths;
  auto note = [&](const std::string& path) {
    if (path != "name" && std::find(paths.begin(), paths.end(), path) == paths.end()) paths.push_back(path);
  };
  // Pairs, not structured bindings: C++17 lambdas cannot capture those (clang refuses it).
  for (const auto& entry : one) {
    const std::string& path = entry.first;
    const auto match = std::find_if(other.begin(), other.end(), [&](const auto& p) { return p.first == path; });
    if (match == other.end() || match->second != entry.second) note(path);
  }
  for (const auto& entry : other) {
    const std::string& path = entry.first;
    if (std::none_of(one.begin(), one.end(), [&](const auto& p) { return p.first == path; })) note(path);
  }
  return paths;
}

// What a user calls the value at a description's path: "X acceleration" for
// axes.x.max_acceleration_mm_s2, "chord smoothing" for control.chord_smoothing.
std::string label(const std::string& path) {
  static const std::pair<const char*, const char*> kNames[] = {
      {"max_velocity_mm_min", "velocity"},       {"max_acceleration_mm_s2", "acceleration"},
      {"max_jerk_mm_s3", "jerk"},                {"position_gain_1_s", "position gain"},
      {"velocity_feed_forward", "feed-forward"}, {"velocity_loop_time_constant_s", "velocity loop lag"},
      {"cycle_s", "cycle"},                      {"rapid_mm_min", "rapid"},
      {"chord_tolerance_mm", "chord tolerance"}, {"acceleration_rise_time_s", "acceleration rise time"}};
  const std::size_t dot = path.rfind('.');
  const std::string key = dot == std::string::npos ? path : path.substr(dot + 1);
  std::string name = key;
  for (const auto& [k, n] : kNames)
    if (key == k) name = n;
  std::replace(name.begin(), name.end(), '_', ' ');
  // axes.x.<key>: the axis first, in capitals.
  if (path.rfind("axes.", 0) == 0 && dot == 6) return std::string(1, static_cast<char>(std::toupper(path[5]))) + " " + name;
  return name;
}

// The name before its edits, the edits it lists and whether it has more.
struct EditedName {
  std::string base;
  std::vector<std::string> listed;
  bool more = false;
};

EditedName parse(const std::string& name) {
  EditedName n{name, {}, false};
  const std::size_t mark = name.rfind(kEditedMark);
  if (mark == std::string::npos || name.empty() || name.back() != ')') return n;
  n.base = name.substr(0, mark);
  std::string list = name.substr(mark + std::char_traits<char>::length(kEditedMark));
  list.pop_back();
  const std::size_t more = std::char_traits<char>::length(kMore);
  if (list.size() >= more && list.compare(list.size() - more, more, kMore) == 0) {
    n.more = true;
    list.erase(list.size() - more);
  }
  for (std::size_t from = 0; from <= list.size();) {
    const std::size_t comma = list.find(", ", from);
    const std::string item = list.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
    if (!item.empty()) n.listed.push_back(item);
    if (comma == std::string::npos) break;
    from = comma + 2;
  }
  return n;
}

}  // namespace

Machine namedAfterEdits(Machine edited, const Machine& original) {
  if (edited.name != original.name) return edited;
  const std::vector<std::string> changed = differences(edited, original);
  if (changed.empty()) return edited;
  EditedName name = parse(original.name);
  std::vector<std::string> all = name.listed;
  for (const std::string& path : changed)
    if (std::find(all.begin(), all.end(), label(path)) == all.end()) all.push_back(label(path));
  std::string list;
  for (std::size_t k = 0; k < all.size() && k < kNamedChanges; ++k) list += (k ? ", " : "") + all[k];
  if (name.more || all.size() > kNamedChanges) list += kMore;
  edited.name = name.base + kEditedMark + list + ")";
  return edited;
}

}  // namespace isurface::app_model
