// The one bound on a run's length that the interpreter keeps: the lines that loops, calls and
// jumps back read again. Nested loops, subprograms repeated inside repeated subprograms and
// M99 P or GOTO back-jumps multiply each other's rounds, so no bound per loop stops them; a bound
// on the whole run does, whatever the construct, before its moves fill memory or a disk.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "interpreter_state.h"

namespace isurface::gcode {

const std::string& InterpreterState::pathOfText(const char* at) const {
  if (at >= mainText_.begin && at <= mainText_.end) return result_.program.source;
  for (const SubroutineFile& file : files_)
    if (at >= file.text.data() && at <= file.text.data() + file.text.size()) return file.path;
  return source_;
}

bool InterpreterState::stopNeverEnding() {
  // What is running, outermost first: O-word loops and calls, Fanuc WHILE loops. A loop at a
  // call depth began before the call made from that depth (which is still in progress).
  std::vector<ControlFlow::Open> open = flow_.open();
  for (ControlFlow::Open& loop : macro_.openLoops()) open.push_back(std::move(loop));
  std::stable_sort(open.begin(), open.end(), [](const ControlFlow::Open& a, const ControlFlow::Open& b) {
    return 2 * a.depth + a.call < 2 * b.depth + b.call;
  });
  const std::string& mainPath = result_.program.source;
  auto place = [&](const std::string& path, std::uint32_t line) {
    return path == mainPath ? fmt::format("line {}", line)
                            : fmt::format("{}:{}", std::filesystem::path(path).filename().string(), line);
  };
  std::string running;
  for (const ControlFlow::Open& o : open)
    running += fmt::format("{}{} ({})", running.empty() ? "" : " > ", o.what, place(pathOfText(o.at.at), o.at.line));
  Diagnostic d{source_, line_, 0, ""};
  std::string jumpBack;
  if (lastJumpBack_) {
    const std::string& path = lastJumpBack_->file ? lastJumpBack_->file->path : mainPath;
    jumpBack = fmt::format("the last jump back: {} to line {}", place(path, lastJumpBack_->from), lastJumpBack_->to);
    d.file = path;
    d.line = lastJumpBack_->to;  // where it goes on again, as a loop is named at its top
  }
  if (!open.empty()) {  // named where the outermost of them stands
    d.file = pathOfText(open.front().at.at);
    d.line = open.front().at.line;
  }
  d.message = fmt::format(
      "a program that never ends? Its loops, calls and jumps back have read lines again {} times, the most one "
      "run may{}{}",
      options_.maxLinesReadAgain, running.empty() ? "" : "; running: " + running,
      jumpBack.empty() ? "" : "; " + jumpBack);
  result_.errors.push_back(std::move(d));
  ended_ = true;  // with --keep-going too: nothing after it would be read
  return false;
}

}  // namespace isurface::gcode
