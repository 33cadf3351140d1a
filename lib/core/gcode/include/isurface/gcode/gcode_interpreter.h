#pragma once
// RS274/NGC interpreter for real CAM output: turns G-code text into a Program of exact moves.
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "isurface/gcode/program.h"

namespace isurface {

struct InterpreterOptions {
  // Skip a bad block, record its error and go on (the caller still exits non-zero).
  bool keepGoing = false;
  // Reference positions of G28 and G30, machine = workpiece coordinates here, mm.
  Vec3 g28Position = Vec3::Zero();
  Vec3 g30Position = Vec3::Zero();
  // Position before the first move, mm.
  Vec3 startPosition = Vec3::Zero();
  // The control's power-on units (G20 when true); a program that moves before saying G20 or
  // G21 gets one warning naming them.
  bool inchAtPowerOn = false;
  // The control's power-on plane and distance mode (RS274/NGC: G17, G90). When a machine
  // description names them (`powerOnModesNamed`), a program that moves before stating its own
  // gets one warning naming the mode used.
  Plane planeAtPowerOn = Plane::XY;
  bool incrementalAtPowerOn = false;
  bool powerOnModesNamed = false;
  // Fanuc and Haas controls keep G0-G3 apart from the canned cycles: after G80, axis words go
  // on with the G0-G3 motion that was in effect before the cycle (RS274/NGC: an error).
  bool fanuc = false;
  // Centre-format arcs (LinuxCNC's rule): an arc whose end radius differs from its start radius
  // by more than arcRadiusTolerance AND by more than arcRadiusRelativeTolerance of the larger
  // radius is an error, and so is any difference over 100 times arcRadiusTolerance. LinuxCNC's
  // values: 0.0283 mm in G21 programs, 0.002828 inch (0.0718 mm) in G20 programs. mm.
  double arcRadiusTolerance = 0.0283;
  double arcRadiusToleranceInch = 0.0718;  // used instead of the above while G20 is in effect
  // The relative part of that rule: a fraction of the larger radius.
  double arcRadiusRelativeTolerance = 0.001;
  // R-format arcs: a radius short of half the chord by at most this is taken as a semicircle;
  // centre-format arcs: a start or end radius under this is a zero-radius error. mm (LinuxCNC's
  // RADIUS_TOLERANCE, 0.00005 inch).
  double arcReachTolerance = 0.00127;
  // Tool diameters by tool number (mm), for cutter radius compensation (G41 / G42 D<tool>, or
  // the tool in the spindle). Empty: every tool's radius is 0 and compensated moves follow the
  // programmed path.
  std::map<int, double> toolDiameters;
  // Folders searched for subroutines in files of their own: `o<name> call` reads name.ngc, a
  // Fanuc M98 / G65 P1234 reads O1234 (or O1234.nc, .ngc, .txt). Reading a file adds the
  // program's own folder last.
  std::vector<std::string> subroutinePath;
  // The bound on a run's loops, calls and jumps back: the lines they read again (executed or
  // read past), over the whole run: the lines read may outnumber the program's by this much. A program that goes past it is taken to never end, and its
  // interpretation stops with an error naming the loops and calls in progress. Real programs
  // read at most a few million lines again; a never-ending one reaches this in seconds.
  std::uint64_t maxLinesReadAgain = kDefaultMaxLinesReadAgain;
  static constexpr std::uint64_t kDefaultMaxLinesReadAgain = 10000000;
  // When set, told the call stack of every move made (its index in the program and, outermost
  // first, "LINE name" of each call in progress joined by " > ", with "file:" before the line
  // when the call stands in a subroutine file; empty outside any call). Moves of a block found bad are made
  // again under the same indices, so a later report replaces an earlier one.
  std::function<void(std::uint64_t moveIndex, const std::string& stack)> callStack;
  // Called now and then with the fraction of the input read, 0..1.
  std::function<void(double)> progress;
};

struct InterpretResult {
  Program program;
  std::vector<Diagnostic> errors;  // empty on success; with keepGoing, every bad block
  bool ok() const { return errors.empty(); }
};

// Interprets text held in memory. `sourceName` is used in diagnostics.
InterpretResult interpretGcode(std::string_view text, const std::string& sourceName,
                               const InterpreterOptions& options = {});

// Maps and interprets a file. A file that cannot be read is reported as an error diagnostic.
InterpretResult interpretGcodeFile(const std::string& path, const InterpreterOptions& options = {});

}  // namespace isurface
