#include "isurface/base/diagnostic.h"

#include <cstdio>

namespace isurface {

namespace {

// Control bytes from the input (a NUL, an escape sequence) are shown, not passed on: a NUL
// would end the message where C strings end, and an escape could rewrite the user's terminal.
void appendPrintable(std::string& out, const std::string& text) {
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      out += c;
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out += escaped;
    }
  }
}

}  // namespace

std::string Diagnostic::str() const {
  std::string out;
  appendPrintable(out, file.empty() ? std::string("<input>") : file);
  if (line > 0) {
    out += ':' + std::to_string(line);
    if (column > 0) out += ':' + std::to_string(column);
  }
  out += ": ";
  appendPrintable(out, message);
  return out;
}

}  // namespace isurface
