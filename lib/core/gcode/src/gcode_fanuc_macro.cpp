// Fanuc macro B's GOTO, IF and WHILE statements.
#include "gcode_fanuc_macro.h"
#include "gcode_line_text.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstring>

namespace isurface::gcode {

namespace {

// Matches a keyword (any case) at p and moves past it and the blanks after.
bool keyword(const char*& p, const char* end, const char* word) {
  const std::size_t n = std::strlen(word);
  if (static_cast<std::size_t>(end - p) < n) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(p[i])) != word[i]) return false;
  if (p + n < end && std::isalpha(static_cast<unsigned char>(p[n]))) return false;
  p = skipLineBlanks(p + n, end);
  return true;
}

// The block number of a line ("N120 ..."), if it has one.
std::optional<long> blockNumberOf(const char* p, const char* end) {
  p = skipLineBlanks(p, end);
  if (p >= end || (*p != 'N' && *p != 'n')) return std::nullopt;
  p = skipLineBlanks(p + 1, end);
  long n = 0;
  bool digits = false;
  for (; p < end && (std::isdigit(static_cast<unsigned char>(*p)) || isLineBlank(*p)); ++p)
    if (!isLineBlank(*p)) n = n * 10 + (*p - '0'), digits = true;
  return digits ? std::optional<long>(n) : std::nullopt;
}

const char* lineEnd(const char* p, const char* end) {
  const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
  return nl ? static_cast<const char*>(nl) : end;
}

}  // namespace

bool FanucMacro::isStatement(const char* begin, const char* end) {
  const char* p = pastBlockNumber(begin, end);
  for (const char* word : {"goto", "if", "while", "end"}) {
    const char* q = p;
    if (keyword(q, end, word)) return true;
  }
  return false;
}

std::optional<LinePosition> FanucMacro::findBlock(long number, LinePosition from) const {
  // Forward from `from`, then from the start of the program, as a Fanuc control searches.
  std::uint32_t line = from.line;
  for (const char* p = from.at; p < end_; ++line) {
    const char* e = lineEnd(p, end_);
    if (blockNumberOf(p, e) == number) return LinePosition{p, line};
    p = e + 1;
  }
  line = 1;
  for (const char* p = begin_; p < from.at && p < end_; ++line) {
    const char* e = lineEnd(p, end_);
    if (blockNumberOf(p, e) == number) return LinePosition{p, line};
    p = e + 1;
  }
  return std::nullopt;
}

std::optional<LinePosition> FanucMacro::findEnd(int id, LinePosition from) const {
  std::uint32_t line = from.line;
  for (const char* p = from.at; p < end_; ++line) {
    const char* e = lineEnd(p, end_);
    const char* q = pastBlockNumber(p, e);
    if (keyword(q, e, "end") && std::isdigit(static_cast<unsigned char>(q < e ? *q : ' ')) && std::atoi(q) == id)
      return LinePosition{e + 1, line + 1};
    p = e + 1;
  }
  return std::nullopt;
}

bool FanucMacro::count(Outcome& out, std::uint32_t column) {
  if (++jumps_ <= kMaxJumps) return true;
  out.ok = false;
  out.column = column;
  out.message = fmt::format("over {} jumps (GOTO and loop rounds): a program that never ends?", kMaxJumps);
  return false;
}

FanucMacro::Outcome FanucMacro::execute(LinePosition here, const char* end) {
  Outcome out;
  const char* p = pastBlockNumber(here.at, end);
  const std::uint32_t column = static_cast<std::uint32_t>(p - here.at + 1);
  const LinePosition next{end + 1, here.line + 1};
  auto error = [&](std::string message) {
    out.ok = false;
    out.column = column;
    out.message = std::move(message);
    return out;
  };
  auto value = [&](double& v) {
    std::string message;
    if (readRealValue(p, end, parameters_, v, message)) return true;
    error(std::move(message));
    return false;
  };
  auto condition = [&](double& v) {
    if (p >= end || *p != '[') {
      error("a condition in [ ] is missing");
      return false;
    }
    return value(v);
  };
  auto goTo = [&]() {
    double n = 0;
    if (!value(n)) return out;
    const auto target = findBlock(std::lround(n), next);
    if (!target) return error(fmt::format("GOTO {}: no block N{} in the program", std::lround(n), std::lround(n)));
    if (!count(out, column)) return out;
    out.jump = target;
    return out;
  };
  double v = 0;
  if (keyword(p, end, "goto")) return goTo();
  if (keyword(p, end, "if")) {
    if (!condition(v)) return out;
    p = skipLineBlanks(p, end);
    if (keyword(p, end, "goto")) return v != 0 ? goTo() : out;
    if (keyword(p, end, "then")) {
      if (v != 0) out.then = p;
      return out;
    }
    return error("IF [..] must go on with GOTO or THEN");
  }
  if (keyword(p, end, "while")) {
    if (!condition(v)) return out;
    p = skipLineBlanks(p, end);
    if (!keyword(p, end, "do") || p >= end || !std::isdigit(static_cast<unsigned char>(*p)))
      return error("WHILE [..] must go on with DO and a loop number");
    const int id = std::atoi(p);
    const bool again = !loops_.empty() && loops_.back().id == id && loops_.back().top.line == here.line;
    if (v != 0) {
      if (!again) loops_.push_back(Loop{id, here});
      return out;
    }
    if (again) loops_.pop_back();
    const auto after = findEnd(id, next);
    if (!after) return error(fmt::format("WHILE .. DO{} has no END{}", id, id));
    out.jump = after;
    return out;
  }
  if (keyword(p, end, "end")) {
    const int id = p < end ? std::atoi(p) : 0;
    if (loops_.empty() || loops_.back().id != id) return error(fmt::format("END{} without its WHILE .. DO{}", id, id));
    if (!count(out, column)) return out;
    out.jump = loops_.back().top;
    return out;
  }
  return error("not a Fanuc macro statement");
}

}  // namespace isurface::gcode
