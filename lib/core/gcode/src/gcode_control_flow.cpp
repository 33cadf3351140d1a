// LinuxCNC's O-word control flow (its manual's "O Codes"), executed where the lines stand.
#include "gcode_control_flow.h"
#include "gcode_line_text.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstring>

namespace isurface::gcode {

namespace {

std::string shown(const std::string& label) { return "o" + label; }

}  // namespace

bool isOWordLine(const char* begin, const char* end) {
  const char* p = pastBlockNumber(begin, end);
  return p < end && (*p == 'o' || *p == 'O');
}

namespace {

// Past a `#..` parameter or a `[..]` expression (an O-word's number given by one).
const char* pastParameterExpression(const char* p, const char* end) {
  while (p < end && *p == '#') ++p;
  if (p < end && *p == '<') {
    while (p < end && *p != '>') ++p;
    return p < end ? p + 1 : p;
  }
  if (p < end && *p == '[') {
    int depth = 0;
    for (; p < end; ++p) {
      if (*p == '[') ++depth;
      if (*p == ']' && --depth == 0) return p + 1;
    }
    return p;
  }
  while (p < end && (std::isdigit(static_cast<unsigned char>(*p)) || *p == '.')) ++p;
  return p;
}

}  // namespace

ControlFlow::Outcome ControlFlow::execute(LinePosition here, const char* end, LinePosition next) {
  // The line: [N..] O label [keyword] [rest].
  const char* begin = here.at;
  const char* p = pastBlockNumber(begin, end);
  OLine o;
  o.column = static_cast<std::uint32_t>(p - begin + 1);
  p = skipLineBlanks(p + 1, end);
  auto error = [&](std::string message) {
    Outcome out;
    out.ok = false;
    out.column = o.column;
    out.message = std::move(message);
    return out;
  };
  if (p < end && *p == '<') {
    const char* close = static_cast<const char*>(std::memchr(p, '>', static_cast<std::size_t>(end - p)));
    if (!close) return error("Unclosed O-word name (missing '>')");
    o.label = "<";
    for (const char* q = p + 1; q < close; ++q)
      if (!isLineBlank(*q)) o.label += static_cast<char>(std::tolower(static_cast<unsigned char>(*q)));
    o.label += ">";
    p = close + 1;
  } else if (p < end && (*p == '#' || *p == '[')) {  // a number given by a parameter or an expression
    double value = 0;
    std::string message;
    if (skip_) {  // lines being skipped are not evaluated: their parameters may not be set yet
      o.label = "#";
      p = pastParameterExpression(p, end);
    } else if (!readRealValue(p, end, parameters_, value, message)) {
      return error(std::move(message));
    } else if (value < 0 || value != std::floor(value) || value > 1e9) {
      return error(fmt::format("O-word number {:g} is not a whole number of 0 or more", value));
    } else {
      o.label = std::to_string(static_cast<long>(value));
    }
  } else {
    std::string digits;  // without leading zeros: o0100 is o100
    bool any = false;
    for (; p < end && (std::isdigit(static_cast<unsigned char>(*p)) || isLineBlank(*p)); ++p) {
      if (isLineBlank(*p)) continue;
      any = true;
      if (!(digits.empty() && *p == '0')) digits += *p;
    }
    if (!any) return error("O-word without a number or <name>");
    o.label = digits.empty() ? "0" : digits;
  }
  p = skipLineBlanks(p, end);
  std::string word;
  while (p < end && std::isalpha(static_cast<unsigned char>(*p))) word += static_cast<char>(std::tolower(static_cast<unsigned char>(*p++)));
  static const std::unordered_map<std::string, Keyword> kKeywords = {
      {"sub", Keyword::Sub},       {"endsub", Keyword::Endsub},     {"call", Keyword::Call},
      {"do", Keyword::Do},         {"while", Keyword::While},       {"endwhile", Keyword::Endwhile},
      {"if", Keyword::If},         {"elseif", Keyword::Elseif},     {"else", Keyword::Else},
      {"endif", Keyword::Endif},   {"break", Keyword::Break},       {"continue", Keyword::Continue},
      {"return", Keyword::Return}, {"repeat", Keyword::Repeat},     {"endrepeat", Keyword::Endrepeat}};
  if (word.empty()) {  // a program number ("O1000 (name)"): where a Fanuc subprogram starts
    programs_[o.label] = next;
    if (skip_ && skip_->target == SkipTo::FindProgram && skip_->label == o.label) {
      const Skip request = std::move(*skip_);
      skip_.reset();
      return enterProgram(request, next);
    }
    return {};
  }
  const auto found = kKeywords.find(word);
  if (found == kKeywords.end()) return error(fmt::format("Unknown O-word keyword '{}' after {}", word, shown(o.label)));
  o.keyword = found->second;
  o.rest = p;
  seen_ = true;
  if (skip_) {
    bool resume = false;
    Outcome out = executeSkipping(o, here, end, next, resume);
    if (!resume) return out;
  }
  return run(o, here, end, next);
}

ControlFlow::Outcome ControlFlow::executeSkipping(const OLine& o, LinePosition here, const char* end, LinePosition next,
                                                  bool& resume) {
  (void)here;
  const Skip& s = *skip_;
  if (s.target == SkipTo::FindProgram) return {};  // only "O<n>" lines matter (see execute)
  if (o.label != s.label) {
    // Looking for a subroutine defined further on: those read past on the way are known too.
    if (s.target == SkipTo::FindSub && o.keyword == Keyword::Sub) subroutines_[o.label] = next;
    return {};
  }
  switch (s.target) {
    case SkipTo::EndSub:
      if (o.keyword == Keyword::Endsub) skip_.reset();
      return {};
    case SkipTo::FindSub:
      if (o.keyword == Keyword::Sub) {
        subroutines_[o.label] = next;
        Skip found = std::move(*skip_);
        skip_.reset();
        return call(o, next, std::move(found.arguments), found.at, found.back);
      }
      return {};
    case SkipTo::BranchEnd:
      if (o.keyword == Keyword::Elseif) {
        double v = 0;
        Outcome out;
        if (!condition(o, end, v, out)) return out;
        if (v != 0) skip_.reset(), branches_.back().taken = true;
      } else if (o.keyword == Keyword::Else) {
        skip_.reset();
        branches_.back().taken = true;
      } else if (o.keyword == Keyword::Endif) {
        skip_.reset();
        branches_.pop_back();
      }
      return {};
    case SkipTo::EndIf:
      if (o.keyword == Keyword::Endif) skip_.reset(), branches_.pop_back();
      return {};
    case SkipTo::FindProgram: return {};
    case SkipTo::LoopEnd:
    case SkipTo::LoopContinue:
      if (o.keyword == Keyword::Endwhile || o.keyword == Keyword::Endrepeat || o.keyword == Keyword::While) {
        resume = s.target == SkipTo::LoopContinue;
        skip_.reset();
      }
      return {};
  }
  return {};
}

bool ControlFlow::condition(const OLine& o, const char* end, double& value, Outcome& outcome) const {
  const char* p = skipLineBlanks(o.rest, end);
  std::string message;
  if (p >= end || *p != '[') message = fmt::format("{} needs a condition in [ ]", shown(o.label));
  else if (readRealValue(p, end, parameters_, value, message)) return true;
  outcome.ok = false;
  outcome.column = o.column;
  outcome.message = std::move(message);
  return false;
}

ControlFlow::Loop* ControlFlow::findLoop(const std::string& label) {
  const std::size_t base = frames_.empty() ? 0 : frames_.back().loops;
  for (std::size_t k = loops_.size(); k > base; --k)
    if (loops_[k - 1].label == label) return &loops_[k - 1];
  return nullptr;
}

void ControlFlow::beginLoop(const std::string& label, Keyword kind, LinePosition top, LinePosition opened,
                            double remaining) {
  Loop loop{label, kind, top, remaining, opened};
  loop.branches = branches_.size();
  loops_.push_back(std::move(loop));
}

ControlFlow::Outcome ControlFlow::call(const OLine& o, LinePosition body, std::vector<double> arguments, LinePosition at,
                                       LinePosition back) {
  if (frames_.size() >= kMaxCallDepth) {
    Outcome out;
    out.ok = false;
    out.column = o.column;
    out.message = fmt::format("Subroutine calls nested deeper than {} (a recursion that never ends?) calling {}",
                              kMaxCallDepth, shown(o.label));
    return out;
  }
  // What a call returns is set by its return, or is nothing.
  parameters_.set("_value", 0.0);
  parameters_.set("_value_returned", 0.0);
  Frame frame;
  frame.label = o.label;
  frame.back = back;
  frame.at = at;
  frame.loops = loops_.size();
  frame.branches = branches_.size();
  frames_.push_back(std::move(frame));
  parameters_.pushScope();
  for (std::size_t i = 0; i < arguments.size(); ++i) parameters_.set(static_cast<int>(i + 1), arguments[i]);
  Outcome out;
  out.jump = body;
  return out;
}

ControlFlow::Outcome ControlFlow::callProgram(const std::string& program,
                                              const std::vector<std::pair<int, double>>& arguments, bool macro,
                                              long times, LinePosition here, LinePosition next, std::uint32_t column) {
  seen_ = true;
  if (times < 1) return {};  // L0: no run at all
  Skip request = skipTo(SkipTo::FindProgram, program, here.line);
  request.back = next;
  request.at = here;
  request.programArguments = arguments;
  request.macro = macro;
  request.times = times;
  request.column = column;
  const auto found = programs_.find(program);
  if (found != programs_.end()) return enterProgram(request, found->second);
  skip_ = std::move(request);  // in a file of its own, or further on in this one
  Outcome out;
  if (findFile_) out.jump = findFile_(program, true);
  return out;
}

ControlFlow::Outcome ControlFlow::enterProgram(const Skip& request, LinePosition body) {
  Outcome out;
  if (request.times < 1) return out;
  if (frames_.size() >= kMaxCallDepth) {
    out.ok = false;
    out.column = request.column;
    out.message = fmt::format("Subprogram calls nested deeper than {} (a recursion that never ends?) calling O{}",
                              kMaxCallDepth, request.label);
    return out;
  }
  Frame frame;
  frame.label = "O" + request.label;
  frame.back = request.back;
  frame.at = request.at;
  frame.loops = loops_.size();
  frame.branches = branches_.size();
  frame.program = true;
  frame.scoped = request.macro;
  frame.timesLeft = request.times - 1;
  frame.body = body;
  frames_.push_back(frame);
  if (request.macro) parameters_.pushScope();
  for (const auto& [number, value] : request.programArguments) parameters_.set(number, value);
  out.jump = body;
  return out;
}

ControlFlow::Outcome ControlFlow::returnFromProgram(std::uint32_t column, bool& inProgram) {
  Outcome out;
  inProgram = !frames_.empty() && frames_.back().program;
  if (!inProgram) {
    if (!frames_.empty()) {
      out.ok = false;
      out.column = column;
      out.message = fmt::format("M99 inside {} sub, which returns with endsub or return", shown(frames_.back().label));
    }
    return out;
  }
  Frame& frame = frames_.back();
  loops_.resize(frame.loops);
  branches_.resize(frame.branches);
  if (frame.timesLeft > 0) {
    --frame.timesLeft;
    out.jump = frame.body;
    return out;
  }
  if (frame.scoped) parameters_.popScope();
  out.jump = frame.back;
  frames_.pop_back();
  return out;
}

ControlFlow::Outcome ControlFlow::loopEnd() {
  Outcome out;
  out.jump = loops_.back().top;
  return out;
}

ControlFlow::Outcome ControlFlow::run(const OLine& o, LinePosition here, const char* end, LinePosition next) {
  Outcome out;
  auto error = [&](std::string message) {
    out.ok = false;
    out.column = o.column;
    out.message = std::move(message);
    return out;
  };
  // Only what this call opened counts: a recursive call meets its caller's loops and ifs, with
  // the same labels on the same lines.
  const std::size_t loopBase = frames_.empty() ? 0 : frames_.back().loops;
  const std::size_t branchBase = frames_.empty() ? 0 : frames_.back().branches;
  const bool loopOnTop = loops_.size() > loopBase && loops_.back().label == o.label;
  const bool branchOnTop = branches_.size() > branchBase && branches_.back().label == o.label;
  double v = 0;
  switch (o.keyword) {
    case Keyword::None: return out;
    case Keyword::Sub:
      subroutines_[o.label] = next;
      skip_ = skipTo(SkipTo::EndSub, o.label, here.line);
      return out;
    case Keyword::Endsub:
    case Keyword::Return: {
      if (frames_.empty() || frames_.back().label != o.label)
        return error(fmt::format("{} {} outside a call of it", shown(o.label),
                                 o.keyword == Keyword::Return ? "return" : "endsub"));
      const char* p = skipLineBlanks(o.rest, end);
      if (p < end && *p == '[') {
        double value = 0;
        std::string message;
        if (!readRealValue(p, end, parameters_, value, message)) return error(std::move(message));
        parameters_.set("_value", value);
        parameters_.set("_value_returned", 1.0);
      }
      const Frame frame = frames_.back();
      frames_.pop_back();
      loops_.resize(frame.loops);
      branches_.resize(frame.branches);
      parameters_.popScope();
      out.jump = frame.back;
      return out;
    }
    case Keyword::Call: {
      std::vector<double> arguments;
      const char* p = skipLineBlanks(o.rest, end);
      while (p < end && *p != ';') {
        if (*p == '(') {  // a comment between the arguments, as LinuxCNC reads it
          while (p < end && *p != ')') ++p;
          p = skipLineBlanks(p < end ? p + 1 : p, end);
          continue;
        }
        double value = 0;
        std::string message;
        if (!readRealValue(p, end, parameters_, value, message)) return error(std::move(message));
        if (arguments.size() == static_cast<std::size_t>(Parameters::kCallParameters))
          return error(fmt::format("More than {} arguments in a call of {}", Parameters::kCallParameters, shown(o.label)));
        arguments.push_back(value);
      }
      const auto sub = subroutines_.find(o.label);
      if (sub != subroutines_.end()) return call(o, sub->second, std::move(arguments), here, next);
      skip_ = skipTo(SkipTo::FindSub, o.label, here.line);
      skip_->arguments = std::move(arguments);
      skip_->back = next;
      skip_->at = here;
      // A file of its own comes first (LinuxCNC's subroutine path); else further on in this one.
      if (findFile_ && o.label.front() == '<') out.jump = findFile_(o.label, false);
      return out;
    }
    case Keyword::Do:
      beginLoop(o.label, Keyword::Do, next, here);
      return out;
    case Keyword::While: {
      if (!condition(o, end, v, out)) return out;
      if (loopOnTop && loops_.back().kind == Keyword::Do) {  // the end of a do loop
        if (v != 0) return loopEnd();
        loops_.pop_back();
        return out;
      }
      const bool again = loopOnTop && loops_.back().kind == Keyword::While && loops_.back().top.line == here.line;
      if (v != 0) {
        if (!again) beginLoop(o.label, Keyword::While, here, here);
        return out;
      }
      if (again) loops_.pop_back();
      skip_ = skipTo(SkipTo::LoopEnd, o.label, here.line);
      return out;
    }
    case Keyword::Endwhile:
      if (!loopOnTop || loops_.back().kind != Keyword::While) return error(fmt::format("{} endwhile without its while", shown(o.label)));
      return loopEnd();
    case Keyword::Repeat: {
      if (!condition(o, end, v, out)) return out;
      const double times = std::round(v);
      if (times >= 1) beginLoop(o.label, Keyword::Repeat, next, here, times);
      else skip_ = skipTo(SkipTo::LoopEnd, o.label, here.line);
      return out;
    }
    case Keyword::Endrepeat:
      if (!loopOnTop || loops_.back().kind != Keyword::Repeat)
        return error(fmt::format("{} endrepeat without its repeat", shown(o.label)));
      if (--loops_.back().remaining >= 1) return loopEnd();
      loops_.pop_back();
      return out;
    case Keyword::If:
      if (!condition(o, end, v, out)) return out;
      branches_.push_back(Branch{o.label, v != 0});
      if (v == 0) skip_ = skipTo(SkipTo::BranchEnd, o.label, here.line);
      return out;
    case Keyword::Elseif:
    case Keyword::Else:
      // Reached from the branch that ran: what follows up to the endif is not for this pass.
      if (!branchOnTop) return error(fmt::format("{} {} without its if", shown(o.label), o.keyword == Keyword::Else ? "else" : "elseif"));
      skip_ = skipTo(SkipTo::EndIf, o.label, here.line);
      return out;
    case Keyword::Endif:
      if (!branchOnTop) return error(fmt::format("{} endif without its if", shown(o.label)));
      branches_.pop_back();
      return out;
    case Keyword::Break:
    case Keyword::Continue: {
      Loop* loop = findLoop(o.label);
      if (!loop) return error(fmt::format("{} {} outside a loop of that name", shown(o.label),
                                          o.keyword == Keyword::Break ? "break" : "continue"));
      // Loops and ifs opened inside this one end here.
      branches_.resize(loop->branches);
      loops_.resize(static_cast<std::size_t>(loop - loops_.data()) + 1);
      if (o.keyword == Keyword::Break) loops_.pop_back();
      skip_ = skipTo(o.keyword == Keyword::Break ? SkipTo::LoopEnd : SkipTo::LoopContinue, o.label, here.line);
      return out;
    }
  }
  return out;
}

std::vector<ControlFlow::Call> ControlFlow::calls() const {
  std::vector<Call> out;
  out.reserve(frames_.size());
  for (const Frame& f : frames_) out.push_back({f.program ? f.label : shown(f.label), f.back});
  return out;
}

std::vector<ControlFlow::Open> ControlFlow::open() const {
  auto keyword = [](Keyword k) { return k == Keyword::While ? "while" : k == Keyword::Do ? "do" : "repeat"; };
  auto loopOf = [&](const Loop& loop, std::size_t depth) {
    return Open{fmt::format("{} {}", shown(loop.label), keyword(loop.kind)), loop.opened, depth};
  };
  std::vector<Open> out;
  std::size_t loop = 0;
  for (std::size_t depth = 0; depth < frames_.size(); ++depth) {
    const Frame& f = frames_[depth];
    for (; loop < f.loops; ++loop) out.push_back(loopOf(loops_[loop], depth));
    const std::string what = !f.program ? shown(f.label) + " call"
                             : f.scoped ? "G65 P" + f.label.substr(1)
                                        : "M98 P" + f.label.substr(1);
    out.push_back(Open{what, f.at, depth, true});
  }
  for (; loop < loops_.size(); ++loop) out.push_back(loopOf(loops_[loop], frames_.size()));
  return out;
}

std::optional<LinePosition> ControlFlow::searchOnAfterFile() const {
  if (skip_ && (skip_->target == SkipTo::FindSub || skip_->target == SkipTo::FindProgram)) return skip_->back;
  return std::nullopt;
}

std::optional<std::string> ControlFlow::unfinished() const {
  if (skip_) {
    const std::string o = shown(skip_->label);
    switch (skip_->target) {
      case SkipTo::EndSub: return fmt::format("{} sub (line {}) has no endsub", o, skip_->fromLine);
      case SkipTo::FindSub:
        return fmt::format("{} is called (line {}) but defined nowhere{}", o, skip_->fromLine,
                           skip_->label.front() == '<'
                               ? fmt::format(": not in the file, and no {}.ngc in the subroutine path defines it",
                                             skip_->label.substr(1, skip_->label.size() - 2))
                               : " in the file");
      case SkipTo::FindProgram:
        return fmt::format("subprogram O{} is called (line {}) but is neither in the file nor a file O{} in the "
                           "subroutine path",
                           skip_->label, skip_->fromLine, skip_->label);
      case SkipTo::BranchEnd:
      case SkipTo::EndIf: return fmt::format("{} (line {}) has no endif", o, skip_->fromLine);
      case SkipTo::LoopEnd:
      case SkipTo::LoopContinue: return fmt::format("{} (line {}): the end of its loop is missing", o, skip_->fromLine);
    }
  }
  if (!branches_.empty()) return fmt::format("{} if has no endif", shown(branches_.back().label));
  if (!loops_.empty()) return fmt::format("{} loop has no end", shown(loops_.back().label));
  if (!frames_.empty()) return fmt::format("{} was called and never returned", shown(frames_.back().label));
  return std::nullopt;
}

}  // namespace isurface::gcode
