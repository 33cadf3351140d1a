// Words, numbers and comments of one RS274/NGC block.
#include "gcode_lexer.h"

#include <fast_float/fast_float.h>
#include <fmt/format.h>

#include <cmath>
#include <cstring>

#include "gcode_parameters.h"
#include "isurface/base/tolerances.h"

namespace isurface::gcode {

namespace {

// Character classes, looked up once per character.
enum : std::uint8_t { kOther = 0, kBlank, kDigit, kLetter, kDot, kSign };

struct CharTable {
  std::uint8_t cls[256];
  constexpr CharTable() : cls() {
    for (int c = 0; c < 256; ++c) cls[c] = kOther;
    cls[static_cast<unsigned char>(' ')] = kBlank;
    cls[static_cast<unsigned char>('\t')] = kBlank;
    cls[static_cast<unsigned char>('\r')] = kBlank;
    cls[static_cast<unsigned char>('\f')] = kBlank;
    cls[static_cast<unsigned char>('\v')] = kBlank;
    for (int c = '0'; c <= '9'; ++c) cls[c] = kDigit;
    for (int c = 'a'; c <= 'z'; ++c) cls[c] = kLetter;
    for (int c = 'A'; c <= 'Z'; ++c) cls[c] = kLetter;
    cls[static_cast<unsigned char>('.')] = kDot;
    cls[static_cast<unsigned char>('+')] = kSign;
    cls[static_cast<unsigned char>('-')] = kSign;
  }
};
constexpr CharTable kChars;

inline std::uint8_t classOf(char c) { return kChars.cls[static_cast<unsigned char>(c)]; }

constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                             1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                             1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// Any number beyond this magnitude is a mistake in a G-code program (1000 km in mm).
constexpr double kMaxMagnitude = 1e9;
constexpr std::size_t kMaxNumberChars = 400;

// The letters that start a word. E, U, V, W are not supported here.
constexpr std::uint32_t kWordLetters =
    letterBit('A') | letterBit('B') | letterBit('C') | letterBit('D') | letterBit('F') |
    letterBit('G') | letterBit('H') | letterBit('I') | letterBit('J') | letterBit('K') |
    letterBit('L') | letterBit('M') | letterBit('N') | letterBit('O') | letterBit('P') |
    letterBit('Q') | letterBit('R') | letterBit('S') | letterBit('T') | letterBit('X') |
    letterBit('Y') | letterBit('Z');

std::string showChar(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return fmt::format("'{}'", c);
  return fmt::format("'\\x{:02x}'", u);
}

inline std::uint32_t columnOf(const char* begin, const char* p) {
  const auto d = static_cast<std::size_t>(p - begin) + 1;
  return d > 0xffffffffu ? 0xffffffffu : static_cast<std::uint32_t>(d);
}

// The written text of a bad number, for the message: sign, digits, dots and blanks.
std::string numberText(const char* start, const char* end) {
  std::string text;
  for (const char* p = start; p < end && text.size() < 40; ++p) {
    const auto k = classOf(*p);
    if (k == kDigit || k == kDot || k == kSign) text += *p;
    else if (k != kBlank) break;
  }
  return text;
}

bool slowParse(const char* start, const char* end, double& value) {
  char buffer[kMaxNumberChars + 2];
  std::size_t n = 0;
  for (const char* p = start; p < end; ++p) {
    const auto k = classOf(*p);
    if (k == kBlank) continue;
    if (k != kDigit && k != kDot && k != kSign) break;
    if (n >= kMaxNumberChars) return false;
    buffer[n++] = *p;
  }
  const char* first = buffer;
  if (n > 0 && buffer[0] == '+') ++first;  // fast_float does not take a leading '+'
  double v = 0;
  const auto r = fast_float::from_chars(first, buffer + n, v, fast_float::chars_format::fixed);
  if (r.ec != std::errc() || r.ptr != buffer + n) return false;
  value = v;
  return true;
}

}  // namespace

namespace {

// The common case: [sign] digits [. digits], at most 15 digits in all, not followed by more of
// the number after blanks. Returns false to leave the number to the general parser.
inline bool parseSimpleNumber(const char*& p, const char* end, double& value) {
  const char* q = p;
  bool negative = false;
  if (q < end && (*q == '-' || *q == '+')) {
    negative = *q == '-';
    ++q;
  }
  std::uint64_t mantissa = 0;
  const char* const intStart = q;
  while (q < end && static_cast<unsigned>(*q - '0') < 10u) mantissa = mantissa * 10 + static_cast<unsigned>(*q++ - '0');
  std::ptrdiff_t digits = q - intStart;
  if (digits > 9) return false;  // may exceed kMaxMagnitude
  std::ptrdiff_t fraction = 0;
  if (q < end && *q == '.') {
    const char* const fracStart = ++q;
    while (q < end && static_cast<unsigned>(*q - '0') < 10u) mantissa = mantissa * 10 + static_cast<unsigned>(*q++ - '0');
    fraction = q - fracStart;
    digits += fraction;
  }
  if (digits == 0 || digits > 15) return false;
  while (q < end && classOf(*q) == kBlank) ++q;
  if (q < end) {
    const auto k = classOf(*q);
    if (k == kDigit || k == kDot || k == kSign) return false;
  }
  // Both operands are exact doubles: one correctly rounded division.
  double v = fraction ? static_cast<double>(mantissa) / kPow10[fraction] : static_cast<double>(mantissa);
  value = negative ? -v : v;
  p = q;
  return true;
}

}  // namespace

bool parseNumber(const char*& p, const char* end, double& value, std::string* message) {
  if (parseSimpleNumber(p, end, value)) return true;
  const char* const start = p;
  while (p < end && classOf(*p) == kBlank) ++p;
  bool negative = false;
  if (p < end && classOf(*p) == kSign) {
    negative = *p == '-';
    ++p;
  }
  std::uint64_t mantissa = 0;
  int significant = 0, fraction = 0;
  bool dot = false, digits = false, exact = true;
  for (; p < end; ++p) {
    const char c = *p;
    const auto k = classOf(c);
    if (k == kDigit) {
      digits = true;
      const unsigned d = static_cast<unsigned>(c - '0');
      if (significant < 19) {
        if (mantissa != 0 || d != 0) {
          mantissa = mantissa * 10 + d;
          ++significant;
        }
        if (dot) ++fraction;
      } else {
        exact = false;
      }
    } else if (k == kDot) {
      if (dot) break;
      dot = true;
    } else if (k != kBlank) {
      break;
    }
  }
  if (!digits) {
    if (message) {
      const std::string text = numberText(start, end);
      *message = text.empty() ? std::string("Bad number format: a number is missing")
                              : fmt::format("Bad number format parsing '{}'", text);
    }
    return false;
  }
  if (p < end && (classOf(*p) == kDot || classOf(*p) == kSign)) {
    if (message)
      *message = fmt::format("Bad number format (trailing characters) parsing '{}'",
                             numberText(start, end));
    return false;
  }
  double v;
  if (exact && mantissa < (1ull << 53) && fraction <= 22) {
    // Both operands are exact doubles: one correctly rounded division.
    v = fraction ? static_cast<double>(mantissa) / kPow10[fraction] : static_cast<double>(mantissa);
    if (negative) v = -v;
  } else if (!slowParse(start, p, v)) {  // the syntax is right: too long or too large
    if (message) *message = fmt::format("Number out of range: '{}'", numberText(start, end));
    return false;
  }
  if (!std::isfinite(v) || std::fabs(v) > kMaxMagnitude) {
    if (message)
      *message = fmt::format("Number out of range: '{}'", numberText(start, end));
    return false;
  }
  value = v;
  return true;
}

namespace {

// A word's value that is not a plain number: a parameter, an expression or a function, maybe signed.
bool startsComputedValue(const char* p, const char* end) {
  while (p < end && (classOf(*p) == kBlank || classOf(*p) == kSign)) ++p;
  if (p >= end) return false;
  if (*p == '#' || *p == '[') return true;
  if (classOf(*p) != kLetter) return false;  // the common case: a number
  static const char* const kFunctions[] = {"exists", "round", "acos", "asin", "atan", "sqrt", "abs",
                                           "cos",    "exp",   "fix",  "fup",  "sin",  "tan",  "ln"};
  for (const char* f : kFunctions) {
    const std::size_t n = std::strlen(f);
    if (static_cast<std::size_t>(end - p) < n) continue;
    bool same = true;
    for (std::size_t i = 0; i < n && same; ++i) same = (p[i] | 0x20) == f[i];
    if (same) {
      const char* q = p + n;
      while (q < end && classOf(*q) == kBlank) ++q;
      if (q < end && *q == '[') return true;
    }
  }
  return false;
}

}  // namespace

namespace {

// A G or M code in tenths (G1 -> 10, G90.1 -> 901); codes that are not whole tenths get a value
// no table knows (-1).
inline int codeInTenths(double v) {
  const double tenths = v * 10.0;
  if (tenths >= 0 && tenths < 99999.5) {
    const int rounded = static_cast<int>(tenths + 0.5);
    if (std::fabs(tenths - rounded) <= kWholeNumberTolerance) return rounded;
  }
  return -1;
}

// Most blocks are only words of a letter and a plain number ([sign] digits [. digits]), blanks
// and comments: this reads those in one pass without the general lexer's checks for
// parameters, expressions and functions. Anything else (and any error) returns false, for the
// general lexer to read the block from its start, so that both give the same block and errors.
bool lexPlainBlock(const char* begin, const char* end, Block& block) {
  std::uint32_t present = 0;
  int gCount = 0, mCount = 0;
  const char* p = begin;
  while (p < end) {
    const char c = *p;
    if (classOf(c) != kLetter) {
      if (classOf(c) == kBlank) {
        ++p;
        continue;
      }
      if (c == ';') break;
      if (c != '(') return false;
      const char* q = p + 1;
      while (q < end && *q != ')' && *q != '(') ++q;
      if (q == end || *q == '(') return false;
      p = q + 1;
      continue;
    }
    const char upper = static_cast<char>(c & ~0x20);
    const int index = letterIndex(upper);
    if ((kWordLetters & (1u << index)) == 0 || upper == 'O') return false;
    const std::uint32_t col = columnOf(begin, p);
    ++p;
    // Only a digit or a point may follow the sign of a plain number: a parameter, an expression
    // or a function is left to the general lexer.
    double v;
    if (!parseSimpleNumber(p, end, v)) return false;
    if (upper == 'G') {
      if (gCount == kMaxGWords) return false;
      block.g[gCount] = codeInTenths(v);
      block.gValue[gCount] = v;
      block.gColumn[gCount++] = col;
    } else if (upper == 'M') {
      if (mCount == kMaxMWords) return false;
      block.m[mCount] = codeInTenths(v);
      block.mColumn[mCount++] = col;
    } else {
      const std::uint32_t bit = 1u << index;
      if (present & bit) return false;
      present |= bit;
      block.value[index] = v;
      block.column[index] = col;
    }
  }
  block.kind = BlockKind::Normal;
  block.present = present;
  block.gCount = gCount;
  block.mCount = mCount;
  return true;
}

// Any block, plain or not; kept out of lexBlock so that plain blocks do not pay for its frame.
[[gnu::noinline]] bool lexAnyBlock(const char* begin, const char* end, Block& block, LexError& error,
                                   Parameters* parameters) {
  block.kind = BlockKind::Normal;
  block.present = 0;
  block.gCount = 0;
  block.mCount = 0;
  const char* p = begin;
  while (p < end && classOf(*p) == kBlank) ++p;
  if (p == end) return true;
  if (*p == '/') {
    block.kind = BlockKind::Deleted;
    return true;
  }
  if (*p == '%') {
    block.kind = BlockKind::Percent;
    return true;
  }
  if (*p == '$') {
    block.kind = BlockKind::SenderCommand;
    return true;
  }
  const char* afterHash = p + 1;
  while (afterHash < end && classOf(*afterHash) == kBlank) ++afterHash;
  // A function's value is a parameter's number too (LinuxCNC reads `#atan[1]/[1] = 3` as #45).
  const char* afterName = afterHash;
  while (afterName < end && classOf(*afterName) == kLetter) ++afterName;
  const bool function = afterName > afterHash && afterName < end && *afterName == '[';
  if (*p == '#' && !function &&
      (afterHash == end || !(classOf(*afterHash) == kDigit || *afterHash == '<' || *afterHash == '[' ||
                             *afterHash == '#'))) {
    block.kind = BlockKind::SenderComment;
    return true;
  }
  auto fail = [&](const char* at, std::string message) {
    error.column = columnOf(begin, at);
    error.message = std::move(message);
    return false;
  };
  std::string numberMessage;
  while (p < end) {
    const char c = *p;
    const auto k = classOf(c);
    if (k == kBlank) {
      ++p;
      continue;
    }
    if (k == kLetter) {
      const char upper = static_cast<char>(c & ~0x20);
      const int index = letterIndex(upper);
      const char* const wordStart = p;
      ++p;
      if ((kWordLetters & (1u << index)) == 0)
        return fail(wordStart, fmt::format("Unknown word starting with {}", upper));
      if (upper == 'O') {
        if ((block.present & ~letterBit('N')) != 0 || block.gCount || block.mCount ||
            (parameters && parameters->hasStaged()))
          return fail(wordStart, "An O-word must start the block");
        // Its label and what follows are read by the control flow (gcode_control_flow.h).
        block.kind = BlockKind::OWord;
        return true;
      }
      const char* const numberStart = p;
      double v;
      if (startsComputedValue(p, end)) {
        if (!parameters) return fail(p, "Parameters and expressions (#, [ ]) are not supported");
        const char* const valueStart = p;
        if (!readRealValue(p, end, *parameters, v, numberMessage)) return fail(valueStart, std::move(numberMessage));
        if (std::fabs(v) > kMaxMagnitude) return fail(wordStart, fmt::format("{} word value {:g} out of range", upper, v));
      } else if (!parseSimpleNumber(p, end, v) && !parseNumber(p, end, v, &numberMessage)) {
        if (p == numberStart || numberMessage.find("missing") != std::string::npos)
          return fail(wordStart, fmt::format("Bad number format: {} word without a number", upper));
        return fail(wordStart, std::move(numberMessage));
      }
      const std::uint32_t col = columnOf(begin, wordStart);
      if (upper == 'G' || upper == 'M') {
        const int code = codeInTenths(v);
        if (upper == 'G') {
          if (block.gCount == kMaxGWords) return fail(wordStart, "Too many G words on one line");
          block.g[block.gCount] = code;
          block.gValue[block.gCount] = v;
          block.gColumn[block.gCount++] = col;
        } else {
          if (block.mCount == kMaxMWords) return fail(wordStart, "Too many M words on one line");
          block.m[block.mCount] = code;
          block.mColumn[block.mCount++] = col;
        }
        continue;
      }
      const std::uint32_t bit = 1u << index;
      if (block.present & bit)
        return fail(wordStart,
                    fmt::format("Multiple {} words on one line", static_cast<char>(upper | 0x20)));
      block.present |= bit;
      block.value[index] = v;
      block.column[index] = col;
      continue;
    }
    if (c == '(') {
      const char* q = p + 1;
      while (q < end && *q != ')') {
        if (*q == '(') return fail(q, "Nested comment found");
        ++q;
      }
      if (q == end) return fail(p, "Unclosed comment found");
      p = q + 1;
      continue;
    }
    if (c == ';') break;
    if (c == '#' && parameters) {
      // A parameter setting: staged, it takes effect after the block.
      const char* const at = p++;
      ParameterRef ref;
      if (!readParameterRef(p, end, *parameters, ref, numberMessage)) return fail(at, std::move(numberMessage));
      while (p < end && classOf(*p) == kBlank) ++p;
      if (p >= end || *p != '=') return fail(at, "Equal sign missing in parameter setting");
      ++p;
      double v;
      const bool read = parameters->bareSettings ? readBareExpression(p, end, *parameters, v, numberMessage)
                                                 : readRealValue(p, end, *parameters, v, numberMessage);
      if (!read) return fail(at, std::move(numberMessage));
      parameters->stage(std::move(ref), v);
      continue;
    }
    if (c == '#' || c == '[')
      return fail(p, parameters ? "An expression must stand where a word's number does (after its letter)"
                                : "Parameters and expressions (#, [ ]) are not supported");
    if (k == kDigit || k == kDot || k == kSign)
      return fail(p, fmt::format("Number {} without a letter", numberText(p, end)));
    return fail(p, fmt::format("Bad character used: {}", showChar(c)));
  }
  return true;
}

}  // namespace

bool lexBlock(const char* begin, const char* end, Block& block, LexError& error, Parameters* parameters) {
  return lexPlainBlock(begin, end, block) || lexAnyBlock(begin, end, block, error, parameters);
}

}  // namespace isurface::gcode
