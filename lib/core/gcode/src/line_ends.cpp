#include "isurface/gcode/line_ends.h"

#include <cstring>

namespace isurface {

bool hasLoneCarriageReturn(std::string_view text) {
  const char* p = text.data();
  const char* const end = p + text.size();
  while (p < end) {
    const void* cr = std::memchr(p, '\r', static_cast<std::size_t>(end - p));
    if (!cr) return false;
    p = static_cast<const char*>(cr) + 1;
    if (p == end || *p != '\n') return true;
  }
  return false;
}

std::string withLineFeeds(std::string_view text) {
  std::string out(text);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (out[i] == '\r' && (i + 1 == out.size() || out[i + 1] != '\n')) out[i] = '\n';
  return out;
}

}  // namespace isurface
