// isurface-cli report: one self-contained HTML document about a program: its summary, its
// quality maps, the worst regions with their G-code and the speed over them, and how close each
// axis came to the machine's limits.
#include <unistd.h>

#include <algorithm>
#include <limits>
#include <cstdlib>
#include <iterator>
#include <vector>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "command.h"
#include "output_options.h"
#include "inputs.h"
#include "isurface/io/atomic_file.h"
#include "isurface/report/html_document.h"
#include "isurface/report/program_report.h"
#include "isurface/workflow/file_kinds.h"
#include "progress.h"
#include "trajectory_input.h"
#include "isurface/base/json_text.h"

namespace isurface::cli {
namespace {

struct ReportCliOptions {
  std::string program, dump, output, json, batch, compare, optimise;
  double chordTolerance = kDefaultChordTolerance;
  std::vector<std::string> failOn;
  MachineOption machine;
  GapLimitOption gapLimit;
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

// Why a report fails its gates, one sentence each: a threshold crossed ("threshold crossed: jerk
// 5.2e+04 > 3e+04"), or, once, the surface's figures that could not be measured at all (its
// passes were not joined: a gate must not pass a program it could not measure).
std::vector<std::string> crossed(const nlohmann::json& report, const std::vector<Threshold>& thresholds) {
  std::vector<std::string> out;
  std::string unmeasured;
  for (const Threshold& t : thresholds)
    if (t.name != "machining_time" && report.contains("unmeasured")) {
      if (unmeasured.find(t.name) == std::string::npos) unmeasured += (unmeasured.empty() ? "" : ", ") + t.name;
    }
    else if (const double v = figureOf(report, t.name); v > t.limit)
      out.push_back(fmt::format("threshold crossed: {} {:.4g} > {:g}", t.name, v, t.limit));
  if (!unmeasured.empty())
    out.push_back(fmt::format("not measured ({}): {}", unmeasured, report["unmeasured"].get<std::string>()));
  return out;
}

// Writes one program's report to `html` (and `json`); returns its figures.
nlohmann::json reportOne(const ReportCliOptions& o, const std::string& program, const std::string& dump,
                         const std::string& html, const std::string& json) {
  TrajectoryChannels channels;
  channels.feedback = true;
  const bool dumpOnly = dump.empty() && isBiipFile(program);
  const OpenedRun run = openRunOnTerminal({dumpOnly ? "" : program, dumpOnly ? program : dump}, o.machine, o.force, channels);
  report::ReportOptions options;
  options.regions = o.regions;
  options.optimisation = o.optimise == "auto" ? report::ReportOptimisation::WorstRegion
                         : o.optimise == "all" ? report::ReportOptimisation::AllPasses
                                               : report::ReportOptimisation::None;
  options.chordTolerance = o.chordTolerance;
  options.gapLimit = o.gapLimit.checked();
  if (!o.compare.empty())
    options.compared = openRunOnTerminal({dumpOnly ? "" : program, o.compare}, o.machine, o.force, channels);
  ProgressLine progress("reporting on " + std::filesystem::path(program).filename().string());
  const report::ProgramReport r = report::buildProgramReport(run, options, [&](double f) { progress.update(f); });
  progress.finish();
  writeFileAtomically(html, r.html);
  if (!json.empty()) writeFileAtomically(json, jsonText(r.figures, 2) + "\n");
  std::printf("%s: %zu maps, %zu regions (%zu beyond the thresholds)\n", html.c_str(), r.maps,
              r.figures["regions"].size(), r.regionsFound);
  return r.figures;
}

// The name (without .html or .json) of the report on the program `name` in a batch: the
// program's name, or with " (2)", " (3)" ... when that is taken (a program called `index` is not
// to be replaced by the index). `taken` holds the pages named so far, in lower case.
// A name longer than the folder's file system holds is cut (at a character's start) and marked
// with "~", so that its report is written too.
std::string reportName(const std::string& name, std::set<std::string>& taken, std::size_t longestName) {
  const auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  // Room for " (999).html" after the name.
  const std::size_t room = longestName > 16 ? longestName - 11 : 5;
  std::string stem = name;
  if (stem.size() > room) {
    std::size_t cut = room - 1;
    while (cut > 0 && (static_cast<unsigned char>(stem[cut]) & 0xC0) == 0x80) --cut;
    stem = stem.substr(0, cut) + "~";
  }
  std::string base = stem;
  for (int n = 2; taken.count(lower(base + ".html")) > 0 || taken.count(lower(base + ".json")) > 0; ++n)
    base = stem + " (" + std::to_string(n) + ")";
  taken.insert(lower(base + ".html"));
  taken.insert(lower(base + ".json"));
  return base;
}

// Every G-code program in a folder: a report each and an index ranking them by their worst
// region. A program that cannot be read is listed with its error; the others go on.
int runBatch(const ReportCliOptions& o, const std::vector<Threshold>& thresholds) {
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
  std::set<std::string> pages = {"index.html"};  // lower case: a folder may not tell case apart
  const long nameMax = ::pathconf(o.output.c_str(), _PC_NAME_MAX);
  const std::size_t longestName = nameMax > 0 ? static_cast<std::size_t>(nameMax) : 255;
  for (const std::string& path : programs) {
    try {
      if (fileKind(path, 4096) != FileKind::Program) continue;
    } catch (const InputError&) {
      continue;  // not a program (binary, unreadable): not part of the batch
    }
    Row row;
    row.name = std::filesystem::path(path).filename().string();
    const std::string base = reportName(row.name, pages, longestName);
    row.page = base + ".html";
    try {
      row.figures = reportOne(o, path, "", (std::filesystem::path(o.output) / row.page).string(),
                              (std::filesystem::path(o.output) / (base + ".json")).string());
      // A program that could not be measured ranks first: it fails every gate on the surface.
      row.severity = row.figures.contains("unmeasured")   ? std::numeric_limits<double>::infinity()
                     : row.figures["regions"].empty() ? 0
                                                      : row.figures["regions"][0]["severity"].get<double>();
      const std::vector<std::string> over = crossed(row.figures, thresholds);
      for (const std::string& c : over) row.problem += (row.problem.empty() ? "" : "; ") + c;
    } catch (const InputError& e) {
      row.problem = std::string("not reported: ") + e.what();
      std::fprintf(stderr, "error: %s\n", e.what());
    }
    rows.push_back(std::move(row));
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.severity > b.severity; });
  report::HtmlDocument index("iSurface reports: " + o.batch);
  index.heading(1, "iSurface reports: " + o.batch);
  index.paragraph(fmt::format("{} programs, ranked by the severity of their worst region.", rows.size()));
  std::string table = "<table>\n<tr><th>program</th><th>worst region</th><th>severity</th><th>machining time</th>"
                      "<th>gates failed</th></tr>\n";
  bool failed = false;
  for (const Row& r : rows) {
    failed = failed || !r.problem.empty();
    const bool reported = r.severity >= 0;
    const std::string worst = reported && !r.figures["regions"].empty()
                                  ? fmt::format("lines {}-{}", r.figures["regions"][0]["first_line"].get<int>(),
                                                r.figures["regions"][0]["last_line"].get<int>())
                                  : r.figures.contains("no_surface") ? "no surface: " + r.figures["no_surface"].get<std::string>()
                                                                     : "-";
    table += std::string("<tr") + (r.problem.empty() ? "" : " class=\"near\"") + "><td>" +
             (reported ? "<a href=\"" + report::escapeHtml(report::relativeLink(r.page)) + "\">" + report::escapeHtml(r.name) + "</a>" : report::escapeHtml(r.name)) +
             "</td><td>" + report::escapeHtml(worst) + "</td><td>" +
             (reported && !r.figures.contains("no_surface") ? fmt::format("{:.1f}", r.severity) : "-") +
             "</td><td>" + (reported ? formatDuration(r.figures["summary"]["machining_time_s"].get<double>()) : "-") + "</td><td>" +
             report::escapeHtml(r.problem.empty() ? "none" : r.problem) + "</td></tr>\n";
  }
  index.raw(table + "</table>\n");
  writeFileAtomically((std::filesystem::path(o.output) / "index.html").string(), index.finish());
  std::printf("%s: %zu programs reported\n", (std::filesystem::path(o.output) / "index.html").string().c_str(), rows.size());
  return failed ? kExitFailure : kExitOk;
}

int runReport(const ReportCliOptions& o) {
  if (o.regions < 0 || o.regions > report::kMostRegions)
    throw InputError(Diagnostic{"", 0, 0, fmt::format("--regions must be 0 to {}", report::kMostRegions)});
  if (!(o.chordTolerance >= 1e-6 && o.chordTolerance <= 10))
    throw InputError(Diagnostic{"", 0, 0, "--tolerance must be from 1e-06 to 10 mm"});
  o.gapLimit.checked();
  const std::vector<Threshold> thresholds = parseThresholds(o.failOn);
  if (!o.batch.empty()) {
    if (!o.program.empty() || !o.dump.empty() || !o.json.empty() || !o.compare.empty())
      throw InputError(Diagnostic{"", 0, 0, "--batch takes a folder: give no program, dump, --compare or --json with it"});
    return runBatch(o, thresholds);
  }
  if (o.program.empty()) throw InputError(Diagnostic{"", 0, 0, "give a program (or a dump), or --batch FOLDER"});
  const nlohmann::json figures = reportOne(o, o.program, o.dump, o.output, o.json);
  const std::vector<std::string> over = crossed(figures, thresholds);
  for (const std::string& c : over) std::fprintf(stderr, "%s: %s\n", o.program.c_str(), c.c_str());
  // The report stays: it says why the job fails.
  return over.empty() ? kExitOk : kExitFailure;
}

}  // namespace

Command reportCommand() {
  return Command{"report", "Write one self-contained HTML report of a program: summary, quality maps, worst regions with their G-code and speed, axis limits",
    [](CLI::App& sub) {
      auto o = std::make_shared<ReportCliOptions>();
      sub.add_option("program", o->program, "G-code program (or a Biip dump alone)");
      sub.add_option("dump", o->dump, "Biip dump or trace of the program (default: simulate it)");
      outputOption(sub.add_option("-o,--output", o->output, "HTML file to write (with --batch: the folder of the reports)"))->required();
      sub.add_option("--batch", o->batch, "report on every G-code program in this folder, with an index.html ranking them");
      sub.add_option("--fail-on", o->failOn,
                     "exit 1 when a figure crosses NAME>VALUE: speed_inconsistency (mm/min), accel_inconsistency "
                     "(mm/s^2), jerk (mm/s^3), deviation (um) of the worst region shown, or machining_time (s); repeatable");
      outputOption(sub.add_option("--json", o->json, "also write the report's figures as JSON"));
      sub.add_option("--regions", o->regions, "worst regions shown, 0 to 50")->capture_default_str();
      sub.add_option("--compare", o->compare,
                     "another run of the program (a Biip dump or trace): its speed map beside this one's, the "
                     "difference and the figures of both");
      sub.add_option("--optimize", o->optimise,
                     "re-optimise the worst region (auto) or every pass (all) and show the program before and after")
          ->check(CLI::IsMember({"auto", "all"}));
      sub.add_option("--tolerance", o->chordTolerance, "chord tolerance of the re-fitted moves with --optimize, mm")
          ->capture_default_str();
      sub.add_flag("--force", o->force, "use the dump even if it does not look like the program's own");
      o->machine.addTo(sub, "machine description for the simulation (JSON)");
      o->gapLimit.addTo(sub);
      return [o] { return runReport(*o); };
    }};
}

}  // namespace isurface::cli
