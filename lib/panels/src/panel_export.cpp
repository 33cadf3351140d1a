// Export from the window: the 3D view as a PNG at a chosen size, the current map's figures as
// JSON, the samples of a range of G-code lines as CSV, and the report (panel_report.cpp). Each
// goes through the window's save (a file that exists is replaced only when the user says so).
#include <imgui.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "inspector_state.h"
#include "text_input.h"
#include "isurface/analysis/quality_figures.h"
#include "isurface/io/trajectory_writing.h"
#include "isurface/vis/offscreen_render.h"
#include "isurface/base/json_text.h"
#include "isurface/base/value_range.h"

namespace isurface::panels {

namespace {

// The map's colour values: what its range was taken from.
nlohmann::json valueFigures(const std::vector<float>& values) {
  std::vector<double> finite;
  finite.reserve(values.size());
  for (float v : values)
    if (std::isfinite(v)) finite.push_back(v);
  if (finite.empty()) return nlohmann::json::object();
  double sum = 0;
  for (double v : finite) sum += v;
  const double mean = sum / static_cast<double>(finite.size());
  const auto [low, high] = std::minmax_element(finite.begin(), finite.end());
  const double min = *low, max = *high;
  // The percentiles as the map's 1-99 % colour range takes them, so that the two agree.
  const ValueRange outer = percentileRange(values, 1, 99), middle = percentileRange(values, 50, 50);
  return {{"min", min}, {"p1", outer.lo}, {"median", middle.lo}, {"p99", outer.hi}, {"max", max}, {"mean", mean}};
}

std::string figuresJson(const Document& doc) {
  nlohmann::json out = {{"program", doc.programPath},
                        {"dump", doc.dumpPath},
                        {"machine", doc.machineKnown ? doc.machine.name : ""},
                        {"samples", doc.samples->size()},
                        {"machining_time_s", machiningTime(*doc.samples)},
                        {"quantity", doc.map.style.quantityLabel},
                        {"unit", doc.map.style.unit},
                        {"colour_range", {doc.map.style.range.lo, doc.map.style.range.hi}},
                        {"passes", doc.map.passes.passes.size()},
                        {"values", valueFigures(doc.map.data.scalars)}};
  if (doc.map.mesh) {
    // The values at the figures' resolution, where the map's range is taken too, whatever the
    // window's size thinned the map to.
    const std::shared_ptr<const SurfaceMesh> mesh = vis::figuresMesh(*doc.samples, doc.map);
    out["values"] = valueFigures(vis::vertexValuesShown(doc.map.request, *doc.samples, *mesh));
    const QualityFigures f = measureQualityFigures(*doc.samples, *mesh);
    out["figures"] = {{"surface_samples", f.samples},
                      {"speed_fluctuation_mm_min", f.speedFluctuation},
                      {"inconsistency_p99_mm_min", f.inconsistencyP99},
                      {"inconsistency_mean_mm_min", f.inconsistencyMean},
                      {"jerk_p99_mm_s3", f.jerkP99}};
    if (f.hasDeviation) out["figures"]["deviation_p99_um"] = f.deviationP99;
  }
  return jsonText(out, 2) + "\n";
}

constexpr std::size_t kCsvRun = 65536;

// Every sample of the lines first..last: time, line, commanded (and feedback) position, and the
// curves (speed, acceleration, jerk, extra channels).
std::string samplesCsv(const Document& doc, std::uint32_t first, std::uint32_t last, std::size_t& rows) {
  const Trajectory& t = *doc.samples;
  const bool feedback = t.hasFeedback();
  std::string out = "sample,t_s,line,x_mm,y_mm,z_mm";
  if (feedback) out += ",fb_x_mm,fb_y_mm,fb_z_mm";
  for (const Curve& c : doc.curves) out += "," + c.label + (c.unit.empty() ? "" : " [" + c.unit + "]");
  out += "\n";
  rows = 0;
  // The curves' values are read a run of consecutive samples at a time.
  std::vector<std::vector<float>> curveValues(doc.curves.size());
  std::size_t runFirst = 0, runLast = 0;
  RunChannel<std::uint32_t>::Cursor lineAt = t.line.cursor(), lineAhead = t.line.cursor();
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (lineAt[k] < first || lineAt[k] > last) continue;
    if (k >= runLast) {
      runFirst = k;
      runLast = k;
      while (runLast < t.size() && runLast - runFirst < kCsvRun && lineAhead[runLast] >= first && lineAhead[runLast] <= last) ++runLast;
      for (std::size_t c = 0; c < doc.curves.size(); ++c) curveValues[c] = doc.curves[c].values.values(runFirst, runLast);
    }
    out += fmt::format("{},{:.6f},{},{:.6f},{:.6f},{:.6f}", k, t.timeAt(k), lineAt[k], t.x[k], t.y[k], t.z[k]);
    if (feedback) {
      const Vec3 f = t.feedback(k);
      out += fmt::format(",{:.6f},{:.6f},{:.6f}", f.x(), f.y(), f.z());
    }
    for (const std::vector<float>& values : curveValues) out += fmt::format(",{:.6g}", values[k - runFirst]);
    out += "\n";
    ++rows;
  }
  return out;
}

}  // namespace

// A file kept rather than replaced: the Export dialog opens again, its path to be changed.
std::function<void()> backToTheDialog(Inspector::State& s) {
  return [&s] { s.dialogs.exportTo.opening = true; };
}

namespace {

// The map's figures or the samples of lines first..last, written to `path`.
void exportNumbers(Inspector::State& s, app_model::ExportKind kind, const std::string& path, int first, int last) {
  const Document* doc = s.activeDocument();
  if (!doc || !doc->samples) return;
  if (kind == app_model::ExportKind::MapFigures) {
    if (doc->scene) s.save(path, figuresJson(*doc), "map figures", backToTheDialog(s));
    return;
  }
  std::size_t rows = 0;
  std::string csv = samplesCsv(*doc, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last), rows);
  if (rows == 0) s.status = fmt::format("lines {}-{} produced no samples: nothing exported", first, last);
  else s.save(path, std::move(csv), fmt::format("{} samples", rows), backToTheDialog(s));
}

// The active document's samples as a Biip dump, with its machine when it is known.
void exportRunDump(Inspector::State& s, const std::string& path) {
  const Document* doc = s.activeDocument();
  if (!doc || !doc->samples) return;
  const std::shared_ptr<const Trajectory> samples = doc->samples;
  const std::string machine = doc->machineKnown ? machineDescriptionJson(doc->machine) : std::string();
  s.saveWith(path, [samples, machine](const std::string& to) { writeTrajectoryBiip(*samples, to, machine); },
             fmt::format("run ({} samples)", samples->size()), backToTheDialog(s));
}

// A radio button for one kind of export.
void kindButton(app_model::ExportDialog& dialog, const char* label, app_model::ExportKind kind) {
  if (ImGui::RadioButton(label, dialog.kind == kind)) dialog.choose(kind);
}

}  // namespace

void drawExportDialog(Inspector::State& s) {
  app_model::ExportDialog& d = s.dialogs.exportTo;
  if (d.opening) ImGui::OpenPopup("Export");
  d.opening = false;
  d.open = beginDialog("Export");
  if (!d.open) return;
  using app_model::ExportKind;
  Document* doc = s.activeDocument();
  kindButton(d, "the view as PNG", ExportKind::ViewPng);
  noteControl(s, "export.png");
  ImGui::SameLine();
  kindButton(d, "the map's figures as JSON", ExportKind::MapFigures);
  noteControl(s, "export.json");
  ImGui::SameLine();
  kindButton(d, "the samples of lines as CSV", ExportKind::LineSamples);
  noteControl(s, "export.csv");
  ImGui::SameLine();
  kindButton(d, "a report (HTML)", ExportKind::Report);
  noteControl(s, "export.report");
  ImGui::SameLine();
  kindButton(d, "the run as a Biip dump", ExportKind::RunDump);
  noteControl(s, "export.dump");
  // Each kind's own settings in a block of one height, so that the path and the Export button
  // below stay where they are when the kind changes.
  ImGui::BeginChild("##kind", ImVec2(ImGui::GetFontSize() * 40, 2 * ImGui::GetFrameHeightWithSpacing()), false,
                    ImGuiWindowFlags_NoScrollbar);
  if (d.kind == ExportKind::ViewPng) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    ImGui::InputInt("width [px]", &d.width, 0);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    ImGui::InputInt("height [px]", &d.height, 0);
  } else if (d.kind == ExportKind::LineSamples) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    ImGui::InputInt("first line", &d.first, 0);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    ImGui::InputInt("last line", &d.last, 0);
  } else if (d.kind == ExportKind::Report) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    ImGui::InputInt("worst regions shown", &d.regions, 0);
    ImGui::TextDisabled("maps, worst regions with their G-code and speed, axis limits: one file to open in a browser");
  } else if (d.kind == ExportKind::RunDump) {
    ImGui::TextDisabled("every sample (lines, positions, feedback, feed) and the machine that made them, to open "
                        "again or give to isurface-cli");
  }
  ImGui::EndChild();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 30);
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();  // typing goes to the path at once
  inputTextWithHint("##path", "file to write", d.path);
  noteControl(s, "export.path");
  app_model::ExportSubject subject;
  if (doc) {
    subject.name = doc->name;
    subject.hasSamples = doc->samples != nullptr;
    subject.hasMap = doc->scene != nullptr;
    subject.thinning = doc->samples ? doc->samples->thinning : 1;
  }
  subject.jobRunning = s.job.running();
  const std::string problem = d.problem(subject);
  // The line is there when empty too: the button below does not move when a problem appears.
  ImGui::TextDisabled("%s", problem.empty() ? " " : problem.c_str());
  const bool write = ImGui::Button("Export");
  noteControl(s, "export.write");
  if (write && problem.empty()) {
    if (d.kind == ExportKind::ViewPng) {
      const std::vector<unsigned char> rgb = s.view.snapshot(d.width, d.height);
      if (rgb.empty()) s.status = "error: the view could not be drawn at that size";
      else s.save(d.path, vis::pngOfRgb(rgb.data(), d.width, d.height), "view image", backToTheDialog(s));
    } else if (d.kind == ExportKind::Report) {
      s.startReport(d.path, d.regions);
    } else if (d.kind == ExportKind::RunDump) {
      auto dump = [&s, path = d.path] { exportRunDump(s, path); };
      if (!s.loadFeedbackFirst(dump)) dump();
    } else {
      // The figures' predicted deviation and the samples' feedback columns need the feedback.
      auto numbers = [&s, kind = d.kind, path = d.path, first = d.first, last = d.last] {
        exportNumbers(s, kind, path, first, last);
      };
      if (!s.loadFeedbackFirst(numbers)) numbers();
    }
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Close") || escapeCloses(s)) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace isurface::panels
