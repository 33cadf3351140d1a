#pragma once
// A machine description's "kinematics": its five-axis structure, rotary axes and tool length.
#include <string>

#include <nlohmann/json.hpp>

#include "isurface/kinematics/five_axis.h"

namespace isurface {

// Throws InputError naming the key for anything missing, unknown or impossible.
FiveAxisKinematics readKinematics(const nlohmann::json& description, const std::string& source);
nlohmann::ordered_json kinematicsJson(const FiveAxisKinematics& k);

}  // namespace isurface
