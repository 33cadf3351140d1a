// RS274/NGC parameters and expressions, with LinuxCNC's operators, precedence and functions.
#include "gcode_parameters.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "isurface/base/units.h"

namespace isurface::gcode {

namespace {

constexpr double kDegree = kPi / 180.0;
// A parameter number or a comparison operand within this of a whole number counts as one.
constexpr double kWholeTolerance = 1e-4;
// Nesting of brackets and indirect parameters: deeper is a mistake, not a program.
constexpr int kMaxDepth = 64;

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

void skipBlanks(const char*& p, const char* end) {
  while (p < end && isBlank(*p)) ++p;
}

// Case-insensitive match of a keyword at p (blanks inside a keyword are not allowed here).
bool matchWord(const char* p, const char* end, const char* word) {
  const std::size_t n = std::strlen(word);
  if (static_cast<std::size_t>(end - p) < n) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(p[i])) != word[i]) return false;
  return true;
}

enum class Op { None, Power, Times, Divide, Mod, Plus, Minus, Eq, Ne, Gt, Ge, Lt, Le, And, Or, Xor };

int precedence(Op op) {
  switch (op) {
    case Op::Power: return 5;
    case Op::Times: case Op::Divide: case Op::Mod: return 4;
    case Op::Plus: case Op::Minus: return 3;
    case Op::Eq: case Op::Ne: case Op::Gt: case Op::Ge: case Op::Lt: case Op::Le: return 2;
    case Op::And: case Op::Or: case Op::Xor: return 1;
    case Op::None: return 0;
  }
  return 0;
}

// The binary operator at p, advancing past it; Op::None when there is none.
Op readOperator(const char*& p, const char* end) {
  skipBlanks(p, end);
  if (p >= end) return Op::None;
  if (p + 1 < end && p[0] == '*' && p[1] == '*') return p += 2, Op::Power;
  switch (*p) {
    case '*': return ++p, Op::Times;
    case '/': return ++p, Op::Divide;
    case '+': return ++p, Op::Plus;
    case '-': return ++p, Op::Minus;
    default: break;
  }
  static const struct {
    const char* word;
    Op op;
  } kWords[] = {{"mod", Op::Mod}, {"and", Op::And}, {"xor", Op::Xor}, {"or", Op::Or}, {"eq", Op::Eq},
                {"ne", Op::Ne},   {"gt", Op::Gt},   {"ge", Op::Ge},   {"lt", Op::Lt}, {"le", Op::Le}};
  for (const auto& w : kWords)
    if (matchWord(p, end, w.word)) return p += std::strlen(w.word), w.op;
  return Op::None;
}

bool apply(Op op, double a, double b, double& out, std::string& message) {
  switch (op) {
    case Op::Power:
      if (a < 0 && std::fabs(b - std::round(b)) > kWholeTolerance) {
        message = "Attempt to raise negative to non-integer power";
        return false;
      }
      out = std::pow(a, b);
      break;
    case Op::Times: out = a * b; break;
    case Op::Divide:
      if (b == 0) {
        message = "Attempt to divide by zero";
        return false;
      }
      out = a / b;
      break;
    case Op::Mod:
      if (b == 0) {
        message = "Attempt to divide by zero (MOD)";
        return false;
      }
      out = std::fmod(a, b);
      if (out < 0) out += std::fabs(b);  // LinuxCNC: the result has the sign of the divisor's magnitude
      break;
    case Op::Plus: out = a + b; break;
    case Op::Minus: out = a - b; break;
    case Op::Eq: out = std::fabs(a - b) < kWholeTolerance ? 1 : 0; break;
    case Op::Ne: out = std::fabs(a - b) >= kWholeTolerance ? 1 : 0; break;
    case Op::Gt: out = a > b ? 1 : 0; break;
    case Op::Ge: out = a >= b ? 1 : 0; break;
    case Op::Lt: out = a < b ? 1 : 0; break;
    case Op::Le: out = a <= b ? 1 : 0; break;
    case Op::And: out = (a != 0 && b != 0) ? 1 : 0; break;
    case Op::Or: out = (a != 0 || b != 0) ? 1 : 0; break;
    case Op::Xor: out = ((a != 0) != (b != 0)) ? 1 : 0; break;
    case Op::None: break;
  }
  if (!std::isfinite(out)) {
    message = "Expression result is not a finite number";
    return false;
  }
  return true;
}

class Reader {
 public:
  Reader(const char*& p, const char* end, const Parameters& parameters, std::string& message)
      : p_(p), end_(end), parameters_(parameters), message_(message) {}

  bool realValue(double& value) {
    if (++depth_ > kMaxDepth) return fail("Expression nested too deeply");
    skipBlanks(p_, end_);
    bool negative = false;
    while (p_ < end_ && (*p_ == '-' || *p_ == '+')) {
      negative ^= *p_ == '-';
      ++p_;
      skipBlanks(p_, end_);
    }
    bool ok = false;
    if (p_ >= end_) ok = fail("Bad number format: a number is missing");
    else if (*p_ == '[') ok = expression(value);
    else if (*p_ == '#') ok = parameterValue(value);
    else if (std::isalpha(static_cast<unsigned char>(*p_))) ok = function(value);
    else ok = number(value);
    --depth_;
    if (!ok) return false;
    if (negative) value = -value;
    skipBlanks(p_, end_);
    return true;
  }

  // `[ a op b op c ... ]`, by precedence.
  bool expression(double& value) {
    ++p_;  // '['
    return binary(value, true);
  }

  // `a op b op c ...` up to ']' (bracketed) or to the end of the line or a comment.
  bool binary(double& value, bool bracketed) {
    std::vector<double> values;
    std::vector<Op> ops;
    double v = 0;
    if (!realValue(v)) return false;
    values.push_back(v);
    for (;;) {
      skipBlanks(p_, end_);
      if (bracketed && p_ >= end_) return fail("Unclosed expression (missing ']')");
      if (!bracketed && (p_ >= end_ || *p_ == '(' || *p_ == ';')) break;
      if (bracketed && *p_ == ']') {
        ++p_;
        break;
      }
      const Op op = readOperator(p_, end_);
      if (op == Op::None) return fail(fmt::format("Unknown operation in expression at '{}'", excerpt()));
      while (!ops.empty() && precedence(ops.back()) >= precedence(op))
        if (!reduce(values, ops)) return false;
      ops.push_back(op);
      if (!realValue(v)) return false;
      values.push_back(v);
    }
    while (!ops.empty())
      if (!reduce(values, ops)) return false;
    value = values.back();
    return true;
  }

  // `forExists`: a number out of range is no parameter (number -1), not an error, as
  // LinuxCNC's EXISTS[#99999] is 0.
  bool parameterRef(ParameterRef& ref, bool forExists = false) {
    skipBlanks(p_, end_);
    if (p_ < end_ && *p_ == '<') {
      const char* close = static_cast<const char*>(std::memchr(p_, '>', static_cast<std::size_t>(end_ - p_)));
      if (!close) return fail("Unclosed parameter name (missing '>')");
      std::string name;
      for (const char* q = p_ + 1; q < close; ++q)
        if (!isBlank(*q)) name += static_cast<char>(std::tolower(static_cast<unsigned char>(*q)));
      if (name.empty()) return fail("Empty parameter name");
      p_ = close + 1;
      ref = ParameterRef{0, std::move(name)};
      return true;
    }
    double index = 0;
    if (!realValue(index)) return false;
    const double whole = std::round(index);
    if (std::fabs(index - whole) > kWholeTolerance) return fail(fmt::format("Parameter number {:g} is not an integer", index));
    if ((whole < 1 || whole > kMaxNumberedParameter) && forExists) {
      ref = ParameterRef{-1, {}};
      return true;
    }
    if (whole < 1 || whole > kMaxNumberedParameter)
      return fail(fmt::format("Parameter number {:g} out of range (1-{})", whole, kMaxNumberedParameter));
    ref = ParameterRef{static_cast<int>(whole), {}};
    return true;
  }

 private:
  bool fail(std::string message) {
    message_ = std::move(message);
    return false;
  }

  std::string excerpt() const { return std::string(p_, p_ + std::min<std::ptrdiff_t>(end_ - p_, 12)); }

  bool reduce(std::vector<double>& values, std::vector<Op>& ops) {
    const double b = values.back();
    values.pop_back();
    double out = 0;
    if (!apply(ops.back(), values.back(), b, out, message_)) return false;
    values.back() = out;
    ops.pop_back();
    return true;
  }

  bool parameterValue(double& value) {
    ++p_;  // '#'
    ParameterRef ref;
    if (!parameterRef(ref)) return false;
    return ref.name.empty() ? parameters_.read(ref.number, value, message_) : parameters_.read(ref.name, value, message_);
  }

  bool number(double& value) {
    char buffer[64];
    std::size_t n = 0;
    bool dot = false, digits = false;
    for (; p_ < end_; ++p_) {
      const char c = *p_;
      if (isBlank(c)) continue;
      if (c == '.' && !dot) dot = true;
      else if (std::isdigit(static_cast<unsigned char>(c))) digits = true;
      else break;
      if (n + 1 >= sizeof buffer) return fail("Number too long");
      buffer[n++] = c;
    }
    buffer[n] = 0;
    if (!digits) return fail(n ? "Bad number format" : "Bad number format: a number is missing");
    value = std::strtod(buffer, nullptr);
    return true;
  }

  bool bracketed(double& value) {
    skipBlanks(p_, end_);
    if (p_ >= end_ || *p_ != '[') return fail("Left bracket missing after a function name");
    return expression(value);
  }

  bool function(double& value) {
    static const char* const kNames[] = {"exists", "round", "acos", "asin", "atan", "sqrt", "abs", "cos", "exp",
                                         "fix",    "fup",   "sin",  "tan",  "ln"};
    const char* name = nullptr;
    for (const char* n : kNames)
      if (matchWord(p_, end_, n)) {
        name = n;
        break;
      }
    if (!name) return fail(fmt::format("Unknown function or word in an expression at '{}'", excerpt()));
    p_ += std::strlen(name);
    const std::string f = name;
    if (f == "exists") {
      skipBlanks(p_, end_);
      if (p_ + 1 >= end_ || p_[0] != '[') return fail("EXISTS takes [#<name>]");
      ++p_;
      skipBlanks(p_, end_);
      if (p_ >= end_ || *p_ != '#') return fail("EXISTS takes [#<name>]");
      ++p_;
      ParameterRef ref;
      if (!parameterRef(ref, /*forExists=*/true)) return false;
      skipBlanks(p_, end_);
      if (p_ >= end_ || *p_ != ']') return fail("Unclosed expression (missing ']')");
      ++p_;
      value = ref.name.empty() ? (ref.number > 0 ? 1.0 : 0.0) : (parameters_.exists(ref.name) ? 1.0 : 0.0);
      return true;
    }
    double a = 0;
    if (!bracketed(a)) return false;
    if (f == "atan") {
      skipBlanks(p_, end_);
      if (p_ >= end_ || *p_ != '/') return fail("ATAN takes two arguments: ATAN[y]/[x]");
      ++p_;
      double b = 0;
      if (!bracketed(b)) return false;
      value = std::atan2(a, b) / kDegree;
      return true;
    }
    if ((f == "asin" || f == "acos") && (a < -1 || a > 1)) return fail(fmt::format("Argument to {} out of range: {:g}", f, a));
    if (f == "sqrt" && a < 0) return fail("Attempt to take square root of negative number");
    if (f == "ln" && a <= 0) return fail("Zero or negative argument to LN");
    if (f == "abs") value = std::fabs(a);
    else if (f == "acos") value = std::acos(a) / kDegree;
    else if (f == "asin") value = std::asin(a) / kDegree;
    else if (f == "cos") value = std::cos(a * kDegree);
    else if (f == "sin") value = std::sin(a * kDegree);
    else if (f == "tan") value = std::tan(a * kDegree);
    else if (f == "exp") value = std::exp(a);
    else if (f == "fix") value = std::floor(a);
    else if (f == "fup") value = std::ceil(a);
    else if (f == "ln") value = std::log(a);
    else if (f == "round") value = std::round(a);  // halves away from zero, as LinuxCNC
    else value = std::sqrt(a);
    if (!std::isfinite(value)) return fail("Expression result is not a finite number");
    return true;
  }

  const char*& p_;
  const char* end_;
  const Parameters& parameters_;
  std::string& message_;
  int depth_ = 0;
};

}  // namespace

Parameters::Parameters() : numbered_(kMaxNumberedParameter + 1, 0.0) {}

bool Parameters::read(int number, double& value, std::string& message) const {
  if (number < 1 || number > kMaxNumberedParameter) {
    message = fmt::format("Parameter number {} out of range (1-{})", number, kMaxNumberedParameter);
    return false;
  }
  if (system_ && system_(number, value)) return true;
  value = numbered_[static_cast<std::size_t>(number)];
  return true;
}

bool Parameters::read(const std::string& name, double& value, std::string& message) const {
  const auto it = named_.find(name);
  if (it == named_.end()) {
    message = fmt::format("Named parameter #<{}> not defined", name);
    return false;
  }
  value = it->second;
  return true;
}

bool Parameters::exists(const std::string& name) const { return named_.count(name) != 0; }

void Parameters::pushScope() {
  Scope saved;
  saved.numbered.assign(numbered_.begin() + 1, numbered_.begin() + 1 + kCallParameters);
  for (auto it = named_.begin(); it != named_.end();) {
    if (it->first.front() != '_') {
      saved.locals.insert(*it);
      it = named_.erase(it);
    } else {
      ++it;
    }
  }
  std::fill(numbered_.begin() + 1, numbered_.begin() + 1 + kCallParameters, 0.0);
  scopes_.push_back(std::move(saved));
}

void Parameters::popScope() {
  if (scopes_.empty()) return;
  Scope& saved = scopes_.back();
  std::copy(saved.numbered.begin(), saved.numbered.end(), numbered_.begin() + 1);
  for (auto it = named_.begin(); it != named_.end();) it = it->first.front() != '_' ? named_.erase(it) : std::next(it);
  named_.insert(saved.locals.begin(), saved.locals.end());
  scopes_.pop_back();
}

void Parameters::commit() {
  for (auto& [ref, value] : staged_) {
    if (ref.name.empty()) numbered_[static_cast<std::size_t>(ref.number)] = value;
    else named_[ref.name] = value;
  }
  staged_.clear();
}

bool readRealValue(const char*& p, const char* end, const Parameters& parameters, double& value, std::string& message) {
  return Reader(p, end, parameters, message).realValue(value);
}

bool readBareExpression(const char*& p, const char* end, const Parameters& parameters, double& value,
                        std::string& message) {
  return Reader(p, end, parameters, message).binary(value, false);
}

bool readParameterRef(const char*& p, const char* end, const Parameters& parameters, ParameterRef& ref,
                      std::string& message) {
  return Reader(p, end, parameters, message).parameterRef(ref);
}

}  // namespace isurface::gcode
