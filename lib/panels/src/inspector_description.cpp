// The window's state told as JSON, and the places of its named controls: what a script or a
// test driving the window checks and clicks.
#include <imgui.h>
#include <nlohmann/json.hpp>

#include "inspector_state.h"
#include "isurface/base/json_text.h"

namespace isurface::panels {

void noteControl(Inspector::State& s, const std::string& name) {
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  s.chrome.controls[name] = {min.x, min.y, max.x, max.y};
}

std::optional<std::array<float, 4>> Inspector::controlRect(const std::string& name) const {
  const auto found = state_->chrome.controls.find(name);
  if (found == state_->chrome.controls.end()) return std::nullopt;
  return found->second;
}

namespace {

const char* viewDirectionName(vis::ViewDirection view) {
  switch (view) {
    case vis::ViewDirection::Top: return "top";
    case vis::ViewDirection::Front: return "front";
    case vis::ViewDirection::Left: return "left";
    case vis::ViewDirection::Iso: break;
  }
  return "iso";
}

nlohmann::json pointJson(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

// The region the Optimise dialog holds: its lines, its box (mm) and the surface samples inside.
nlohmann::json optimiseBoxJson(const app_model::BoxSelection& b) {
  nlohmann::json box = {{"lines", {b.lines.first, b.lines.last}}, {"lower", pointJson(b.lower)}, {"upper", pointJson(b.upper)}, {"samples", b.samples}};
  if (b.ownPasses) box["own_passes"] = {b.ownPasses->first, b.ownPasses->last};
  return box;
}

nlohmann::json machineJson(const Machine& m) {
  nlohmann::json axes = nlohmann::json::array();
  for (const AxisLimits& a : m.axes)
    axes.push_back({{"max_velocity_mm_s", a.maxVelocity}, {"max_acceleration_mm_s2", a.maxAcceleration},
                    {"max_jerk_mm_s3", a.maxJerk}});
  return {{"name", m.name}, {"cycle_s", m.cycle}, {"axes", axes}};
}

// The finer surface shown where the camera looks, if any, and whether one is being made.
nlohmann::json closeUpJson(const ViewRefinement& r) {
  nlohmann::json out = {{"building", r.building.valid()}};
  if (r.shown)
    out.update({{"vertices", r.shown->mesh->vertexSample.size()},
                {"stride", r.shown->stride},
                {"lower", pointJson(r.shown->lower)},
                {"upper", pointJson(r.shown->upper)}});
  return out;
}

}  // namespace

std::string Inspector::describe() const {
  const State& s = *state_;
  nlohmann::json documents = nlohmann::json::array();
  for (const auto& doc : s.documents) {
    nlohmann::json d = {{"name", doc->name},
                        {"program", doc->programPath},
                        {"dump", doc->dumpPath},
                        {"samples", doc->samples ? doc->samples->size() : 0},
                        {"machine", doc->machineKnown ? doc->machine.name : ""}};
    // "loaded", "on request" (in the dump or the servo's to replay, not yet loaded) or "none".
    d["feedback"] = doc->samples && doc->samples->hasFeedback() ? "loaded"
                    : doc->feedbackAvailable()                   ? "on request"
                                                                 : "none";
    if (doc->samples && doc->samples->size() > 1)
      d["duration_s"] = doc->samples->timeAt(doc->samples->size() - 1) - doc->samples->timeAt(0);
    d["map_quantity"] = doc->scene ? doc->map.style.quantityLabel : "";  // what its map is coloured by
    d["warnings"] = doc->warnings;
    documents.push_back(d);
  }
  const app_model::Selection& sel = s.selection.current();
  nlohmann::json selection = nlohmann::json::object();
  if (sel.sample) selection["sample"] = *sel.sample;
  if (sel.line) selection["line"] = *sel.line;
  if (s.pointer.hoverSample) selection["hover_sample"] = *s.pointer.hoverSample;
  if (const Document* active = s.active < s.documents.size() ? s.documents[s.active].get() : nullptr) {
    if (sel.sample && active->samples && *sel.sample < active->samples->size())
      selection["position"] = pointJson(active->samples->commanded(*sel.sample));
    if (active->scene)
      if (const std::optional<Vec3> tip = active->scene->toolTip()) selection["tool_tip"] = pointJson(*tip);
  }
  nlohmann::json measure = nlohmann::json::object();
  measure["active"] = s.pointer.measuring;
  if (s.pointer.measureA) measure["a"] = pointJson(*s.pointer.measureA);
  if (s.pointer.measureB) measure["b"] = pointJson(*s.pointer.measureB);
  if (s.pointer.measureA && s.pointer.measureB) measure["distance_mm"] = (*s.pointer.measureB - *s.pointer.measureA).norm();
  nlohmann::json controls = nlohmann::json::object();
  for (const auto& [name, rect] : s.chrome.controls) controls[name] = rect;
  // The surface's box in window pixels, where a script clicks to pick.
  const auto view = s.chrome.controls.find("view");
  if (const auto r = s.view.surfaceOnScreen(); r && view != s.chrome.controls.end())
    controls["surface"] = {view->second[0] + r->x0, view->second[1] + r->y0, view->second[0] + r->x1, view->second[1] + r->y1};
  nlohmann::json camera = nlohmann::json::object();
  if (const auto pose = s.view.camera())
    camera = {{"position", pointJson(pose->position)}, {"focal_point", pointJson(pose->focalPoint)}, {"view_up", pointJson(pose->viewUp)},
              {"parallel_scale_mm", pose->parallelScale}, {"view_angle_deg", pose->viewAngle}};
  nlohmann::json windows = {{"machine", s.dialogs.machine.open},
                            {"locate", s.dialogs.locate.open},
                            {"optimise", s.dialogs.optimise.open},
                            {"export", s.dialogs.exportTo.open},
                            {"replace_question", s.dialogs.overwriteQuestion.has_value()},
                            {"help", s.dialogs.helpOpen},
                            {"warnings", s.dialogs.warningsOpen},
                            {"regions", s.dialogs.regionsOpen},
                            {"menu", s.chrome.menuOpen}};
  nlohmann::json map = nlohmann::json::object();
  if (const Document* doc = s.active < s.documents.size() ? s.documents[s.active].get() : nullptr; doc && doc->scene)
    map = {{"quantity", doc->map.style.quantityLabel},
           {"unit", doc->map.style.unit},
           {"range", {doc->map.style.range.lo, doc->map.style.range.hi}},
           {"colour_map", doc->map.style.colorMap},
           {"caption", doc->map.style.caption},
           {"surface", s.settings.feedbackSurface ? "feedback" : "commanded"},
           {"vertices", doc->map.mesh ? doc->map.mesh->vertexSample.size() : 0},
           {"passes", doc->map.passes.passes.size()},
           {"regions_found", doc->regions && doc->regionsOfMap == doc->map.mesh ? nlohmann::json(doc->regions->regions.size())
                                                                                : nlohmann::json()},
           {"pattern", pathPatternName(doc->map.passes.pattern)},
           {"pattern_asked", pathPatternName(doc->map.request.pattern)},
           {"close_up", closeUpJson(s.refinement)}};
  nlohmann::json optimised;  // the re-optimisation shown beside the map
  if (s.comparison)
    optimised = {{"lines", {s.comparison->first, s.comparison->last}},
                 {"kept", s.comparison->kept},
                 {"summary", s.comparison->summary},
                 {"superseded_by", s.comparison->supersededBy},
                 {"saved", s.comparison->saved},
                 {"discard_question", s.comparison->discardQuestion}};
  const nlohmann::json out = {{"documents", documents},
                              {"optimised", optimised},
                              {"map", map},
                              {"view_text", map.empty() ? emptyViewText(s) : std::string()},
                              {"length_unit", s.units().lengthUnit()},
                              {"colour", {{"quantity", s.settings.channel.empty() ? quantityInfo(s.settings.quantity).label
                                                                                   : s.settings.channel},
                                          {"unit", s.settings.channel.empty()
                                                       ? s.units().unitOf(quantityInfo(s.settings.quantity).unit)
                                                       : ""},
                                          {"range_mode", s.settings.rangeMode},
                                          {"view", viewDirectionName(s.settings.view)},
                                          {"gap_limit_mm", s.settings.gapLimit},
                                          {"fixed", {s.settings.fixedLow, s.settings.fixedHigh}}}},
                              {"locate", {{"sample", s.dialogs.locate.sample}, {"line", s.dialogs.locate.line}, {"message", s.dialogs.locate.message}}},
                              {"recent_files", s.persistent.recentFiles},
                              {"scale_bar", {{"length", s.pointer.scaleBar.length}, {"unit", s.pointer.scaleBar.unit}, {"pixels", s.pointer.scaleBar.pixels}}},
                              {"theme", s.persistent.theme},
                              {"ui_scale", s.persistent.uiScale},
                              {"active", s.active},
                              {"optimise_lines", {s.dialogs.optimise.first, s.dialogs.optimise.last}},  // the Optimise dialog's range
                              {"optimise_time_share", s.active < s.documents.size() ? linesTimeShare(*s.documents[s.active], s.dialogs.optimise.first, s.dialogs.optimise.last).value_or(0.0) : 0.0},
                              {"open_path", s.dialogs.open.path},  // the Open dialog's path, typed or chosen
                              {"export_path", s.dialogs.exportTo.path},  // the Export dialog's
                              {"busy", s.job.running() || !s.queue.runs.empty()},
                              {"job", s.job.running() ? nlohmann::json{{"label", s.job.label()}, {"progress", s.job.progress()}, {"stage", s.job.stage()}}
                                                      : nlohmann::json()},
                              {"selection", selection},
                              {"curves_span", {s.follow.curveFirst, s.follow.curveLast}},  // samples the curves show
                              {"gcode_search", s.dialogs.gcodeSearch.message},
                              {"gcode_search_text", s.dialogs.gcodeSearch.text},  // what the find field holds
                              {"gcode_top_line", s.follow.gcodeTopLine},
                              {"machine", machineJson(s.dialogs.machine.inUse)},
                              {"machine_source", s.dialogs.machine.source},
                              {"machine_edited", s.dialogs.machine.open ? machineJson(s.dialogs.machine.edit) : nlohmann::json()},
                              {"measure", measure},
                              {"windows", windows},
                              {"last_saved", s.chrome.lastSaved},
                              {"optimise_problem", s.dialogs.optimise.open ? s.dialogs.optimise.problem : std::string()},
                              {"optimise_range_problem", s.dialogs.optimise.open ? s.dialogs.optimise.rangeProblem() : std::string()},
                              {"optimise_notice", s.dialogs.optimise.open ? s.dialogs.optimise.notice : std::string()},
                              {"optimise_box", s.dialogs.optimise.open && s.dialogs.optimise.box ? optimiseBoxJson(*s.dialogs.optimise.box) : nlohmann::json()},
                              {"optimise_replaces", s.dialogs.optimise.open ? unsavedResultReplaced(s) : std::string()},
                              {"status", s.status},
                              {"status_shown", s.chrome.statusShown},
                              {"camera", camera},
                              {"controls", controls}};
  return jsonText(out, 1);
}

}  // namespace isurface::panels
