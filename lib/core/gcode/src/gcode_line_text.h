#pragma once
// Reading a line's text before it is lexed: blanks, and the N word a statement may follow.
// Private to the gcode module.
#include <cctype>

namespace isurface::gcode {

inline bool isLineBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

inline const char* skipLineBlanks(const char* p, const char* end) {
  while (p < end && isLineBlank(*p)) ++p;
  return p;
}

// Past blanks, an N word (a block number) and the blanks after it: where an O word or a Fanuc
// macro statement stands.
inline const char* pastBlockNumber(const char* p, const char* end) {
  p = skipLineBlanks(p, end);
  if (p < end && (*p == 'N' || *p == 'n')) {
    ++p;
    while (p < end && (std::isdigit(static_cast<unsigned char>(*p)) || isLineBlank(*p) || *p == '.')) ++p;
  }
  return skipLineBlanks(p, end);
}

}  // namespace isurface::gcode
