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
#include "isurface/analysis/quality_figures.h"
#include "isurface/vis/offscreen_render.h"
#include "isurface/base/json_text.h"

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
  return {{"min", min},
          {"p1", percentileOf(finite, 1)},
          {"median", percentileOf(finite, 50)},
          {"p99", percentileOf(finite, 99)},
          {"max", max},
          {"mean", mean}};
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

// `path` (a buffer of `size` bytes) with the extension of export kind `kind` in place of a known
// export's extension; a path with another extension, or none, is left to the user.
void withExtensionOf(char* path, std::size_t size, int kind) {
  static const char* const kExtensions[] = {".png", ".json", ".csv", ".html"};
  std::string text(path);
  for (const char* known : kExtensions) {
    const std::size_t length = std::strlen(known);
    if (text.size() <= length || text.compare(text.size() - length, length, known) != 0) continue;
    text = text.substr(0, text.size() - length) + kExtensions[std::clamp(kind, 0, 3)];
    if (text.size() < size) std::snprintf(path, size, "%s", text.c_str());
    return;
  }
}

// The map's figures (kind 1) or the samples of lines first..last (kind 2), written to `path`.
void exportNumbers(Inspector::State& s, int kind, const std::string& path, int first, int last) {
  const Document* doc = s.activeDocument();
  if (!doc || !doc->samples) return;
  if (kind == 1) {
    if (doc->scene) s.save(path, figuresJson(*doc), "map figures");
    return;
  }
  std::size_t rows = 0;
  std::string csv = samplesCsv(*doc, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last), rows);
  if (rows == 0) s.status = fmt::format("lines {}-{} produced no samples: nothing exported", first, last);
  else s.save(path, std::move(csv), fmt::format("{} samples", rows));
}

}  // namespace

void drawExportDialog(Inspector::State& s) {
  if (s.exportDialog) {
    ImGui::OpenPopup("Export");
    if (const auto line = s.selection.current().line) s.exportFirst = s.exportLast = static_cast<int>(*line);
  }
  s.exportDialog = false;
  if (!ImGui::BeginPopupModal("Export", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  Document* doc = s.activeDocument();
  const int kindBefore = s.exportKind;
  ImGui::RadioButton("the view as PNG", &s.exportKind, 0);
  noteControl(s, "export.png");
  ImGui::SameLine();
  ImGui::RadioButton("the map's figures as JSON", &s.exportKind, 1);
  noteControl(s, "export.json");
  ImGui::SameLine();
  ImGui::RadioButton("the samples of lines as CSV", &s.exportKind, 2);
  noteControl(s, "export.csv");
  ImGui::SameLine();
  ImGui::RadioButton("a report (HTML)", &s.exportKind, 3);
  noteControl(s, "export.report");
  // Another kind of export gets its own file name's extension: a JSON is not offered "view.png".
  if (s.exportKind != kindBefore) withExtensionOf(s.exportPath, sizeof s.exportPath, s.exportKind);
  if (s.exportKind == 0) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    ImGui::InputInt("width [px]", &s.exportWidth, 0);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    ImGui::InputInt("height [px]", &s.exportHeight, 0);
  } else if (s.exportKind == 2) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    ImGui::InputInt("first line", &s.exportFirst, 0);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    ImGui::InputInt("last line", &s.exportLast, 0);
  } else if (s.exportKind == 3) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    ImGui::InputInt("worst regions shown", &s.exportRegions, 0);
    ImGui::TextDisabled("maps, worst regions with their G-code and speed, axis limits: one file to open in a browser");
  }
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 30);
  ImGui::InputTextWithHint("##path", "file to write", s.exportPath, sizeof s.exportPath);
  noteControl(s, "export.path");
  std::string problem;
  if (!doc || !doc->samples) problem = "nothing to export: open a program or a dump first";
  else if (s.exportKind != 2 && !doc->scene) problem = "no map to export: " + doc->name + " has no surface";
  else if ((s.exportKind == 1 || s.exportKind == 2) && doc->samples->thinning > 1)
    problem = fmt::format("{} is shown thinned (1 sample in {}): its figures and samples need every sample",
                          doc->name, doc->samples->thinning);
  else if (s.exportKind == 0 && (s.exportWidth < 64 || s.exportHeight < 64 || s.exportWidth > 8192 || s.exportHeight > 8192))
    problem = "the size must be 64 to 8192 pixels each way";
  else if (s.exportKind == 2 && (s.exportFirst < 1 || s.exportLast < s.exportFirst))
    problem = "the lines must be first <= last, from 1";
  else if (s.exportKind == 3 && (s.exportRegions < 0 || s.exportRegions > 50))
    problem = "the regions shown must be 0 to 50";
  else if (s.exportKind == 3 && s.job.running())
    problem = "wait for the work in progress (or cancel it) first";
  else if (!s.exportPath[0]) problem = "give the file to write";
  if (!problem.empty()) ImGui::TextDisabled("%s", problem.c_str());
  const bool write = ImGui::Button("Export");
  noteControl(s, "export.write");
  if (write && problem.empty()) {
    if (s.exportKind == 0) {
      const std::vector<unsigned char> rgb = s.view.snapshot(s.exportWidth, s.exportHeight);
      if (rgb.empty()) s.status = "error: the view could not be drawn at that size";
      else s.save(s.exportPath, vis::pngOfRgb(rgb.data(), s.exportWidth, s.exportHeight), "view image");
    } else if (s.exportKind == 3) {
      s.startReport(s.exportPath, s.exportRegions);
    } else {
      // The figures' predicted deviation and the samples' feedback columns need the feedback.
      auto numbers = [&s, kind = s.exportKind, path = std::string(s.exportPath), first = s.exportFirst,
                      last = s.exportLast] { exportNumbers(s, kind, path, first, last); };
      if (!s.loadFeedbackFirst(numbers)) numbers();
    }
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Close") || escapeCloses(s)) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace isurface::panels
