#include "isurface/base/line_range.h"

#include "isurface/base/diagnostic.h"

namespace isurface {

namespace {

[[noreturn]] void badRange(const std::string& message) { throw InputError(Diagnostic{"", 0, 0, message}); }

}  // namespace

LineRange parseLineRange(const std::string& text) {
  const auto number = [&](const std::string& part) -> std::uint32_t {
    if (part.empty() || part.size() > 9 || part.find_first_not_of("0123456789") != std::string::npos)
      badRange("line range must be A-B with 1-based line numbers, got '" + text + "'");
    return static_cast<std::uint32_t>(std::stoul(part));
  };
  const std::size_t dash = text.find('-');
  LineRange r;
  r.first = number(text.substr(0, dash));
  r.last = dash == std::string::npos ? r.first : number(text.substr(dash + 1));
  if (r.first == 0) badRange("line numbers start at 1, got '" + text + "'");
  if (r.first > r.last) badRange("line range '" + text + "' ends before it starts");
  return r;
}

}  // namespace isurface
