// Fanuc subprograms and macro calls, as Fanuc and Haas controls (and LinuxCNC 2.9's M98/M99) run
// them: M98 P<program> L<times> calls the lines after "O<program>" and M99 comes back; G65
// P<program> L<times> does the same with letter arguments in parameters of the call's own.
#include <fmt/format.h>

#include <cmath>

#include "interpreter_state.h"
#include "isurface/base/tolerances.h"

namespace isurface::gcode {

namespace {

// Fanuc's argument specification I: the parameter each letter of a G65 block sets.
constexpr struct {
  char letter;
  int parameter;
} kMacroArguments[] = {{'A', 1},  {'B', 2},  {'C', 3},  {'I', 4},  {'J', 5},  {'K', 6},  {'D', 7},
                       {'F', 9},  {'H', 11}, {'M', 13}, {'Q', 17}, {'R', 18}, {'S', 19}, {'T', 20},
                       {'X', 24}, {'Y', 25}, {'Z', 26}};

// The program number of a P word ("O1000" and "P1000" name the same program), or nothing.
std::optional<std::string> programNumber(double p) {
  const double whole = std::nearbyint(p);
  if (std::fabs(p - whole) > kWholeNumberTolerance || whole < 0 || whole > 99999999) return std::nullopt;
  return fmt::format("{}", static_cast<long long>(whole));
}

}  // namespace

bool InterpreterState::subprogram(const Block& block, int code) {
  const std::uint32_t column = block.mColumn[0];
  if (code == 990) {
    if (block.has('P')) {
      const double p = block.get('P');
      if (p < 0 || std::fabs(p - std::nearbyint(p)) > kWholeNumberTolerance)
        return fail(block.col('P'), "M99 P must be a block number");
    }
    bool inProgram = false;
    const std::size_t depth = flow_.callDepth();
    const ControlFlow::Outcome out = flow_.returnFromProgram(column, inProgram);
    if (!out.ok) return fail(out.column, out.message);
    // M99 P: back to the calling program's block N P instead of the line after the call (once
    // the call is over: while L repeats remain, M99 starts the subprogram again).
    if (inProgram && block.has('P') && out.jump && flow_.callDepth() < depth) {
      const long number = std::lround(block.get('P'));
      const std::optional<LinePosition> target = blockInTextOf(number, *out.jump);
      if (!target) {
        jump_ = out.jump;  // the return is made: on after the call, when going on after errors
        return fail(block.col('P'), fmt::format("M99 P{0}: no block N{0} in the calling program", number));
      }
      jump_ = target;
      return true;
    }
    if (!inProgram) {
      // On the control a main program that ends with M99 starts again, for ever: read once here.
      warnOnce(warnedMainM99_, column, "M99 in the main program: the control would run it again and again; read once");
      ended_ = true;
    }
    jump_ = out.jump;
    return true;
  }
  if (!block.has('P')) return fail(column, "P word (the program number) missing with M98");
  const std::optional<std::string> program = programNumber(block.get('P'));
  if (!program) return fail(block.col('P'), "M98 P must be a program number");
  long times = 1;
  for (char letter : {'L', 'K'})
    if (block.has(letter)) {
      const double l = block.get(letter);
      if (l < 0 || std::fabs(l - std::nearbyint(l)) > kWholeNumberTolerance || l > 99999)
        return fail(block.col(letter), fmt::format("M98 {} must be a whole number of runs from 0 to 99999 (it is {:g})", letter, l));
      times = static_cast<long>(std::nearbyint(l));
    }
  const ControlFlow::Outcome out = flow_.callProgram(*program, {}, false, times, lineStart_, nextLine_, column);
  if (!out.ok) return fail(out.column, out.message);
  jump_ = out.jump;
  return true;
}

bool InterpreterState::macroCall(const Block& block, std::uint32_t column) {
  if (!block.has('P')) return fail(column, "P word (the program number) missing with G65");
  const std::optional<std::string> program = programNumber(block.get('P'));
  if (!program) return fail(block.col('P'), "G65 P must be a program number");
  long times = 1;
  if (block.has('L')) {
    const double l = block.get('L');
    if (l < 0 || std::fabs(l - std::nearbyint(l)) > kWholeNumberTolerance || l > 99999)
      return fail(block.col('L'), fmt::format("G65 L must be a whole number of runs from 0 to 99999 (it is {:g})", l));
    times = static_cast<long>(std::nearbyint(l));
  }
  std::vector<std::pair<int, double>> arguments;
  for (const auto& a : kMacroArguments)
    if (block.has(a.letter)) arguments.emplace_back(a.parameter, block.get(a.letter));
  if (block.mCount > 0) return fail(block.mColumn[0], "M words cannot stand with G65 (M is an argument there)");
  const ControlFlow::Outcome out = flow_.callProgram(*program, arguments, true, times, lineStart_, nextLine_, column);
  if (!out.ok) return fail(out.column, out.message);
  jump_ = out.jump;
  return true;
}

}  // namespace isurface::gcode
