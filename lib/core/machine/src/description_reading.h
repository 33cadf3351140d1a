#pragma once
// Reading a machine description's JSON: numbers, positions and keys checked, every mistake an
// InputError naming the file and the key.
#include <initializer_list>
#include <string>

#include <nlohmann/json.hpp>

#include "isurface/base/diagnostic.h"
#include "isurface/base/geometry.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace isurface::description_reading {

using nlohmann::json;

[[noreturn]] inline void fail(const std::string& source, const std::string& message) {
  throw InputError(Diagnostic{source, 0, 0, message});
}

inline double number(const json& object, const char* key, double fallback, const std::string& source,
              const std::string& where) {
  if (!object.contains(key)) return fallback;
  const json& value = object.at(key);
  if (!value.is_number()) fail(source, where + key + " must be a number");
  const double v = value.get<double>();
  if (!std::isfinite(v)) fail(source, where + key + " must be finite");
  return v;
}

inline void requirePositive(double value, const std::string& source, const std::string& key) {
  if (!(value > 0)) fail(source, key + " must be greater than 0 (got " + std::to_string(value) + ")");
}

// A point or direction: an array of three finite numbers named where + key.
inline Vec3 position(const json& object, const char* key, const Vec3& fallback, const std::string& source,
                     const std::string& where = "reference_positions_mm.") {
  if (!object.contains(key)) return fallback;
  const json& value = object.at(key);
  if (!value.is_array() || value.size() != 3) fail(source, where + key + " must be an array of 3 numbers");
  Vec3 p;
  for (int i = 0; i < 3; ++i) {
    if (!value[i].is_number()) fail(source, where + key + " must hold numbers");
    p[i] = value[i].get<double>();
    if (!std::isfinite(p[i])) fail(source, where + key + " must be finite");
  }
  return p;
}

// Edits (insertions, deletions, substitutions) that turn a into b.
inline std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// A misspelled key would leave its limit at the default without a word: every key must be one
// this description knows. Notes may stand in "comment", "description" and keys starting "_".
inline void rejectUnknownKeys(const json& object, std::initializer_list<const char*> known, const std::string& where,
                       const std::string& source) {
  for (const auto& item : object.items()) {
    const std::string& key = item.key();
    if (key == "comment" || key == "description" || (!key.empty() && key[0] == '_')) continue;
    const char* nearest = nullptr;
    std::size_t best = 3;  // suggest only a close key
    bool found = false;
    for (const char* k : known) {
      if (key == k) found = true;
      const std::size_t d = editDistance(key, k);
      if (d < best) best = d, nearest = k;
    }
    if (found) continue;
    std::string list;
    for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
    fail(source, "unknown key \"" + where + key + "\"" +
                     (nearest ? std::string(" (did you mean \"") + where + nearest + "\"?)" : std::string()) +
                     "; the keys here are " + list);
  }
}

}  // namespace isurface::description_reading
