// Subroutines and subprograms in files of their own: LinuxCNC's `o<name> call` reads name.ngc,
// a Fanuc `M98 P1234` (or G65) reads the program O1234, from the subroutine path. Their lines
// run from that file's text (diagnostics name the file and its line); their moves carry the
// line of the main program that called into it, so that every move points into the program the
// user opened.
#include <fmt/format.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "interpreter_state.h"
#include "isurface/gcode/line_ends.h"
#include "isurface/base/input_files.h"

namespace isurface::gcode {

namespace {

// The file names a label may be found under, in the order they are tried.
std::vector<std::string> candidateNames(const std::string& label, bool program) {
  if (!program) return {label.substr(1, label.size() - 2) + ".ngc"};  // "<name>" -> name.ngc
  std::vector<std::string> stems = {label};
  if (label.size() < 4) stems.push_back(std::string(4 - label.size(), '0') + label);  // O0100
  std::vector<std::string> names;
  for (const std::string& stem : stems)
    for (const char* prefix : {"O", "o"})
      for (const char* extension : {"", ".nc", ".NC", ".ngc", ".txt"}) names.push_back(prefix + stem + extension);
  return names;
}

}  // namespace

std::optional<LinePosition> InterpreterState::findSubroutineFile(const std::string& label, bool program) {
  for (const std::string& folder : options_.subroutinePath) {
    for (const std::string& name : candidateNames(label, program)) {
      const std::filesystem::path path = std::filesystem::path(folder) / name;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) continue;
      for (const SubroutineFile& loaded : files_)
        if (loaded.path == path.string()) return LinePosition{loaded.text.data(), 1};
      std::ifstream in(path, std::ios::binary);
      noteInputFile(path.string());
      if (!in) continue;
      std::ostringstream text;
      text << in.rdbuf();
      SubroutineFile& file = files_.emplace_back();
      file.path = path.string();
      file.text = text.str();
      if (hasLoneCarriageReturn(file.text)) file.text = withLineFeeds(file.text);
      const std::size_t bom = file.text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
      return LinePosition{file.text.data() + bom, 1};
    }
  }
  return std::nullopt;
}

void InterpreterState::enterTextOf(const char* at) {
  SubroutineFile* now = nullptr;
  if (!(at >= mainText_.begin && at <= mainText_.end)) {
    for (SubroutineFile& file : files_)
      if (at >= file.text.data() && at <= file.text.data() + file.text.size()) now = &file;
  }
  if (now == reading_) return;
  if (!reading_) {  // leaving the main text: its moves name the calling line from now on
    callLine_ = lineStart_.line;
    mainLeftAt_ = nextLine_.at;
  }
  reading_ = now;
  const char* begin = now ? now->text.data() : mainText_.begin;
  textEnd_ = now ? now->text.data() + now->text.size() : mainText_.end;
  source_ = now ? now->path : result_.program.source;
  macro_.setText(begin, textEnd_);
}

std::optional<LinePosition> InterpreterState::blockInTextOf(long number, LinePosition from) {
  // Looked for in the caller's text; the text being read (and named in messages) stays this one.
  SubroutineFile* const before = reading_;
  const std::string sourceBefore = source_;
  const char* const endBefore = textEnd_;
  const std::uint32_t callLine = callLine_;
  const char* const leftAt = mainLeftAt_;
  enterTextOf(from.at);
  const std::optional<LinePosition> found = macro_.blockNumbered(number, from);
  reading_ = before;
  source_ = sourceBefore;
  textEnd_ = endBefore;
  callLine_ = callLine;
  mainLeftAt_ = leftAt;
  macro_.setText(before ? before->text.data() : mainText_.begin, textEnd_);
  return found;
}

void InterpreterState::reportCallStack() const {
  std::string stack;
  for (const ControlFlow::Call& call : flow_.calls()) {
    if (!stack.empty()) stack += " > ";
    // The call stands in the text its return goes back to: a file's, or the main text.
    for (const SubroutineFile& file : files_)
      if (call.back.at >= file.text.data() && call.back.at <= file.text.data() + file.text.size())
        stack += std::filesystem::path(file.path).filename().string() + ':';
    stack += std::to_string(call.back.line - 1) + ' ' + call.name;
  }
  options_.callStack(delivered_ + moves_.size(), stack);
}

bool InterpreterState::leaveFile(const char*& p) {
  // A file read to its end without defining what was looked for: the search goes on after the
  // call, unless the call is in this very file (it would be read again for ever).
  const std::optional<LinePosition> back = flow_.searchOnAfterFile();
  const bool callHere = back && back->at >= reading_->text.data() && back->at <= reading_->text.data() + reading_->text.size();
  if (back && !callHere) {
    p = back->at;
    enterTextOf(p);
    line_ = back->line - 1;
    return true;
  }
  if (back) {
    result_.errors.push_back(Diagnostic{source_, line_, 0, *flow_.unfinished()});
    ended_ = true;
    return false;
  }
  result_.errors.push_back(Diagnostic{
      source_, line_, 0,
      fmt::format("the subroutine file ends without returning (endsub, return or M99) to line {} of {}", callLine_,
                  result_.program.source)});
  ended_ = true;
  return false;
}

}  // namespace isurface::gcode
