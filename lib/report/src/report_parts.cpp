#include "report_parts.h"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "isurface/base/time_format.h"
#include "isurface/vis/offscreen_render.h"
#include "isurface/vis/quality_scene.h"

namespace isurface::report {

std::string renderMapPng(const OpenedRun& run, vis::QualityMapRequest request, double gapLimit,
                         const std::optional<std::pair<Vec3, Vec3>>& box) {
  request.inch = run.program && run.program->inch;
  request.gapLimit = gapLimit;
  if (request.caption.empty())
    request.caption =
        std::filesystem::path(run.files.program.empty() ? run.files.dump : run.files.program).filename().string();
  vis::QualityMap map = vis::buildQualityMap(*run.samples, run.program.get(), request);
  map.style.fontSize = vis::fontSizeForHeight(kMapHeight);
  vis::QualityScene scene(map.data, map.style);
  if (box) scene.frameBox(box->first, box->second);
  return vis::renderSceneToPngBytes(scene, kMapWidth, kMapHeight);
}

std::string duration(double seconds) { return formatDuration(seconds) + fmt::format(" ({:.3f} s)", seconds); }

namespace {

std::string change(double before, double after) {
  if (!(before > 0)) return "-";
  return fmt::format("{:+.1f} %", 100.0 * (after - before) / before);
}

}  // namespace

void figuresTable(HtmlDocument& doc, const std::string& beforeName, const std::string& afterName, double timeBefore,
                  double timeAfter, const QualityFigures& before, const QualityFigures& after) {
  std::vector<std::vector<std::string>> rows = {{"figure", beforeName, afterName, "change"}};
  rows.push_back({"machining time", duration(timeBefore), duration(timeAfter), change(timeBefore, timeAfter)});
  auto row = [&](const std::string& name, double a, double b, const char* unit, const char* format) {
    rows.push_back({name, fmt::format(fmt::runtime(format), a) + unit, fmt::format(fmt::runtime(format), b) + unit,
                    change(a, b)});
  };
  row("speed fluctuation (RMS about the 100 ms mean)", before.speedFluctuation, after.speedFluctuation, " mm/min", "{:.1f}");
  row("adjacent-pass inconsistency, p99", before.inconsistencyP99, after.inconsistencyP99, " mm/min", "{:.1f}");
  row("adjacent-pass inconsistency, mean", before.inconsistencyMean, after.inconsistencyMean, " mm/min", "{:.1f}");
  row("jerk, p99", before.jerkP99, after.jerkP99, " mm/s^3", "{:.0f}");
  if (before.hasDeviation && after.hasDeviation)
    row("predicted deviation, p99", before.deviationP99, after.deviationP99, " um", "{:.2f}");
  doc.table(rows, "figures");
}

nlohmann::json figuresJson(double time, const QualityFigures& f) {
  return {{"machining_time_s", time},
          {"surface_samples", f.samples},
          {"speed_fluctuation_mm_min", f.speedFluctuation},
          {"speed_inconsistency_p99_mm_min", f.inconsistencyP99},
          {"speed_inconsistency_mean_mm_min", f.inconsistencyMean},
          {"jerk_p99_mm_s3", f.jerkP99},
          {"predicted_deviation_p99_um", f.hasDeviation ? nlohmann::json(f.deviationP99) : nlohmann::json(nullptr)}};
}

}  // namespace isurface::report
