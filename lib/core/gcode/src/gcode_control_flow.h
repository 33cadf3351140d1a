#pragma once
// LinuxCNC's O-word control flow: subroutines (sub, endsub, return, call with arguments in
// #1..#30 local to the call, recursion), if/elseif/else/endif, while/endwhile, do/while,
// repeat/endrepeat, break and continue. Lines are executed where they stand in the file, so
// every move keeps the physical line that made it; a construct's lines are found by reading
// on (skipping) as LinuxCNC does, and loops and calls jump back to lines already read.
// Private to the gcode module.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "gcode_parameters.h"

namespace isurface::gcode {

// The start of a line in the text and its 1-based number.
struct LinePosition {
  const char* at = nullptr;
  std::uint32_t line = 0;
};

// True when [begin, end) is an O-word line (after blanks, a block delete '/' and an N word).
bool isOWordLine(const char* begin, const char* end);

class ControlFlow {
 public:
  // A subroutine may call others (and itself) this deep. How long loops run is bounded for the
  // whole run, by the lines they read again (InterpreterOptions::maxLinesReadAgain).
  static constexpr std::size_t kMaxCallDepth = 200;

  explicit ControlFlow(Parameters& parameters) : parameters_(parameters) {}

  // Where a subroutine or subprogram that is not (yet) known may be in a file of its own: given
  // the label ("<name>" of an O-word subroutine, or a Fanuc program number) and whether it is a
  // Fanuc program, the first line of that file's text, or nothing.
  using FileFinder = std::function<std::optional<LinePosition>(const std::string& label, bool program)>;
  void setFileFinder(FileFinder finder) { findFile_ = std::move(finder); }

  // Lines are being read past (a subroutine's body at its definition, a branch not taken, a
  // loop left): only O-word lines matter until the construct's end.
  bool skipping() const { return skip_.has_value(); }
  // Lines are being read past in search of a subroutine or subprogram called.
  bool searching() const { return skip_ && (skip_->target == SkipTo::FindSub || skip_->target == SkipTo::FindProgram); }
  // Some control flow was met: lines already read may be read again.
  bool seen() const { return seen_; }
  std::size_t callDepth() const { return frames_.size(); }
  // The calls in progress, outermost first: what was called ("o<name>", "o100", "O1000") and
  // the line after the call.
  struct Call {
    std::string name;
    LinePosition back;
  };
  std::vector<Call> calls() const;
  // The loops and calls in progress, outermost first: what ("o100 repeat", "M98 P1000"), the
  // line it stands on (and the text it is in), and how many calls were in progress when it
  // began (a call is in the calls before it: its own is counted after it).
  struct Open {
    std::string what;
    LinePosition at;
    std::size_t depth = 0;
    bool call = false;
  };
  std::vector<Open> open() const;

  struct Outcome {
    bool ok = true;
    std::uint32_t column = 0;
    std::string message;
    std::optional<LinePosition> jump;  // where execution goes on, when not the next line
  };
  // Executes the O-word line `here` ending at `end`; `next` is the line after it.
  Outcome execute(LinePosition here, const char* end, LinePosition next);

  // Fanuc subprograms: M98 P<program> L<times> (the caller's parameters are shared) and G65
  // P<program> with letter arguments (`arguments`: parameter number and value, in a scope of
  // its own); the program starts after its "O<program>" line, here or further on.
  Outcome callProgram(const std::string& program, const std::vector<std::pair<int, double>>& arguments, bool macro,
                      long times, LinePosition here, LinePosition next, std::uint32_t column);
  // M99: back to the line after the M98 or G65 (or the program's start again for L repeats).
  // `inProgram` is false when there is no call to return from (M99 ending a main program).
  Outcome returnFromProgram(std::uint32_t column, bool& inProgram);

  // At the end of a subroutine file that did not define what was looked for in it: where the
  // search goes on (the line after the call, in the text that called), or nothing.
  std::optional<LinePosition> searchOnAfterFile() const;

  // At the end of the text: what is left open (an if without its endif, a subroutine called but
  // never defined, ...), or nothing.
  std::optional<std::string> unfinished() const;

 private:
  enum class Keyword {
    None, Sub, Endsub, Call, Do, While, Endwhile, If, Elseif, Else, Endif, Break, Continue, Return, Repeat, Endrepeat
  };
  struct OLine {
    std::string label;  // "123" or "<name>"
    Keyword keyword = Keyword::None;
    const char* rest = nullptr;  // what follows the keyword
    std::uint32_t column = 0;
  };
  struct Loop {
    std::string label;
    Keyword kind;          // While, Do or Repeat
    LinePosition top;      // While: its own line (re-evaluated); Do and Repeat: the line after
    double remaining = 0;  // Repeat
    LinePosition opened;   // the while, do or repeat line
    std::size_t branches = 0;  // ifs open when it began: those opened inside close with it
  };
  struct Branch {
    std::string label;
    bool taken = false;
  };
  struct Frame {
    std::string label;
    LinePosition back;  // the line after the call
    LinePosition at;    // the call's own line
    std::size_t loops = 0, branches = 0;
    bool program = false;      // a Fanuc subprogram (M98, G65): M99 returns
    bool scoped = true;        // parameters of its own (O-word calls, G65; not M98)
    long timesLeft = 0;        // M98 L: runs still to come
    LinePosition body;
  };
  enum class SkipTo { EndSub, BranchEnd, EndIf, LoopEnd, LoopContinue, FindSub, FindProgram };
  struct Skip {
    SkipTo target = SkipTo::EndSub;
    std::string label;
    std::uint32_t fromLine = 0;
    std::vector<double> arguments;  // FindSub: the call's
    LinePosition back;              // FindSub, FindProgram: the line after the call
    LinePosition at;                // FindSub, FindProgram: the call's own line
    std::vector<std::pair<int, double>> programArguments;  // FindProgram
    bool macro = false;
    long times = 1;
    std::uint32_t column = 0;
  };

  static Skip skipTo(SkipTo target, const std::string& label, std::uint32_t line) {
    Skip s;
    s.target = target;
    s.label = label;
    s.fromLine = line;
    return s;
  }
  Outcome executeSkipping(const OLine& o, LinePosition here, const char* end, LinePosition next, bool& resume);
  Outcome run(const OLine& o, LinePosition here, const char* end, LinePosition next);
  Outcome call(const OLine& o, LinePosition body, std::vector<double> arguments, LinePosition at, LinePosition back);
  Outcome enterProgram(const Skip& request, LinePosition body);
  Outcome loopEnd();
  bool condition(const OLine& o, const char* end, double& value, Outcome& outcome) const;
  Loop* findLoop(const std::string& label);
  void beginLoop(const std::string& label, Keyword kind, LinePosition top, LinePosition opened, double remaining = 0);

  Parameters& parameters_;
  FileFinder findFile_;
  bool seen_ = false;
  std::optional<Skip> skip_;
  std::unordered_map<std::string, LinePosition> subroutines_;  // label -> the line after `sub`
  std::unordered_map<std::string, LinePosition> programs_;     // Fanuc program number -> the line after "O<n>"
  std::vector<Loop> loops_;
  std::vector<Branch> branches_;
  std::vector<Frame> frames_;
};

}  // namespace isurface::gcode
