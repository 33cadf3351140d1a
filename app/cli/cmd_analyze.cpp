// isurface-cli analyze: quality prediction. Regions where adjacent passes or consecutive samples
// disagree beyond thresholds, ranked by severity, with their G-code lines, as JSON (and a map).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "command.h"
#include "inputs.h"
#include "output_options.h"
#include "isurface/io/atomic_file.h"
#include "isurface/analysis/quality_regions.h"
#include "isurface/map/quality_map.h"
#include "analysis_picture.h"
#include "progress.h"
#include "trajectory_input.h"
#include "number_options.h"
#include "isurface/base/json_text.h"

namespace isurface::cli {
namespace {

struct AnalyzeOptions {
  std::string gcode, biip, output, png;
  MachineOption machine;
  GapLimitOption gapLimit;
  bool force = false;
  QualityThresholds thresholds;
  std::size_t top = 20;
  AnalysisPainter painter = nullptr;
};

nlohmann::json point(const Vec3& p) { return nlohmann::json::array({p.x(), p.y(), p.z()}); }

void requirePositive(double value, const char* option) {
  if (!(value > 0)) throw InputError(Diagnostic{"", 0, 0, std::string(option) + " must be greater than 0"});
}

int runAnalyze(const AnalyzeOptions& o) {
  requirePositive(o.thresholds.speedInconsistency, "--speed-threshold");
  requirePositive(o.thresholds.accelInconsistency, "--accel-threshold");
  requirePositive(o.thresholds.jerk, "--jerk-threshold");
  const double gapLimit = o.gapLimit.checked();
  const OpenedRun run = openRunOnTerminal({o.gcode, o.biip}, o.machine, o.force);
  const Program& program = *run.program;
  const Trajectory& samples = *run.samples;
  ProgressLine progress("analysing");
  vis::QualityMapRequest request;
  request.quantity = Quantity::SpeedInconsistency;
  request.gapLimit = gapLimit;
  request.fixedRange = ValueRange{0, 2 * o.thresholds.speedInconsistency};
  request.caption = std::filesystem::path(o.gcode).filename().string() + ": predicted defects";
  vis::QualityMap map = vis::buildQualityMap(samples, &program, request);
  const QualityReport report = findQualityRegions(samples, *map.mesh, o.thresholds);
  progress.finish();

  nlohmann::json regions = nlohmann::json::array();
  for (std::size_t k = 0; k < report.regions.size() && k < o.top; ++k) {
    const QualityRegion& r = report.regions[k];
    regions.push_back({{"rank", k + 1},
                       {"severity", r.severity},
                       {"lines", {r.firstLine, r.lastLine}},
                       {"vertices", r.vertices},
                       {"area_mm2", r.area},
                       {"bounding_box", {{"min", point(r.lower)}, {"max", point(r.upper)}}},
                       {"centroid", point(r.centroid)},
                       {"at_pass_ends", r.atPassEnds},
                       {"worst_sample", r.worstSample},
                       {"worst_line", samples.line[r.worstSample]},
                       {"max_speed_inconsistency_mm_min", r.maxSpeedInconsistency},
                       {"max_accel_inconsistency_mm_s2", r.maxAccelInconsistency},
                       {"max_jerk_mm_s3", r.maxJerk},
                       {"max_predicted_deviation_um", samples.hasFeedback() ? nlohmann::json(r.maxDeviation) : nlohmann::json()}});
  }
  const nlohmann::json out = {
      {"source", o.gcode},
      {"samples", samples.size()},
      {"passes", map.passes.passes.size()},
      {"pattern", pathPatternName(map.passes.pattern)},
      {"thresholds",
       {{"speed_inconsistency_mm_min", o.thresholds.speedInconsistency},
        {"accel_inconsistency_mm_s2", o.thresholds.accelInconsistency},
        {"jerk_mm_s3", o.thresholds.jerk}}},
      {"vertices", report.vertices},
      {"flagged_vertices", report.flaggedVertices},
      {"region_count", report.regions.size()},
      {"regions", regions}};
  writeFileAtomically(o.output, jsonText(out, 2) + "\n");

  if (!o.png.empty()) {
    if (!o.painter) throw InputError(Diagnostic{o.png, 0, 0, "pictures are drawn by isurface-cli-all, beside isurface-cli"});
    o.painter(AnalysisPicture{map, samples, report, o.png});
  }
  std::printf("%s: %zu regions beyond the thresholds (%zu of %zu vertices)", o.output.c_str(), report.regions.size(),
              report.flaggedVertices, report.vertices);
  if (!report.regions.empty())
    std::printf("; worst at lines %u-%u, severity %.1f%s", report.regions.front().firstLine,
                report.regions.front().lastLine, report.regions.front().severity,
                report.regions.front().atPassEnds ? " (where passes start and end)" : "");
  const QualityRegion* inside = worstRegionInsidePasses(report);
  if (inside && inside != &report.regions.front())
    std::printf("; worst inside the passes at lines %u-%u, severity %.1f", inside->firstLine, inside->lastLine,
                inside->severity);
  std::printf("\n");
  return kExitOk;
}

}  // namespace

Command analyzeCommand(AnalysisPainter painter) {
  return Command{"analyze", "Predict surface defects: regions where adjacent passes or consecutive samples disagree",
    [painter](CLI::App& sub) {
      auto o = std::make_shared<AnalyzeOptions>();
      o->painter = painter;
      sub.add_option("gcode", o->gcode, "G-code program")->required();
      sub.add_option("biip", o->biip, "Biip dump of the program (default: simulate it)");
      outputOption(sub.add_option("-o,--output", o->output, "JSON report to write"))->required();
      outputOption(sub.add_option("--png", o->png, "also render the map of speed inconsistency, worst line glowing"));
      sub.add_option("--speed-threshold", o->thresholds.speedInconsistency,
                     "speed difference between neighbouring passes, mm/min")
          ->capture_default_str()
          ->check(numberFrom(0, 1e9, true));
      sub.add_option("--accel-threshold", o->thresholds.accelInconsistency,
                     "acceleration difference between neighbouring passes, mm/s^2")
          ->capture_default_str()
          ->check(numberFrom(0, 1e12, true));
      sub.add_option("--jerk-threshold", o->thresholds.jerk, "path jerk, mm/s^3")->capture_default_str()->check(numberFrom(0, 1e12, true));
      sub.add_option("--top", o->top, "regions listed at most")->capture_default_str()->check(wholeNumberFrom(0, 1000000));
      o->machine.addTo(sub, "machine description for the simulation (JSON)");
      o->gapLimit.addTo(sub);
      sub.add_flag("--force", o->force, "use the dump even if it does not look like the program's own");
      return [o] { return runAnalyze(*o); };
    }};
}

}  // namespace isurface::cli
