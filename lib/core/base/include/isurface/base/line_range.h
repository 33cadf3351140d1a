#pragma once
// A range of G-code source lines, as users name them ("A-B").
#include <cstdint>
#include <string>

namespace isurface {

// 1-based source lines, inclusive.
struct LineRange {
  std::uint32_t first = 1, last = 0;
  bool contains(std::uint32_t line) const { return line >= first && line <= last; }
};

// Parses "A-B" (or "A" for one line); malformed text, zero or A > B throw InputError.
LineRange parseLineRange(const std::string& text);

}  // namespace isurface
