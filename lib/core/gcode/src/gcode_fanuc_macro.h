#pragma once
// Fanuc macro B's control statements, read in the Fanuc dialect: GOTO n (to the block numbered
// N n, searched forward and then from the start), IF [cond] GOTO n, IF [cond] THEN statement,
// WHILE [cond] DO m ... END m. Lines run where they stand, so every move keeps its physical line.
// Private to the gcode module.
#include <cstdint>
#include <map>
#include <utility>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "gcode_control_flow.h"
#include "gcode_parameters.h"

namespace isurface::gcode {

class FanucMacro {
 public:
  explicit FanucMacro(const Parameters& parameters) : parameters_(parameters) {}
  void setText(const char* begin, const char* end) { begin_ = begin, end_ = end; }

  // True when the line [begin, end) (after an N word) is one of the statements above.
  static bool isStatement(const char* begin, const char* end);

  struct Outcome {
    bool ok = true;
    std::uint32_t column = 0;
    std::string message;
    std::optional<LinePosition> jump;
    const char* then = nullptr;  // IF .. THEN with a true condition: the statement to run
  };
  Outcome execute(LinePosition here, const char* end);

  // The block numbered N `number` in the program `from` stands in (M99 P returning to it).
  std::optional<LinePosition> blockNumbered(long number, LinePosition from) { return findBlock(number, from); }

  // Subprogram calls in progress (M98, G65): a loop belongs to the call it began in, and those of
  // a call that returned (M99) are over.
  // The WHILE loops running, outermost first.
  std::vector<ControlFlow::Open> openLoops() const {
    std::vector<ControlFlow::Open> out;
    for (const Loop& loop : loops_) out.push_back({"WHILE .. DO" + std::to_string(loop.id), loop.top, loop.depth});
    return out;
  }

  void setCallDepth(std::size_t depth) {
    depth_ = depth;
    while (!loops_.empty() && loops_.back().depth > depth_) loops_.pop_back();
  }

 private:
  struct Loop {
    int id;
    LinePosition top;  // the WHILE line, evaluated again each round
    std::size_t depth;  // subprogram calls it runs inside
  };
  std::optional<LinePosition> findBlock(long number, LinePosition from);
  std::optional<LinePosition> findEnd(int id, LinePosition from) const;

  const Parameters& parameters_;
  const char* begin_ = nullptr;
  const char* end_ = nullptr;
  std::vector<Loop> loops_;
  std::size_t depth_ = 0;
  // (the text, the line after the GOTO, the number): a subprogram file has lines of its own.
  std::map<std::tuple<const char*, std::uint32_t, long>, std::optional<LinePosition>> found_;
};

}  // namespace isurface::gcode
