#include "isurface/report/program_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "isurface/analysis/kinematics.h"
#include "isurface/analysis/quality_regions.h"
#include "isurface/analysis/quantities.h"
#include "isurface/app_model/text_lines.h"
#include "isurface/base/units.h"
#include "isurface/vis/line_plot.h"
#include "report_beside.h"
#include "report_parts.h"

namespace isurface::report {
namespace {

constexpr int kPlotWidth = 720, kPlotHeight = 260;
constexpr std::size_t kPlotPoints = 4000;      // a plot's samples are thinned to about this many
constexpr double kPlotSeconds = 1.5;           // s either side of a region's worst sample
constexpr std::uint32_t kExcerptContext = 12;  // G-code lines either side of a region's worst line

void summary(HtmlDocument& doc, const OpenedRun& run, nlohmann::json& out) {
  const Trajectory& t = *run.samples;
  double length = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double d = (t.commanded(i) - t.commanded(i - 1)).norm();
    if (std::isfinite(d)) length += d;
  }
  float lowFeed = 0, highFeed = 0;
  if (run.program)
    for (const Move& m : run.program->moves)
      if (m.kind == MoveKind::Linear || m.isArc()) {
        lowFeed = lowFeed == 0 ? m.feed : std::min(lowFeed, m.feed);
        highFeed = std::max(highFeed, m.feed);
      }
  const bool inch = run.program && run.program->inch;
  const double time = machiningTime(t);
  const std::string feeds =
      highFeed <= 0 ? "none"
      : inch        ? fmt::format("F{:g} to F{:g} in/min", lowFeed / kMmPerInch, highFeed / kMmPerInch)
                    : fmt::format("F{:g} to F{:g} mm/min", lowFeed, highFeed);
  doc.table({{"", "this program"},
             {"Program", run.files.program.empty() ? "(none: a dump alone)" : run.files.program},
             {"Samples from", run.files.dump.empty() ? "a simulation of the program" : run.files.dump},
             {"Machine", run.machineKnown ? run.machine.name : "not named by the dump"},
             {"Machining time", duration(time)},
             {"Path length", fmt::format("{:.1f} mm", length)},
             {"Samples", fmt::format("{} at {:g} ms", t.size(), t.cycle * 1000)},
             {"Programmed feeds", feeds},
             {"Units of the program", inch ? "inch (G20)" : "mm"}});
  out["summary"] = {{"program", run.files.program}, {"dump", run.files.dump}, {"machine", run.machine.name},
                    {"machining_time_s", time}, {"path_length_mm", length}, {"samples", t.size()},
                    {"cycle_s", t.cycle}, {"inch", inch}};
}

std::vector<Quantity> mapQuantities(const Trajectory& t) {
  std::vector<Quantity> q = {Quantity::Speed, Quantity::Acceleration, Quantity::Jerk, Quantity::SpeedInconsistency};
  if (t.hasFeedback()) q.push_back(Quantity::Deviation);
  return q;
}

std::size_t maps(HtmlDocument& doc, const OpenedRun& run, double gapLimit, const ProgressCallback& progress) {
  doc.raw("<div class=\"maps\">\n");
  const std::vector<Quantity> quantities = mapQuantities(*run.samples);
  for (std::size_t k = 0; k < quantities.size(); ++k) {
    for (const auto view : {vis::ViewDirection::Iso, vis::ViewDirection::Top}) {
      vis::QualityMapRequest request;
      request.quantity = quantities[k];
      request.view = view;
      const QuantityInfo& info = quantityInfo(quantities[k]);
      doc.image(renderMapPng(run, request, gapLimit),
                fmt::format("{} ({}), {} view", info.label, info.unit, view == vis::ViewDirection::Iso ? "iso" : "top"));
    }
    if (progress) progress(double(k + 1) / double(quantities.size()));
  }
  doc.raw("</div>\n");
  return quantities.size() * 2;
}

// Speed and acceleration against time around the region's worst sample: a region may span
// many passes, and the seconds around its worst point show what the machine did there.
void regionPlots(HtmlDocument& doc, const Trajectory& t, const QualityRegion& r, const std::vector<double>& speed,
                 const std::vector<double>& accel) {
  const double centre = t.timeAt(r.worstSample);
  std::size_t first = r.worstSample, last = r.worstSample;
  while (first > 0 && t.timeAt(first - 1) >= centre - kPlotSeconds) --first;
  while (last + 1 < t.size() && t.timeAt(last + 1) <= centre + kPlotSeconds) ++last;
  if (first >= last) return;
  const std::size_t stride = std::max<std::size_t>(1, (last - first) / kPlotPoints);
  const std::string around = fmt::format("around the worst point (line {}, {:.2f} s)", t.line[r.worstSample], centre);
  vis::LinePlot speedPlot{"Path speed " + around, "time (s)", "mm/min", {}, {{"speed (mm/min)", {}}}};
  vis::LinePlot accelPlot{"Tangential acceleration " + around, "time (s)", "mm/s^2", {}, {{"acceleration (mm/s^2)", {}}}};
  for (std::size_t i = first; i <= last; i += stride) {
    speedPlot.x.push_back(t.timeAt(i));
    accelPlot.x.push_back(t.timeAt(i));
    speedPlot.series[0].y.push_back(speed[i]);
    accelPlot.series[0].y.push_back(accel[i]);
  }
  doc.raw("<div class=\"maps\">\n");
  doc.image(vis::plotToPng(speedPlot, kPlotWidth, kPlotHeight), speedPlot.title);
  doc.image(vis::plotToPng(accelPlot, kPlotWidth, kPlotHeight), accelPlot.title);
  doc.raw("</div>\n");
}

void excerpt(HtmlDocument& doc, const app_model::TextLines& lines, const QualityRegion& r, std::uint32_t worstLine) {
  std::vector<std::pair<std::uint32_t, std::string>> numbered;
  const std::uint32_t from = std::max(r.firstLine, worstLine > kExcerptContext ? worstLine - kExcerptContext : 1u);
  const std::uint32_t to = std::min<std::uint32_t>(
      {r.lastLine, worstLine + kExcerptContext, static_cast<std::uint32_t>(lines.count())});
  for (std::uint32_t n = from; n <= to; ++n) numbered.emplace_back(n, std::string(lines.line(n)));
  doc.paragraph(
      fmt::format("G-code around the worst line (lines {}-{} of the region's {}-{}):", from, to, r.firstLine, r.lastLine));
  doc.code(numbered, worstLine);
}

void oneRegion(HtmlDocument& doc, const OpenedRun& run, double gapLimit, const QualityRegion& r, int number,
               const std::optional<app_model::TextLines>& lines, const std::vector<double>& speed,
               const std::vector<double>& accel) {
  const Trajectory& t = *run.samples;
  const std::uint32_t worstLine = t.line[r.worstSample];
  doc.openSection(fmt::format("region-{}", number), "region");
  doc.heading(3, fmt::format("{}. Lines {}-{}{}", number, r.firstLine, r.lastLine,
                             r.atPassEnds ? " (where passes start and end)" : ""));
  doc.table({{"severity", "largest speed difference to the neighbouring pass", "largest acceleration difference",
              "largest jerk", "largest predicted deviation", "worst line", "area"},
             {fmt::format("{:.1f}", r.severity), fmt::format("{:.0f} mm/min", r.maxSpeedInconsistency),
              fmt::format("{:.0f} mm/s^2", r.maxAccelInconsistency), fmt::format("{:.0f} mm/s^3", r.maxJerk),
              t.hasFeedback() ? fmt::format("{:.2f} um", r.maxDeviation) : "no feedback", std::to_string(worstLine),
              fmt::format("{:.1f} mm^2", r.area)}});
  vis::QualityMapRequest request;
  request.quantity = Quantity::SpeedInconsistency;
  request.view = vis::ViewDirection::Top;
  request.highlightLine = worstLine;
  doc.raw("<div class=\"maps\">\n");
  doc.image(renderMapPng(run, request, gapLimit, std::make_pair(r.lower, r.upper)),
            fmt::format("Close-up of the region (x {:.1f} to {:.1f} mm, y {:.1f} to {:.1f} mm), speed difference "
                        "between neighbouring passes; line {} glows",
                        r.lower.x(), r.upper.x(), r.lower.y(), r.upper.y(), worstLine));
  doc.image(renderMapPng(run, request, gapLimit), fmt::format("Where it lies on the whole part; line {} glows", worstLine));
  doc.raw("</div>\n");
  if (lines && lines->count() > 0) excerpt(doc, *lines, r, worstLine);
  regionPlots(doc, t, r, speed, accel);
  doc.closeSection();
}

void regions(HtmlDocument& doc, const OpenedRun& run, const vis::QualityMap& surface, int count,
             const ProgressCallback& progress, nlohmann::json& out, std::size_t& found) {
  const Trajectory& t = *run.samples;
  const QualityReport report = surface.mesh ? findQualityRegions(t, *surface.mesh) : QualityReport{};
  found = report.regions.size();
  const int shown = std::min<int>(count, static_cast<int>(report.regions.size()));
  doc.heading(2, fmt::format("Worst regions ({} beyond the thresholds, {} shown)", report.regions.size(), shown));
  // The program's lines as the window's G-code pane numbers them (any line ends), not copied.
  std::optional<app_model::TextLines> lines;
  if (!run.files.program.empty()) lines.emplace(run.files.program);
  const std::vector<double> speed = sampleQuantity(Quantity::Speed, t), accel = sampleQuantity(Quantity::Acceleration, t);
  out["regions"] = nlohmann::json::array();
  if (shown == 0) doc.paragraph("No region of the surface passes the thresholds.");
  for (int k = 0; k < shown; ++k) {
    const QualityRegion& r = report.regions[static_cast<std::size_t>(k)];
    oneRegion(doc, run, surface.request.gapLimit, r, k + 1, lines, speed, accel);
    out["regions"].push_back({{"first_line", r.firstLine}, {"last_line", r.lastLine},
                              {"worst_line", t.line[r.worstSample]}, {"severity", r.severity},
                              {"at_pass_ends", r.atPassEnds},
                              {"box_mm", {{"min", {r.lower.x(), r.lower.y(), r.lower.z()}},
                                          {"max", {r.upper.x(), r.upper.y(), r.upper.z()}}}},
                              {"max_speed_inconsistency_mm_min", r.maxSpeedInconsistency},
                              {"max_accel_inconsistency_mm_s2", r.maxAccelInconsistency}, {"max_jerk_mm_s3", r.maxJerk},
                              {"max_predicted_deviation_um", r.maxDeviation}});
    if (progress) progress(double(k + 1) / shown);
  }
}

std::string percentOf(double value, double limit) {
  return limit > 0 ? fmt::format("{:.0f} %", 100 * value / limit) : "not limited";
}

void axisLimits(HtmlDocument& doc, const OpenedRun& run, nlohmann::json& out) {
  const Trajectory& t = *run.samples;
  const KinematicsSummary k =
      summarizeKinematics(t.x.data(), t.y.data(), t.z.data(), t.irregularTime ? t.time.data() : nullptr, t.size(), t.cycle);
  std::vector<std::vector<std::string>> rows = {{"axis", "largest velocity", "of the limit", "largest acceleration",
                                                 "of the limit", "largest jerk", "of the limit"}};
  out["axes"] = nlohmann::json::array();
  for (int a = 0; a < 3; ++a) {
    const AxisLimits& limit = run.machine.axes[a];
    const KinematicsMaxima& m = k.axis[a];
    rows.push_back({std::string(1, "XYZ"[a]), fmt::format("{:.0f} mm/min", mmPerSToMmPerMin(m.speed)),
                    percentOf(m.speed, limit.maxVelocity), fmt::format("{:.0f} mm/s^2", m.accel),
                    percentOf(m.accel, limit.maxAcceleration), fmt::format("{:.0f} mm/s^3", m.jerk),
                    percentOf(m.jerk, limit.maxJerk)});
    out["axes"].push_back({{"axis", std::string(1, "xyz"[a])}, {"max_velocity_mm_s", m.speed}, {"max_accel_mm_s2", m.accel},
                           {"max_jerk_mm_s3", m.jerk}, {"velocity_limit_mm_s", limit.maxVelocity},
                           {"accel_limit_mm_s2", limit.maxAcceleration}, {"jerk_limit_mm_s3", limit.maxJerk}});
  }
  doc.table(rows);
  if (!run.machineKnown) doc.paragraph("The dump names no machine: the limits are the built-in machine's.");
}

// The surface the maps and regions are drawn on; nothing (and why, in the document) for a run
// without cutting passes (a drilling cycle, a program that only computes): the summary and the
// axis limits still say something.
std::optional<vis::QualityMap> surfaceOf(const OpenedRun& run, double gapLimit, std::string& why) {
  try {
    vis::QualityMapRequest request;
    request.gapLimit = gapLimit;
    return vis::buildQualityMap(*run.samples, run.program.get(), request);
  } catch (const InputError& e) {
    why = e.diagnostic().message;
    return std::nullopt;
  }
}

}  // namespace

ProgramReport buildProgramReport(const OpenedRun& run, const ReportOptions& options, const ProgressCallback& progress) {
  if (options.regions < 0 || options.regions > kMostRegions)
    throw InputError(Diagnostic{"", 0, 0, fmt::format("regions shown must be 0 to {}", kMostRegions)});
  const std::string source = run.files.program.empty() ? run.files.dump : run.files.program;
  if (!run.samples) throw InputError(Diagnostic{source, 0, 0, "the program makes no motion: nothing to report"});
  const std::string name = std::filesystem::path(source).filename().string();
  // Progress: the maps half, the regions, then what stands beside (a run, an optimisation).
  const bool beside = options.compared || options.optimisation != ReportOptimisation::None;
  const double mapsEnd = beside ? 0.3 : 0.5, regionsEnd = beside ? 0.5 : 0.97;
  ProgramReport report;
  HtmlDocument doc("iSurface report: " + name);
  doc.heading(1, "iSurface report: " + name);
  doc.openSection("summary");
  doc.heading(2, "Summary");
  summary(doc, run, report.figures);
  doc.closeSection();

  std::string noSurface;
  const std::optional<vis::QualityMap> surface = surfaceOf(run, options.gapLimit, noSurface);
  doc.openSection("maps");
  doc.heading(2, "Quality maps");
  if (surface) report.maps = maps(doc, run, options.gapLimit, progressStage(progress, 0, mapsEnd));
  else doc.paragraph("No quality map: " + noSurface + ".");
  // Passes that are there but make no surface (one pass, passes not joined) are not measured,
  // which is not the same as measured and found fine (a gate on the figures must not pass them).
  if (!surface) report.figures["no_surface"] = noSurface;
  if (!surface && noSurface != kNoCuttingPasses) report.figures["unmeasured"] = noSurface;
  doc.closeSection();

  doc.openSection("regions");
  report.figures["regions"] = nlohmann::json::array();
  if (surface) {
    regions(doc, run, *surface, options.regions, progressStage(progress, mapsEnd, regionsEnd), report.figures,
            report.regionsFound);
  } else {
    doc.heading(2, "Worst regions");
    doc.paragraph("None: there is no surface to find them on.");
  }
  doc.closeSection();

  doc.openSection("limits");
  doc.heading(2, "How close each axis came to the machine's limits");
  axisLimits(doc, run, report.figures);
  doc.closeSection();

  if (options.compared) {
    const double end = options.optimisation != ReportOptimisation::None ? 0.7 : 1.0;
    comparisonSection(doc, run, *options.compared, options.gapLimit, progressStage(progress, regionsEnd, end), report.figures);
  }
  if (options.optimisation != ReportOptimisation::None)
    optimisationSection(doc, run, options, progressStage(progress, options.compared ? 0.7 : regionsEnd, 1.0),
                        report.figures);
  report.html = doc.finish();
  if (progress) progress(1.0);
  return report;
}

}  // namespace isurface::report
