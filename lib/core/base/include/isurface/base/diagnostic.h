#pragma once
// Errors and warnings about user input, located in a file as `file:line:column: message`.
#include <stdexcept>
#include <string>

namespace isurface {

struct Diagnostic {
  std::string file;     // as the user named it
  unsigned line = 0;    // 1-based physical line, 0 when the problem is not on a line
  unsigned column = 0;  // 1-based column, 0 when unknown
  std::string message;

  std::string str() const;  // "file:line:column: message", omitting parts that are 0
};

// Thrown for bad input (malformed G-code, damaged Biip file, impossible parameters).
// Commands turn it into a message on stderr and exit code 2.
class InputError : public std::runtime_error {
 public:
  explicit InputError(Diagnostic d) : std::runtime_error(d.str()), diag_(std::move(d)) {}
  const Diagnostic& diagnostic() const { return diag_; }

 private:
  Diagnostic diag_;
};

}  // namespace isurface
