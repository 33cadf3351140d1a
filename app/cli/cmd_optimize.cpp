// isurface-cli optimize: re-optimise a region of a program (constant speed intervals, Akima
// fitting, interval speed planning), write the new program, re-simulate both and compare.
#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "command.h"
#include "output_options.h"
#include "inputs.h"
#include "isurface/io/atomic_file.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/optimise/optimized_run_comparison.h"
#include "isurface/analysis/quality_regions.h"
#include "isurface/workflow/region_optimisation.h"
#include "progress.h"
#include "isurface/vis/difference_map.h"
#include "isurface/map/quality_map.h"
#include "isurface/vis/quality_scene.h"
#include "isurface/vis/offscreen_render.h"
#include "trajectory_input.h"
#include "number_options.h"
#include "isurface/base/json_text.h"

namespace isurface::cli {
namespace {

struct OptimizeCliOptions {
  std::string input, output, lines, box, report, pngBefore, pngAfter, pngDifference;
  MachineOption machine;
  GapLimitOption gapLimit;
  Objective objective = Objective::Balanced;
  bool automatic = false, all = false;
  double chordTolerance = kDefaultChordTolerance;
};

nlohmann::json figuresJson(const QualityFigures& f) {
  return {{"samples", f.samples},
          {"speed_fluctuation_mm_min", f.speedFluctuation},
          {"speed_inconsistency_p99_mm_min", f.inconsistencyP99},
          {"speed_inconsistency_mean_mm_min", f.inconsistencyMean},
          {"jerk_p99_mm_s3", f.jerkP99},
          {"predicted_deviation_p99_um", f.hasDeviation ? nlohmann::json(f.deviationP99) : nlohmann::json(nullptr)}};
}

nlohmann::json candidatesJson(const RegionOptimisation& r) {
  nlohmann::json out = nlohmann::json::array();
  for (const RegionOptimisation::Outcome& c : r.candidates)
    out.push_back({{"plan", c.plan}, {"kept", c.kept}, {"reason", c.reason}, {"machining_time_s", c.timeAfter},
                    {"region", figuresJson(c.region)}, {"whole_program", figuresJson(c.whole)}});
  return out;
}

// A top view of the run's surface coloured as the request says.
void renderTop(const SurfaceRun& run, const Program& program, vis::QualityMapRequest request, const std::string& caption,
               const std::string& path) {
  request.view = vis::ViewDirection::Top;
  request.caption = caption;
  request.gapLimit = run.gapLimit;
  const vis::QualityMap map = vis::buildQualityMap(*run.samples, &program, request);
  vis::QualityScene scene(map.data, map.style);
  vis::renderSceneToPng(scene, 1200, 800, path);
}

void renderSpeed(const SurfaceRun& run, const Program& program, const std::string& caption, const ValueRange& range,
                 const std::string& path) {
  vis::QualityMapRequest request;
  request.quantity = Quantity::Speed;
  request.fixedRange = range;
  renderTop(run, program, request, caption, path);
}

const std::map<std::string, Objective> kObjectives = {
    {"balanced", Objective::Balanced}, {"time", Objective::Time}, {"quality", Objective::Quality}};

// "X0,Y0,X1,Y1" in mm.
std::pair<Vec3, Vec3> parseBox(const std::string& text) {
  double v[4];
  char extra = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &v[3], &extra) != 4 ||
      !std::all_of(std::begin(v), std::end(v), [](double x) { return std::isfinite(x); }) || v[0] == v[2] || v[1] == v[3])
    throw InputError(Diagnostic{"", 0, 0, "bad --box '" + text + "': expected X0,Y0,X1,Y1 in mm, a box of some width and height"});
  return {Vec3(v[0], v[1], -std::numeric_limits<double>::infinity()), Vec3(v[2], v[3], std::numeric_limits<double>::infinity())};
}

// The region the options name: lines as given, or chosen on the program's surface.
RegionRequest regionOf(const OptimizeCliOptions& o, const SurfaceRun& before) {
  RegionRequest request;
  request.options.chordTolerance = o.chordTolerance;
  request.objective = o.objective;
  if (!o.lines.empty()) {
    request.lines = parseLineRange(o.lines);
    return request;
  }
  const auto box = o.box.empty() ? std::pair<Vec3, Vec3>() : parseBox(o.box);
  const ChosenRegion chosen = o.automatic ? worstRegion(before, o.input)
                              : o.all     ? wholeProgramRegion(before, o.input)
                                          : regionInBox(before, box.first, box.second, o.input);
  request.lines = chosen.lines;
  request.box = std::make_pair(chosen.lower, chosen.upper);
  return request;
}

int runOptimize(const OptimizeCliOptions& o) {
  if (int(!o.lines.empty()) + int(!o.box.empty()) + int(o.automatic) + int(o.all) != 1)
    throw InputError(Diagnostic{"", 0, 0, "give one of --lines A-B, --box X0,Y0,X1,Y1, --auto or --all"});
  if (!o.box.empty()) parseBox(o.box);  // a malformed box fails before any work
  if (!(o.chordTolerance > 0)) throw InputError(Diagnostic{"", 0, 0, "--tolerance must be greater than 0"});
  if (!(o.chordTolerance >= 1e-6 && o.chordTolerance <= 10))
    throw InputError(Diagnostic{"", 0, 0, "--tolerance must be from 1e-06 to 10 mm"});
  const double gapLimit = o.gapLimit.checked();
  const OpenedRun opened = openRunOnTerminal({o.input, ""}, o.machine, false);
  const Machine& machine = opened.machine;
  const Program& program = *opened.program;
  std::ifstream in(o.input, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();

  const SurfaceRun before = surfaceRun(opened.samples, &program, gapLimit);
  RegionRequest request = regionOf(o, before);
  ProgressLine progress("optimising");
  request.onCandidate = [&progress](const std::string& which) { progress.stage(which); };
  const RegionOptimisation r =
      optimiseRegion(text.str(), program, before, machine, request, [&](double f) { progress.update(f); });
  progress.finish();
  // A candidate that is worse is not written: the program goes out as it came in, byte for byte.
  writeFileAtomically(o.output, r.kept ? r.result.text : text.str());
  const OptimizeResult& result = r.result;
  const LineRange range = r.lines;
  const SurfaceRun& after = r.after;
  const Program& newProgram = *r.program;
  const Vec3 &lower = r.lower, &upper = r.upper;
  const double distance = r.maxPathDistance, timeBefore = r.timeBefore, timeAfter = r.timeAfter;
  // The maps of a candidate that was not kept show what was tried, and say so.
  const std::string afterName = r.kept ? o.output : "the candidate not kept";

  nlohmann::json passes = nlohmann::json::array();
  for (const OptimizedPass& p : result.passes)
    passes.push_back({{"lines", {p.firstLine, p.lastLine}}, {"new_lines", {p.newFirstLine, p.newLastLine}},
                      {"old_moves", p.oldMoves}, {"new_moves", p.newMoves}, {"interval_feeds_mm_min", p.intervalFeeds}});
  const nlohmann::json report = {
      {"source", o.input}, {"output", o.output}, {"kept", r.kept}, {"reason", r.reason}, {"plan", r.plan},
      {"objective", objectiveName(r.objective)}, {"candidates", candidatesJson(r)},
      {"lines", {range.first, range.last}},
      {"new_lines", {result.newRange.first, result.newRange.last}},
      {"machining_time_s", {{"before", timeBefore}, {"after", timeAfter}}},
      {"region", {{"before", figuresJson(r.regionBefore)}, {"after", figuresJson(r.regionAfter)}}},
      {"whole_program", {{"before", figuresJson(r.wholeBefore)}, {"after", figuresJson(r.wholeAfter)}}},
      {"max_path_distance_mm", distance}, {"passes", passes},
      {"program_lines", {{"before", r.linesBefore}, {"after", r.linesAfter}}},
      {"compared_box_mm", {{"min", {lower.x(), lower.y()}}, {"max", {upper.x(), upper.y()}}}}};
  if (!o.report.empty()) writeFileAtomically(o.report, jsonText(report, 2) + "\n");
  if (!o.pngBefore.empty() || !o.pngAfter.empty()) {
    const std::vector<float> speeds = vertexQuantity(Quantity::Speed, *before.samples, *before.mesh);
    const ValueRange span = percentileRange(speeds, 1, 99);
    if (!o.pngBefore.empty()) renderSpeed(before, program, o.input + " before", span, o.pngBefore);
    if (!o.pngAfter.empty()) renderSpeed(after, newProgram, afterName + " after", span, o.pngAfter);
  }
  if (!o.pngDifference.empty()) {
    const RunComparison difference = compareOptimizedRuns(*before.samples, *after.samples, result);
    renderTop(before, program, vis::regionDifferenceMapRequest(difference, *before.samples, range),
              afterName + " against " + o.input, o.pngDifference);
  }
  std::printf("%s: %s\n", o.output.c_str(), regionSummary(r).c_str());
  if (!r.kept) std::fprintf(stderr, "warning: %s: not kept (%s); written unchanged\n", o.output.c_str(), r.reason.c_str());
  return kExitOk;
}

}  // namespace

Command optimizeCommand() {
  return Command{"optimize", "Re-optimise a region (constant speed intervals, Akima fitting), write it and compare", [](CLI::App& sub) {
      auto o = std::make_shared<OptimizeCliOptions>();
      sub.add_option("gcode", o->input, "G-code program")->required();
      outputOption(sub.add_option("-o,--output", o->output, "new G-code program to write"))->required();
      sub.add_option("--lines", o->lines, "the region as a line range A-B");
      sub.add_option("--box", o->box, "the passes crossing a box X0,Y0,X1,Y1 (mm, top view), measured inside it");
      sub.add_flag("--auto", o->automatic, "the most severe region that analyze finds");
      sub.add_flag("--all", o->all, "every pass of the program");
      outputOption(sub.add_option("--report", o->report, "comparison report (JSON)"));
      outputOption(sub.add_option("--png-before", o->pngBefore, "speed map before (top view)"));
      outputOption(sub.add_option("--png-after", o->pngAfter, "speed map after, same colour range"));
      outputOption(sub.add_option("--png-diff", o->pngDifference,
                     "speed after minus before (mm/min) on the surface before, passes aligned (top view)"));
      sub.add_option("--tolerance", o->chordTolerance, "chord tolerance of the new G1 moves, mm")
          ->capture_default_str()
          ->check(numberFrom(0, 1, true));
      o->machine.addTo(sub, "machine description (JSON)");
      o->gapLimit.addTo(sub);
      sub.add_option("--objective", o->objective,
                     "balanced: no figure worse, time not longer (the best figures and time together); time: the fastest such "
                     "candidate; quality: the candidate that improves the region most, up to 5 % longer")
          ->transform(CLI::CheckedTransformer(kObjectives, CLI::ignore_case))
          ->default_str("balanced");
      return [o] { return runOptimize(*o); };
    }};
}

}  // namespace isurface::cli
