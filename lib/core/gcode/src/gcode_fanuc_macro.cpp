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

// A loop number (DO m, END m), read within the line; -1 when there is none.
int loopNumber(const char* p, const char* end) {
  int n = 0;
  bool digits = false;
  for (; p < end && std::isdigit(static_cast<unsigned char>(*p)) && n < 100000; ++p) n = n * 10 + (*p - '0'), digits = true;
  return digits ? n : -1;
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

namespace {

// Where one program of a file ends and the next begins: a '%' line or an "O<number>" line.
bool programBoundary(const char* p, const char* e) {
  p = skipLineBlanks(p, e);
  if (p < e && *p == '%') return true;
  if (p >= e || (*p != 'O' && *p != 'o')) return false;
  const char* q = skipLineBlanks(p + 1, e);
  if (q >= e || !std::isdigit(static_cast<unsigned char>(*q))) return false;
  while (q < e && (std::isdigit(static_cast<unsigned char>(*q)) || isLineBlank(*q))) ++q;
  return q >= e || !std::isalpha(static_cast<unsigned char>(*q));  // not "o100 if ..."
}

}  // namespace

std::optional<LinePosition> FanucMacro::findBlock(long number, LinePosition from) {
  // Within the program the GOTO stands in: forward to its end, then from its start, as a Fanuc
  // control searches. A GOTO of a line goes where it went before (programs that loop by GOTO).
  const auto known = found_.find({begin_, from.line, number});
  if (known != found_.end()) return known->second;
  std::optional<LinePosition> target;
  std::uint32_t line = from.line;
  for (const char* p = from.at; p < end_ && !target; ++line) {
    const char* e = lineEnd(p, end_);
    if (programBoundary(p, e)) break;
    if (blockNumberOf(p, e) == number) target = LinePosition{p, line};
    p = e + 1;
  }
  LinePosition start{begin_, 1};  // of this program: after the last boundary before `from`
  line = 1;
  for (const char* p = begin_; !target && p < from.at && p < end_; ++line) {
    const char* e = lineEnd(p, end_);
    if (programBoundary(p, e)) start = LinePosition{e + 1, line + 1};
    p = e + 1;
  }
  line = start.line;
  for (const char* p = start.at; !target && p < from.at && p < end_; ++line) {
    const char* e = lineEnd(p, end_);
    if (blockNumberOf(p, e) == number) target = LinePosition{p, line};
    p = e + 1;
  }
  found_[{begin_, from.line, number}] = target;
  return target;
}

std::optional<LinePosition> FanucMacro::findEnd(int id, LinePosition from) const {
  std::uint32_t line = from.line;
  for (const char* p = from.at; p < end_; ++line) {
    const char* e = lineEnd(p, end_);
    const char* q = pastBlockNumber(p, e);
    if (keyword(q, e, "end") && loopNumber(q, e) == id)
      return LinePosition{e + 1, line + 1};
    p = e + 1;
  }
  return std::nullopt;
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
    const int id = keyword(p, end, "do") ? loopNumber(p, end) : -1;
    if (id < 0) return error("WHILE [..] must go on with DO and a loop number");
    // Back at the WHILE of a loop already running (from its END): the same loop, and any loop
    // opened inside it and left by a GOTO is over.
    std::size_t k = loops_.size();
    while (k > 0 && !(loops_[k - 1].top.line == here.line && loops_[k - 1].depth == depth_)) --k;
    const bool again = k > 0;
    if (again) loops_.resize(k);
    if (v != 0) {
      if (!again) loops_.push_back(Loop{id, here, depth_});
      return out;
    }
    if (again) loops_.pop_back();
    const auto after = findEnd(id, next);
    if (!after) return error(fmt::format("WHILE .. DO{} has no END{}", id, id));
    out.jump = after;
    return out;
  }
  if (keyword(p, end, "end")) {
    const int id = loopNumber(p, end);
    // Loops left by a GOTO from inside them are over: the innermost loop of this number is the one.
    std::size_t k = loops_.size();
    while (k > 0 && !(loops_[k - 1].id == id && loops_[k - 1].depth == depth_)) --k;
    if (k == 0) return error(fmt::format("END{} without its WHILE .. DO{}", id, id));
    loops_.resize(k);
    out.jump = loops_.back().top;
    return out;
  }
  return error("not a Fanuc macro statement");
}

}  // namespace isurface::gcode
