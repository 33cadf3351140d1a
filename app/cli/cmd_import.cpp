// isurface-cli import: a recorded machine trace (LinuxCNC halsampler text or CSV) -> Biip dump.
#include <cmath>
#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "command.h"
#include "inputs.h"
#include "output_options.h"
#include "isurface/analysis/line_mapping.h"
#include "isurface/io/trace_import.h"
#include "isurface/io/trajectory_writing.h"
#include "number_options.h"

namespace isurface::cli {
namespace {

// Of a trace's samples, the share that must lie within the line mapping's tolerance of the
// program's moves for the trace to be taken as the program's.
constexpr double kLeastShareOnProgram = 0.5;

struct ImportOptions {
  std::string format, input, output, map, preset, gcode;
  double cycle = 0;  // s, 0: the format's or preset's default
  std::size_t lookahead = LineMappingOptions{}.lookaheadMoves;
  bool linuxcncLines = false;
  bool force = false;
};

TraceImportOptions traceOptions(const ImportOptions& o) {
  TraceImportOptions t;
  if (!o.preset.empty()) {
    if (o.preset != "umich") throw InputError(Diagnostic{"--preset", 0, 0, "unknown preset '" + o.preset + "' (known: umich)"});
    if (o.format != "csv") throw InputError(Diagnostic{"--preset", 0, 0, "preset 'umich' is for csv traces"});
    t = umichPreset();
  }
  // --map replaces the whole default mapping: leaving a column out is how to drop it.
  if (!o.map.empty()) t.columns = parseColumnMap(o.map);
  if (o.cycle > 0) t.cycle = o.cycle;
  if (o.format == "csv" && t.columns.empty())
    throw InputError(Diagnostic{o.input, 0, 0, "a csv trace needs --map or --preset"});
  return t;
}

void printMappingReport(const LineMappingReport& r) {
  std::printf("line mapping: %zu samples, distance to the path mean %.4f mm, max %.4f mm, %.1f%% within %g mm\n",
              r.samples, r.meanDistance, r.maxDistance, 100.0 * r.fractionWithin, r.tolerance);
}

// Positions a recorder wrote as inf or nan (or beyond a double, 1e309) are kept, as a dump keeps
// them, and left out of every figure: said here, where the file is still at hand.
void warnOfNonFinitePositions(const Trajectory& trace, const std::string& file) {
  std::size_t count = 0, first = 0;
  for (std::size_t i = 0; i < trace.size(); ++i)
    if (!std::isfinite(trace.x[i]) || !std::isfinite(trace.y[i]) || !std::isfinite(trace.z[i]))
      if (count++ == 0) first = i;
  if (count > 0)
    std::fprintf(stderr, "warning: %s: %zu of %zu samples have a non-finite x, y or z (the first: sample %zu); they are "
                 "kept out of the surface and every figure\n",
                 file.c_str(), count, trace.size(), first + 1);
}

int runImport(const ImportOptions& o) {
  if (!(o.cycle >= 0)) throw InputError(Diagnostic{"--cycle", 0, 0, "the cycle must be > 0 s"});
  const TraceImportOptions options = traceOptions(o);
  Trajectory trace = o.format == "halsampler" ? importHalsampler(o.input, options) : importCsv(o.input, options);
  std::printf("%s: %zu samples at %g ms%s%s\n", o.input.c_str(), trace.size(), trace.cycle * 1000.0,
              trace.hasLine ? ", with lines" : "", trace.hasFeedback() ? ", with feedback" : "");
  warnOfNonFinitePositions(trace, o.input);
  if (!o.gcode.empty()) {
    const Program program = loadProgram(o.gcode, false, false);
    LineMappingOptions mappingOptions = o.linuxcncLines ? linuxcncLineMappingOptions() : LineMappingOptions{};
    mappingOptions.lookaheadMoves = o.lookahead;
    LineMapping mapping = mapSamplesToLines(trace, program, mappingOptions);
    printMappingReport(mapping.report);
    // A trace of another program maps to lines all the same, each sample to its nearest move.
    if (!o.force && mapping.report.samples > 0 && mapping.report.fractionWithin < kLeastShareOnProgram)
      throw InputError(Diagnostic{o.input, 0, 0,
                                  fmt::format("is not a trace of {}: only {:.1f} % of its samples lie within {:g} mm of "
                                              "the program's moves (--force imports it anyway)",
                                              o.gcode, 100.0 * mapping.report.fractionWithin, mapping.report.tolerance)});
    if (trace.hasLine) {
      // The recorded lines are kept; how far the mapping agrees tells how trustworthy it is.
      std::size_t compared = 0, agree = 0;
      trace.line.forEachRun([&](std::uint32_t line, std::size_t begin, std::size_t end) {
        if (line == 0) return;
        compared += end - begin;
        for (std::size_t i = begin; i < end; ++i) agree += line == mapping.line[i];
      });
      std::printf("recorded lines kept; the mapping agrees on %.1f%% of %zu samples with a line\n",
                  compared ? 100.0 * double(agree) / double(compared) : 0.0, compared);
    } else {
      trace.line = RunChannel<std::uint32_t>(mapping.line);
      trace.hasLine = true;
    }
    // The dump is a run of that program: render, compare and the window join the two without --force.
    trace.source = o.gcode;
  }
  writeTrajectoryBiip(trace, o.output);
  std::printf("-> %s\n", o.output.c_str());
  return kExitOk;
}

}  // namespace

Command importCommand() {
  return Command{"import", "Convert a recorded machine trace (halsampler text or CSV) to a Biip dump",
    [](CLI::App& sub) {
      auto o = std::make_shared<ImportOptions>();
      sub.add_option("format", o->format, "trace format")->required()->check(CLI::IsMember({"halsampler", "csv"}));
      sub.add_option("trace", o->input, "recorded trace file")->required();
      outputOption(sub.add_option("-o,--output", o->output, "Biip file to write"))->required();
      sub.add_option("--map", o->map,
                     "role=column,... (roles x y z fb_x fb_y fb_z feed line t, others kept as channels; "
                     "columns: 0-based index for halsampler, header name for csv)");
      sub.add_option("--preset", o->preset, "csv column preset: umich");
      sub.add_option("--cycle", o->cycle, "sample period, s (default 0.001; umich 0.1)")->check(numberFrom(1e-6, 60));
      sub.add_option("--gcode", o->gcode, "the program the trace ran: maps samples to lines when the trace has none");
      sub.add_flag("--force", o->force, "with --gcode: import a trace even if it does not follow the program");
      sub.add_option("--lookahead", o->lookahead, "line mapping: moves ahead a sample may land on")->check(wholeNumberFrom(0, 100000));
      sub.add_flag("--linuxcnc-lines", o->linuxcncLines,
                   "line mapping: give blends into a move its line, as LinuxCNC reports them");
      return [o] { return runImport(*o); };
    }};
}

}  // namespace isurface::cli
