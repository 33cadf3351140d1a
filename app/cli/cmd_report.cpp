// isurface-cli report: one self-contained HTML document about a program: its summary, its
// quality maps, the worst regions with their G-code and the speed over them, and how close each
// axis came to the machine's limits.
#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <vector>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "command.h"
#include "inputs.h"
#include "isurface/analysis/kinematics.h"
#include "isurface/app_model/text_lines.h"
#include "isurface/analysis/quality_regions.h"
#include "isurface/analysis/quantities.h"
#include "isurface/base/units.h"
#include "isurface/io/atomic_file.h"
#include "isurface/vis/line_plot.h"
#include "isurface/vis/offscreen_render.h"
#include "isurface/vis/quality_map.h"
#include "isurface/workflow/file_kinds.h"
#include "progress.h"
#include "report_html.h"
#include "trajectory_input.h"

namespace isurface::cli {
namespace {

struct ReportOptions {
  std::string program, dump, output, json, batch;
  std::vector<std::string> failOn;
  MachineOption machine;
  int regions = 5;
  bool force = false;
};

// A threshold of --fail-on: "NAME>VALUE" on a figure of the report.
struct Threshold {
  std::string name;
  double limit = 0;
};

// The figures a threshold may name, from a report's JSON (0 where it has none).
double figureOf(const nlohmann::json& report, const std::string& name) {
  double worst = 0;
  const char* key = name == "speed_inconsistency"   ? "max_speed_inconsistency_mm_min"
                    : name == "accel_inconsistency" ? "max_accel_inconsistency_mm_s2"
                    : name == "jerk"                ? "max_jerk_mm_s3"
                                                    : "max_predicted_deviation_um";
  if (name == "machining_time") return report["summary"]["machining_time_s"].get<double>();
  for (const auto& r : report["regions"]) worst = std::max(worst, r[key].get<double>());
  return worst;
}

std::vector<Threshold> parseThresholds(const std::vector<std::string>& texts) {
  static const char* const kNames[] = {"speed_inconsistency", "accel_inconsistency", "jerk", "deviation", "machining_time"};
  std::vector<Threshold> out;
  for (const std::string& text : texts) {
    const std::size_t gt = text.find('>');
    Threshold t;
    t.name = text.substr(0, gt);
    char* end = nullptr;
    if (gt != std::string::npos) t.limit = std::strtod(text.c_str() + gt + 1, &end);
    if (gt == std::string::npos || !end || *end || end == text.c_str() + gt + 1 || !std::isfinite(t.limit) ||
        std::find(std::begin(kNames), std::end(kNames), t.name) == std::end(kNames))
      throw InputError(Diagnostic{"", 0, 0, "bad --fail-on '" + text + "': expected NAME>VALUE with NAME one of "
                                            "speed_inconsistency (mm/min), accel_inconsistency (mm/s^2), jerk (mm/s^3), "
                                            "deviation (um), machining_time (s)"});
    out.push_back(t);
  }
  return out;
}

// The thresholds a report crosses, one sentence each.
std::vector<std::string> crossed(const nlohmann::json& report, const std::vector<Threshold>& thresholds) {
  std::vector<std::string> out;
  for (const Threshold& t : thresholds)
    if (const double v = figureOf(report, t.name); v > t.limit) out.push_back(fmt::format("{} {:.4g} > {:g}", t.name, v, t.limit));
  return out;
}

constexpr int kMapWidth = 720, kMapHeight = 450;
constexpr int kPlotWidth = 720, kPlotHeight = 260;
constexpr std::size_t kPlotPoints = 4000;  // a plot's samples are thinned to about this many
constexpr double kPlotSeconds = 1.5;       // s either side of a region's worst sample
constexpr std::uint32_t kExcerptContext = 12;  // G-code lines either side of a region's worst line

std::string renderMap(const OpenedRun& run, Quantity q, vis::ViewDirection view, std::optional<std::uint32_t> line) {
  vis::QualityMapRequest request;
  request.quantity = q;
  request.view = view;
  request.highlightLine = line;
  request.inch = run.program && run.program->inch;
  request.caption = std::filesystem::path(run.files.program.empty() ? run.files.dump : run.files.program).filename().string();
  vis::QualityMap map = vis::buildQualityMap(*run.samples, run.program.get(), request);
  map.style.fontSize = vis::fontSizeForHeight(kMapHeight);
  vis::QualityScene scene(map.data, map.style);
  return vis::renderSceneToPngBytes(scene, kMapWidth, kMapHeight);
}

// "m:ss.mmm (s s)", as simulate prints a machining time.
std::string duration(double seconds) { return formatDuration(seconds) + fmt::format(" ({:.3f} s)", seconds); }

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
  doc.table({{"", "this program"},
             {"Program", run.files.program.empty() ? "(none: a dump alone)" : run.files.program},
             {"Samples from", run.files.dump.empty() ? "a simulation of the program" : run.files.dump},
             {"Machine", run.machineKnown ? run.machine.name : "not named by the dump"},
             {"Machining time", duration(time)},
             {"Path length", fmt::format("{:.1f} mm", length)},
             {"Samples", fmt::format("{} at {:g} ms", t.size(), t.cycle * 1000)},
             {"Programmed feeds", highFeed > 0 ? (inch ? fmt::format("F{:g} to F{:g} in/min", lowFeed / kMmPerInch, highFeed / kMmPerInch)
                                                       : fmt::format("F{:g} to F{:g} mm/min", lowFeed, highFeed))
                                               : "none"},
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

// Speed and acceleration against time around the region's worst sample: a region may span
// many passes, and the seconds around its worst point show what the machine did there.
void regionPlots(HtmlDocument& doc, const Trajectory& t, const QualityRegion& r, const std::vector<double>& speed,
                 const std::vector<double>& accel) {
  const double centre = t.time[r.worstSample];
  std::size_t first = r.worstSample, last = r.worstSample;
  while (first > 0 && t.time[first - 1] >= centre - kPlotSeconds) --first;
  while (last + 1 < t.size() && t.time[last + 1] <= centre + kPlotSeconds) ++last;
  if (first >= last) return;
  const std::size_t stride = std::max<std::size_t>(1, (last - first) / kPlotPoints);
  const std::string around = fmt::format("around the worst point (line {}, {:.2f} s)", t.line[r.worstSample], centre);
  vis::LinePlot speedPlot{"Path speed " + around, "time (s)", "mm/min", {}, {{"speed (mm/min)", {}}}};
  vis::LinePlot accelPlot{"Tangential acceleration " + around, "time (s)", "mm/s^2", {}, {{"acceleration (mm/s^2)", {}}}};
  for (std::size_t i = first; i <= last; i += stride) {
    speedPlot.x.push_back(t.time[i]);
    accelPlot.x.push_back(t.time[i]);
    speedPlot.series[0].y.push_back(speed[i]);
    accelPlot.series[0].y.push_back(accel[i]);
  }
  doc.raw("<div class=\"maps\">\n");
  doc.image(vis::plotToPng(speedPlot, kPlotWidth, kPlotHeight), speedPlot.title);
  doc.image(vis::plotToPng(accelPlot, kPlotWidth, kPlotHeight), accelPlot.title);
  doc.raw("</div>\n");
}

void regions(HtmlDocument& doc, const OpenedRun& run, const QualityReport& report, int count, ProgressLine& progress,
             nlohmann::json& out) {
  const Trajectory& t = *run.samples;
  // The program's lines as the window's G-code pane numbers them (any line ends), not copied.
  std::optional<app_model::TextLines> lines;
  if (!run.files.program.empty()) lines.emplace(run.files.program);
  const std::vector<double> speed = sampleQuantity(Quantity::Speed, t), accel = sampleQuantity(Quantity::Acceleration, t);
  out["regions"] = nlohmann::json::array();
  const int shown = std::min<int>(count, static_cast<int>(report.regions.size()));
  if (shown == 0) doc.paragraph("No region of the surface passes the thresholds.");
  for (int k = 0; k < shown; ++k) {
    const QualityRegion& r = report.regions[static_cast<std::size_t>(k)];
    const std::uint32_t worstLine = t.line[r.worstSample];
    doc.openSection(fmt::format("region-{}", k + 1), "region");
    doc.heading(3, fmt::format("{}. Lines {}-{}{}", k + 1, r.firstLine, r.lastLine, r.atPassEnds ? " (where passes start and end)" : ""));
    doc.table({{"severity", "largest speed difference to the neighbouring pass", "largest acceleration difference", "largest jerk",
                "largest predicted deviation", "worst line", "area"},
               {fmt::format("{:.1f}", r.severity), fmt::format("{:.0f} mm/min", r.maxSpeedInconsistency),
                fmt::format("{:.0f} mm/s^2", r.maxAccelInconsistency), fmt::format("{:.0f} mm/s^3", r.maxJerk),
                t.hasFeedback() ? fmt::format("{:.2f} um", r.maxDeviation) : "no feedback", std::to_string(worstLine),
                fmt::format("{:.1f} mm^2", r.area)}});
    doc.image(renderMap(run, Quantity::SpeedInconsistency, vis::ViewDirection::Top, worstLine),
              fmt::format("Top view, speed difference between neighbouring passes; line {} glows", worstLine));
    if (lines && lines->count() > 0) {
      std::vector<std::pair<std::uint32_t, std::string>> excerpt;
      const std::uint32_t from = std::max(r.firstLine, worstLine > kExcerptContext ? worstLine - kExcerptContext : 1u);
      const std::uint32_t to = std::min<std::uint32_t>({r.lastLine, worstLine + kExcerptContext, static_cast<std::uint32_t>(lines->count())});
      for (std::uint32_t n = from; n <= to; ++n) excerpt.emplace_back(n, std::string(lines->line(n)));
      doc.paragraph(fmt::format("G-code around the worst line (lines {}-{} of the region's {}-{}):", from, to, r.firstLine, r.lastLine));
      doc.code(excerpt, worstLine);
    }
    regionPlots(doc, t, r, speed, accel);
    doc.closeSection();
    out["regions"].push_back({{"first_line", r.firstLine}, {"last_line", r.lastLine}, {"worst_line", worstLine},
                              {"severity", r.severity}, {"at_pass_ends", r.atPassEnds},
                              {"max_speed_inconsistency_mm_min", r.maxSpeedInconsistency},
                              {"max_accel_inconsistency_mm_s2", r.maxAccelInconsistency}, {"max_jerk_mm_s3", r.maxJerk},
                              {"max_predicted_deviation_um", r.maxDeviation}});
    progress.update(0.6 + 0.35 * double(k + 1) / shown);
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

// Writes one program's report to `html` (and `json`); returns its figures.
nlohmann::json reportOne(const ReportOptions& o, const std::string& program, const std::string& dump,
                         const std::string& html, const std::string& json) {
  TrajectoryChannels channels;
  channels.feedback = true;
  const bool dumpOnly = dump.empty() && isBiipFile(program);
  const OpenedRun run = openRunOnTerminal({dumpOnly ? "" : program, dumpOnly ? program : dump}, o.machine, o.force, channels);
  if (!run.samples) throw InputError(Diagnostic{program, 0, 0, "the program makes no motion: nothing to report"});
  const std::string name = std::filesystem::path(program).filename().string();
  HtmlDocument doc("iSurface report: " + name);
  nlohmann::json out;
  ProgressLine progress("reporting on " + name);
  doc.heading(1, "iSurface report: " + name);
  doc.openSection("summary");
  doc.heading(2, "Summary");
  summary(doc, run, out);
  doc.closeSection();

  doc.openSection("maps");
  doc.heading(2, "Quality maps");
  doc.raw("<div class=\"maps\">\n");
  const std::vector<Quantity> quantities = mapQuantities(*run.samples);
  for (std::size_t k = 0; k < quantities.size(); ++k) {
    for (const auto view : {vis::ViewDirection::Iso, vis::ViewDirection::Top}) {
      const QuantityInfo& info = quantityInfo(quantities[k]);
      doc.image(renderMap(run, quantities[k], view, std::nullopt),
                fmt::format("{} ({}), {} view", info.label, info.unit, view == vis::ViewDirection::Iso ? "iso" : "top"));
    }
    progress.update(0.5 * double(k + 1) / double(quantities.size()));
  }
  doc.raw("</div>\n");
  doc.closeSection();

  vis::QualityMapRequest surfaceOnly;
  const vis::QualityMap surface = vis::buildQualityMap(*run.samples, run.program.get(), surfaceOnly);
  const QualityReport report = findQualityRegions(*run.samples, *surface.mesh);
  doc.openSection("regions");
  doc.heading(2, fmt::format("Worst regions ({} beyond the thresholds, {} shown)", report.regions.size(),
                             std::min<std::size_t>(report.regions.size(), std::size_t(o.regions))));
  regions(doc, run, report, o.regions, progress, out);
  doc.closeSection();

  doc.openSection("limits");
  doc.heading(2, "How close each axis came to the machine's limits");
  axisLimits(doc, run, out);
  doc.closeSection();
  progress.finish();

  writeFileAtomically(html, doc.finish());
  if (!json.empty()) writeFileAtomically(json, out.dump(2) + "\n");
  std::printf("%s: %zu maps, %zu regions (%zu beyond the thresholds)\n", html.c_str(), quantities.size() * 2,
              out["regions"].size(), report.regions.size());
  return out;
}

// Every G-code program in a folder: a report each and an index ranking them by their worst
// region. A program that cannot be read is listed with its error; the others go on.
int runBatch(const ReportOptions& o, const std::vector<Threshold>& thresholds) {
  std::vector<std::string> programs;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(o.batch, error))
    if (entry.is_regular_file()) programs.push_back(entry.path().string());
  if (error) throw InputError(Diagnostic{o.batch, 0, 0, "cannot list the folder: " + error.message()});
  std::sort(programs.begin(), programs.end());
  std::filesystem::create_directories(o.output, error);
  if (error) throw InputError(Diagnostic{o.output, 0, 0, "cannot make the folder: " + error.message()});
  struct Row {
    std::string name, page, problem;
    double severity = -1;
    nlohmann::json figures;
  };
  std::vector<Row> rows;
  for (const std::string& path : programs) {
    try {
      if (fileKind(path, 4096) != FileKind::Program) continue;
    } catch (const InputError&) {
      continue;  // not a program (binary, unreadable): not part of the batch
    }
    Row row;
    row.name = std::filesystem::path(path).filename().string();
    row.page = row.name + ".html";
    try {
      row.figures = reportOne(o, path, "", (std::filesystem::path(o.output) / row.page).string(),
                              (std::filesystem::path(o.output) / (row.name + ".json")).string());
      row.severity = row.figures["regions"].empty() ? 0 : row.figures["regions"][0]["severity"].get<double>();
      const std::vector<std::string> over = crossed(row.figures, thresholds);
      for (const std::string& c : over) row.problem += (row.problem.empty() ? "" : "; ") + c;
    } catch (const InputError& e) {
      row.problem = std::string("not reported: ") + e.what();
      std::fprintf(stderr, "error: %s\n", e.what());
    }
    rows.push_back(std::move(row));
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.severity > b.severity; });
  HtmlDocument index("iSurface reports: " + o.batch);
  index.heading(1, "iSurface reports: " + o.batch);
  index.paragraph(fmt::format("{} programs, ranked by the severity of their worst region.", rows.size()));
  std::string table = "<table>\n<tr><th>program</th><th>worst region</th><th>severity</th><th>machining time</th>"
                      "<th>thresholds crossed</th></tr>\n";
  bool failed = false;
  for (const Row& r : rows) {
    failed = failed || !r.problem.empty();
    const bool reported = r.severity >= 0;
    const std::string worst = reported && !r.figures["regions"].empty()
                                  ? fmt::format("lines {}-{}", r.figures["regions"][0]["first_line"].get<int>(),
                                                r.figures["regions"][0]["last_line"].get<int>())
                                  : "-";
    table += std::string("<tr") + (r.problem.empty() ? "" : " class=\"near\"") + "><td>" +
             (reported ? "<a href=\"" + escapeHtml(r.page) + "\">" + escapeHtml(r.name) + "</a>" : escapeHtml(r.name)) +
             "</td><td>" + escapeHtml(worst) + "</td><td>" + (reported ? fmt::format("{:.1f}", r.severity) : "-") +
             "</td><td>" + (reported ? duration(r.figures["summary"]["machining_time_s"].get<double>()) : "-") + "</td><td>" +
             escapeHtml(r.problem.empty() ? "none" : r.problem) + "</td></tr>\n";
  }
  index.raw(table + "</table>\n");
  writeFileAtomically((std::filesystem::path(o.output) / "index.html").string(), index.finish());
  std::printf("%s: %zu programs reported\n", (std::filesystem::path(o.output) / "index.html").string().c_str(), rows.size());
  return failed ? kExitFailure : kExitOk;
}

int runReport(const ReportOptions& o) {
  if (o.regions < 0 || o.regions > 50) throw InputError(Diagnostic{"", 0, 0, "--regions must be 0 to 50"});
  const std::vector<Threshold> thresholds = parseThresholds(o.failOn);
  if (!o.batch.empty()) {
    if (!o.program.empty() || !o.dump.empty() || !o.json.empty())
      throw InputError(Diagnostic{"", 0, 0, "--batch takes a folder: give no program, dump or --json with it"});
    return runBatch(o, thresholds);
  }
  if (o.program.empty()) throw InputError(Diagnostic{"", 0, 0, "give a program (or a dump), or --batch FOLDER"});
  const nlohmann::json figures = reportOne(o, o.program, o.dump, o.output, o.json);
  const std::vector<std::string> over = crossed(figures, thresholds);
  for (const std::string& c : over) std::fprintf(stderr, "%s: threshold crossed: %s\n", o.program.c_str(), c.c_str());
  // The report stays: it says why the job fails.
  return over.empty() ? kExitOk : kExitFailure;
}

}  // namespace

Command reportCommand() {
  return Command{"report", "Write one self-contained HTML report of a program: summary, quality maps, worst regions with their G-code and speed, axis limits",
    [](CLI::App& sub) {
      auto o = std::make_shared<ReportOptions>();
      sub.add_option("program", o->program, "G-code program (or a Biip dump alone)");
      sub.add_option("dump", o->dump, "Biip dump or trace of the program (default: simulate it)");
      sub.add_option("-o,--output", o->output, "HTML file to write (with --batch: the folder of the reports)")->required();
      sub.add_option("--batch", o->batch, "report on every G-code program in this folder, with an index.html ranking them");
      sub.add_option("--fail-on", o->failOn,
                     "exit 1 when a figure crosses NAME>VALUE: speed_inconsistency (mm/min), accel_inconsistency "
                     "(mm/s^2), jerk (mm/s^3), deviation (um) of the worst region shown, or machining_time (s); repeatable");
      sub.add_option("--json", o->json, "also write the report's figures as JSON");
      sub.add_option("--regions", o->regions, "worst regions shown, 0 to 50")->capture_default_str();
      sub.add_flag("--force", o->force, "use the dump even if it does not look like the program's own");
      o->machine.addTo(sub, "machine description for the simulation (JSON)");
      return [o] { return runReport(*o); };
    }};
}

}  // namespace isurface::cli
