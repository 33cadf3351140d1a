#pragma once
// JSON as text, for every JSON this project writes. A string that is not UTF-8 (a file name in
// another encoding, a comment of a program) cannot be written as JSON as it is: nlohmann's
// dump() throws then. Its invalid bytes are written as U+FFFD instead, so that a file whose name
// is not UTF-8 is still named, and no output fails on it.
#include <string>

namespace isurface {

// `json` (an nlohmann::json or ordered_json) as text; indent < 0: one line.
template <class Json>
std::string jsonText(const Json& json, int indent = -1) {
  return json.dump(indent, ' ', false, Json::error_handler_t::replace);
}

}  // namespace isurface
