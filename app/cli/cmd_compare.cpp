// isurface-cli compare: two runs of a program (Biip dumps: simulations or recorded traces)
// aligned by G-code line and arc length; the differences per line and per line range as JSON,
// and run A's surface coloured by the difference as a PNG.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "command.h"
#include "inputs.h"
#include "output_options.h"
#include "isurface/io/atomic_file.h"
#include "isurface/analysis/line_mapping.h"
#include "isurface/analysis/run_comparison.h"
#include "isurface/vis/color_map.h"
#include "isurface/vis/difference_map.h"
#include "isurface/vis/offscreen_render.h"
#include "progress.h"
#include "trajectory_input.h"
#include "isurface/workflow/same_program.h"
#include "number_options.h"
#include "isurface/base/json_text.h"
#include "isurface/vis/quality_scene.h"

namespace isurface::cli {
namespace {

struct CompareOptions {
  std::string runA, runB, gcode, output, png, quantity = "speed", range, view = "iso", colorMap, pattern = "auto";
  bool force = false;
  GapLimitOption gapLimit;
  RunComparisonOptions comparison;
  std::size_t top = 10;
  bool linuxcncLines = false;
};

nlohmann::json figuresJson(const DifferenceFigures& f) {
  return {{"time_a_s", f.timeA},
          {"time_b_s", f.timeB},
          {"time_difference_s", f.timeDifference},
          {"length_a_mm", f.lengthA},
          {"length_b_mm", f.lengthB},
          {"mean_speed_difference_mm_min", f.meanSpeedDifference},
          {"max_speed_difference_mm_min", f.maxSpeedDifference},
          {"max_position_distance_mm", f.maxPositionDistance},
          {"max_path_distance_mm", f.maxPathDistance},
          {"max_feedback_distance_mm", f.maxFeedbackDistance ? nlohmann::json(*f.maxFeedbackDistance) : nlohmann::json()},
          {"samples_a", f.samplesA},
          {"samples_b", f.samplesB}};
}

nlohmann::json rangeJson(const RangeDifference& r) {
  nlohmann::json j = figuresJson(r.figures);
  j["lines"] = {r.firstLine, r.lastLine};
  j["line_count"] = r.lineCount;
  return j;
}

nlohmann::json unmatchedJson(const std::vector<UnmatchedLine>& lines) {
  nlohmann::json out = nlohmann::json::array();
  for (const UnmatchedLine& u : lines) out.push_back({{"line", u.line}, {"samples", u.samples}, {"time_s", u.time}, {"merged_into", u.mergedInto}});
  return out;
}

// A run without a line channel gets its lines from the program, as `import --gcode` does.
Trajectory loadRun(const std::string& path, const Program* program, bool linuxcncLines) {
  Trajectory run = readTrajectory(path);
  if (!run.hasLine && program) {
    LineMapping mapping = mapSamplesToLines(run, *program, linuxcncLines ? linuxcncLineMappingOptions() : LineMappingOptions{});
    std::printf("%s: no line channel; mapped to the program's lines, %.1f%% of samples within %g mm\n", path.c_str(),
                100.0 * mapping.report.fractionWithin, mapping.report.tolerance);
    run.line = mapping.line;
    run.hasLine = true;
  }
  return run;
}

nlohmann::json reportJson(const CompareOptions& o, const RunComparison& c, ComparisonQuantity quantity,
                          const Trajectory& a, const Trajectory& b) {
  nlohmann::json worst = nlohmann::json::array();
  for (std::size_t index : c.worstRanges(quantity, o.top)) {
    nlohmann::json r = rangeJson(c.ranges[index]);
    r["rank"] = worst.size() + 1;
    worst.push_back(std::move(r));
  }
  nlohmann::json ranges = nlohmann::json::array(), lines = nlohmann::json::array();
  for (const RangeDifference& r : c.ranges) ranges.push_back(rangeJson(r));
  for (const LineDifference& l : c.lines) {
    nlohmann::json j = figuresJson(l.figures);
    j["line"] = l.line;
    lines.push_back(std::move(j));
  }
  nlohmann::json totals = figuresJson(c.total);
  totals["time_difference_percent"] = c.total.timeA > 0 ? 100.0 * c.total.timeDifference / c.total.timeA : 0.0;
  return {{"run_a", {{"file", o.runA}, {"samples", a.size()}, {"duration_s", c.durationA}, {"line_coverage", c.coverageA}}},
          {"run_b", {{"file", o.runB}, {"samples", b.size()}, {"duration_s", c.durationB}, {"line_coverage", c.coverageB}}},
          {"differences", "B minus A, B aligned to A per G-code line by arc length from the line's first sample"},
          {"feedback_compared", c.feedbackCompared},
          {"ranked_by", comparisonQuantityName(quantity)},
          {"common_lines", c.lines.size()},
          {"totals", totals},
          {"only_in_a", unmatchedJson(c.onlyInA)},
          {"only_in_b", unmatchedJson(c.onlyInB)},
          {"worst_ranges", worst},
          {"ranges", ranges},
          {"lines", lines}};
}

void printSummary(const CompareOptions& o, const RunComparison& c, ComparisonQuantity quantity) {
  const DifferenceFigures& t = c.total;
  std::printf("%zu common lines (%zu only in A, %zu only in B, each compared with the common line before it); "
              "motion time A %.3f s, B %.3f s, B - A %+.3f s (%+.2f%%)\n",
              c.lines.size(), c.onlyInA.size(), c.onlyInB.size(), t.timeA, t.timeB, t.timeDifference,
              t.timeA > 0 ? 100.0 * t.timeDifference / t.timeA : 0.0);
  std::printf("speed B - A: mean %+.1f mm/min, largest %+.1f mm/min; position at the same arc length: max %.4f mm; "
              "path to path: max %.4f mm\n",
              t.meanSpeedDifference, t.maxSpeedDifference, t.maxPositionDistance, t.maxPathDistance);
  for (std::size_t index : c.worstRanges(quantity, std::min<std::size_t>(o.top, 3))) {
    const RangeDifference& r = c.ranges[index];
    std::printf("  lines %u-%u: time %+.3f s, speed mean %+.1f max %+.1f mm/min, position max %.4f mm\n", r.firstLine,
                r.lastLine, r.figures.timeDifference, r.figures.meanSpeedDifference, r.figures.maxSpeedDifference,
                r.figures.maxPositionDistance);
  }
}

int runCompare(const CompareOptions& o) {
  const auto quantity = parseComparisonQuantity(o.quantity);
  if (!quantity) throw InputError(Diagnostic{"--quantity", 0, 0, "unknown quantity '" + o.quantity + "' (speed, position, time)"});
  const auto view = vis::parseView(o.view);
  if (!view) throw InputError(Diagnostic{"--view", 0, 0, "unknown view '" + o.view + "' (iso, top, front, left)"});
  const double gapLimit = o.gapLimit.checked();
  if (o.comparison.maxRangeLines == 0) throw InputError(Diagnostic{"--range-lines", 0, 0, "must be at least 1"});
  std::optional<ValueRange> fixedRange;
  if (!o.range.empty()) fixedRange = parseRange(o.range);
  if (!o.colorMap.empty()) vis::makeLookupTable(o.colorMap, 0, 1);  // an unknown name fails before any work

  std::optional<Program> program;
  if (!o.gcode.empty()) program = loadProgram(o.gcode, false, false);
  const Program* programPointer = program ? &*program : nullptr;
  const Trajectory a = loadRun(o.runA, programPointer, o.linuxcncLines);
  const Trajectory b = loadRun(o.runB, programPointer, o.linuxcncLines);
  if (!o.force) {
    if (const auto why = runsMismatch(a, b))
      throw InputError(Diagnostic{o.runB, 0, 0, "is not a run of " + o.runA + "'s program: " + *why + " (--force compares them anyway)"});
    // The program given must be the one they ran: its lines name their samples in the report.
    if (program)
      for (const auto& [run, path] : {std::pair<const Trajectory&, const std::string&>{a, o.runA}, {b, o.runB}})
        if (const auto why = samplesMismatch(run, *program))
          throw InputError(Diagnostic{o.gcode, 0, 0, "is not the program " + path + " ran: " + *why + " (--force compares them anyway)"});
  }
  ProgressLine progress("comparing");
  const RunComparison comparison = compareRuns(a, b, o.comparison);
  progress.finish();

  // The map is built before anything is written: a run with no surface writes nothing.
  std::optional<vis::QualityMap> map;
  if (!o.png.empty()) {
    vis::QualityMapRequest request = vis::differenceMapRequest(comparison, *quantity, fixedRange, o.colorMap);
    request.view = *view;
    request.gapLimit = gapLimit;
    request.pattern = parsePathPattern(o.pattern);
    request.caption = std::filesystem::path(o.runB).filename().string() + " against " +
                      std::filesystem::path(o.runA).filename().string();
    map = vis::buildQualityMap(a, programPointer, request);
    map->style.fontSize = vis::fontSizeForHeight(1000);
  }
  writeFileAtomically(o.output, jsonText(reportJson(o, comparison, *quantity, a, b), 2) + "\n");
  printSummary(o, comparison, *quantity);
  std::printf("-> %s\n", o.output.c_str());
  if (map) {
    vis::QualityScene scene(map->data, map->style);
    vis::renderSceneToPng(scene, 1600, 1000, o.png);
    std::printf("-> %s: %s [%s] %.4g .. %.4g\n", o.png.c_str(), map->style.quantityLabel.c_str(),
                map->style.unit.c_str(), map->style.range.lo, map->style.range.hi);
  }
  return kExitOk;
}

}  // namespace

Command compareCommand() {
  return Command{"compare", "Compare two runs of a program (Biip dumps) by G-code line and arc length; JSON and a difference map",
    [](CLI::App& sub) {
      auto o = std::make_shared<CompareOptions>();
      sub.add_option("a", o->runA, "run A, the reference (Biip dump)")->required();
      sub.add_option("b", o->runB, "run B, compared with A (Biip dump)")->required();
      outputOption(sub.add_option("-o,--output", o->output, "JSON report to write"))->required();
      sub.add_option("--gcode", o->gcode, "the program both ran: its tool path in the map, and lines for a run without them");
      outputOption(sub.add_option("--png", o->png, "also render run A's surface coloured by the difference"));
      sub.add_option("--quantity", o->quantity, "difference to map and rank ranges by: speed (mm/min), position (mm), "
                                                "time (s)")->capture_default_str();
      sub.add_option("--range", o->range, "colour range LO:HI (default: symmetric 99th percentile; position 0 to it)");
      sub.add_option("--view", o->view, "iso, top, front or left")->capture_default_str();
      sub.add_option("--cmap", o->colorMap, "colour map (default coolwarm for speed and time, viridis for position)");
      o->gapLimit.addTo(sub);
      sub.add_option("--pattern", o->pattern, "how the map's passes are found: auto, direction-parallel, "
                                              "contour-parallel, no-boundary")->capture_default_str();
      sub.add_option("--top", o->top, "worst ranges listed")->capture_default_str()->check(wholeNumberFrom(0, 1000000));
      sub.add_option("--range-lines", o->comparison.maxRangeLines, "lines a range holds at most")
          ->capture_default_str()
          ->check(wholeNumberFrom(1, 1000000));
      sub.add_option("--time-tolerance", o->comparison.timeTolerance,
                     "s; a line's time difference within it counts as equal when grouping ranges")
          ->capture_default_str()
          ->check(numberFrom(0, 3600));
      sub.add_flag("--linuxcnc-lines", o->linuxcncLines, "mapping lines for a run without them: as LinuxCNC reports blends");
      sub.add_flag("--force", o->force, "compare runs that do not look like runs of one program");
      return [o] { return runCompare(*o); };
    }};
}

}  // namespace isurface::cli
