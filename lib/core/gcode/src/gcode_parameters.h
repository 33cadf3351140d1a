#pragma once
// RS274/NGC parameters as LinuxCNC reads them: numbered #1..#5602 (0 until set; the system's
// #5211-#5219 and #5420-#5428 read what the interpreter says), named locals
// #<name> and globals #<_name> (an error until set). Assignments on a line are staged and take
// effect together after the block, as the standard says: every read on the line sees the values
// from before it. Private to the gcode module.
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <functional>
#include <vector>

namespace isurface::gcode {

constexpr int kMaxNumberedParameter = 5602;

// A parameter named on a line: a number, or a name (lower case, blanks removed).
struct ParameterRef {
  int number = 0;
  std::string name;  // empty for a numbered parameter
};

class Parameters {
 public:
  Parameters();

  // The value of a numbered parameter; false and a message when the number is out of range.
  bool read(int number, double& value, std::string& message) const;
  // The value of a named parameter; false and a message when it was never set.
  bool read(const std::string& name, double& value, std::string& message) const;
  bool exists(const std::string& name) const;

  // Parameters the interpreter keeps itself (the position, the G92 offset): given a number,
  // true and its value, or false when the number is not one of them.
  using SystemReader = std::function<bool(int number, double& value)>;
  void setSystemReader(SystemReader reader) { system_ = std::move(reader); }

  // Sets at once (a call's arguments, a subroutine's return value).
  void set(int number, double value) { numbered_[static_cast<std::size_t>(number)] = value; }
  void set(const std::string& name, double value) { named_[name] = value; }

  // A subroutine call's own parameters: #1..#30 and the named locals (names without a leading
  // '_') are saved, cleared for the call and restored at its return.
  static constexpr int kCallParameters = 30;

  // Fanuc macro B: a setting's value is an expression without brackets (#3 = #1 + #2).
  bool bareSettings = false;
  void pushScope();
  void popScope();

  // Staged until commit(); a later stage of the same parameter on the line wins.
  void stage(ParameterRef ref, double value) { staged_.emplace_back(std::move(ref), value); }
  void commit();
  void discardStaged() { staged_.clear(); }
  bool hasStaged() const { return !staged_.empty(); }

 private:
  std::vector<double> numbered_;
  SystemReader system_;
  std::unordered_map<std::string, double> named_;
  std::vector<std::pair<ParameterRef, double>> staged_;
  struct Scope {
    std::vector<double> numbered;  // #1..#30
    std::unordered_map<std::string, double> locals;
  };
  std::vector<Scope> scopes_;
};

// Reads a real value where a word's number stands: a number, `[expression]`, a parameter
// (`#1`, `##1`, `#[1+2]`, `#<name>`), a unary function (`SIN[30]`, `ATAN[1]/[2]`,
// `EXISTS[#<name>]`), each with an optional sign. Advances `p` past it and trailing blanks.
// Returns false with a message on bad syntax, an undefined parameter or a domain error.
bool readRealValue(const char*& p, const char* end, const Parameters& parameters, double& value,
                   std::string& message);

// Reads what a Fanuc setting assigns: operands and operators up to the end of the line or a
// comment, without brackets around them (`#1 + 2 * #3`).
bool readBareExpression(const char*& p, const char* end, const Parameters& parameters, double& value,
                        std::string& message);

// Reads a parameter reference after its '#' (`1`, `[expr]`, `#1`, `<name>`); `p` points past
// the '#'. Returns false with a message when it is malformed or out of range.
bool readParameterRef(const char*& p, const char* end, const Parameters& parameters, ParameterRef& ref,
                      std::string& message);

}  // namespace isurface::gcode
