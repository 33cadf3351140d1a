#pragma once
// JSON written by the commands: fields in the order they are set, no NaN (JSON has none).
#include <cmath>

#include <nlohmann/json.hpp>

#include "isurface/base/geometry.h"

namespace isurface::cli {

using Json = nlohmann::ordered_json;

// A number, or null when it is not finite.
inline Json numberOrNull(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

// [x, y, z], each as numberOrNull.
inline Json triple(const Vec3& v) { return Json::array({numberOrNull(v.x()), numberOrNull(v.y()), numberOrNull(v.z())}); }

}  // namespace isurface::cli
