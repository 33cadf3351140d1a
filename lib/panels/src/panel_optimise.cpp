// Re-optimising a region from the application: choose the lines (typed, dragged as a box over
// the surface, or the worst region the quality prediction finds), optimise in the background,
// and see the new map beside the old one, the same colour range and camera, or the speed
// difference on the old surface, with the region's figures; save the new program.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "inspector_state.h"
#include "text_input.h"
#include "isurface/optimise/optimized_run_comparison.h"
#include "isurface/workflow/region_optimisation.h"
#include "isurface/workflow/run_inputs.h"
#include "isurface/vis/difference_map.h"
#include "isurface/vis/quality_scene.h"

namespace isurface::panels {

namespace {

// How far the re-fitted passes moved and how their speed changed (after - before).
std::string passDifferenceText(const RunComparison& difference, const OptimizeResult& optimized) {
  double apart = 0, speedChange = 0;  // mm; mm/min, the signed change of largest magnitude
  for (const LineDifference& d : difference.lines) {
    const bool refitted = std::any_of(optimized.passes.begin(), optimized.passes.end(),
                                      [&](const OptimizedPass& p) { return p.firstLine == d.line; });
    if (!refitted) continue;
    apart = std::max(apart, d.figures.maxPathDistance);
    if (std::abs(d.figures.maxSpeedDifference) > std::abs(speedChange)) speedChange = d.figures.maxSpeedDifference;
  }
  return fmt::format(". Simulated, the tool runs within {:.4f} mm of where it ran before; speed after - before up to "
                     "{:+.0f} mm/min",
                     apart, speedChange);
}

std::string whyNotOptimisable(const Document* doc) {
  if (!doc) return "Optimise needs a G-code program: open one first";
  if (!doc->program || doc->programPath.empty())
    return "Optimise needs the G-code program of " + doc->name + ": open the program and this dump together";
  if (!doc->samples || !doc->map.mesh) return "Optimise needs a surface: " + doc->name + " has no cutting passes";
  if (doc->samples->thinning > 1)
    return "Optimise needs every sample: " + doc->name + " is shown thinned (1 sample in " +
           std::to_string(doc->samples->thinning) + ")";
  return "";
}

}  // namespace

std::optional<double> linesTimeShare(const Document& doc, int first, int last) {
  if (!doc.samples || doc.samples->size() < 2 || first < 1 || last < first) return std::nullopt;
  std::size_t inside = 0;
  doc.samples->line.forEachRun([&](std::uint32_t line, std::size_t begin, std::size_t end) {
    if (line >= static_cast<std::uint32_t>(first) && line <= static_cast<std::uint32_t>(last)) inside += end - begin;
  });
  return double(inside) / double(doc.samples->size());
}

namespace {

// The dialog holds a region found for the user (not dragged on the view, so not drawn there).
void holdRegion(Inspector::State& s, const ChosenRegion& region, const char* what) {
  app_model::BoxSelection box{region.lines, region.lower, region.upper, region.vertices};
  if (region.ownPasses.first > 0) box.ownPasses = region.ownPasses;
  s.dialogs.optimise.hold(region.lines, box);
  s.dialogs.optimise.boxOnView = {};
  s.status = fmt::format("{}: lines {}-{}", what, region.lines.first, region.lines.last);
}

// As `optimize --auto`: whole passes around the worst region, its figures taken inside its box.
void chooseWorstRegion(Inspector::State& s) {
  const Document* doc = s.activeDocument();
  if (!doc || !doc->samples || !doc->map.mesh) return;
  try {
    const SurfaceRun run{doc->samples, doc->map.passes, vis::figuresMesh(*doc->samples, doc->map), doc->map.request.gapLimit};
    holdRegion(s, worstRegion(run, doc->name), "worst predicted region");
    // Widened to the passes joined to it (a pass left as it was beside one re-planned leaves a seam);
    // regions where passes start and end rank too, but no re-fitting changes them.
    s.status += " (with every pass joined to it on the surface; the worst inside the passes, regions at pass ends left out)";
  } catch (const InputError& e) {
    s.status = s.dialogs.optimise.notice = e.what();
  }
}

}  // namespace

void Inspector::State::startOptimise(std::uint32_t first, std::uint32_t last,
                                     std::optional<std::pair<Vec3, Vec3>> measuredBox) {
  Document* doc = activeDocument();
  if (const std::string why = whyNotOptimisable(doc); !why.empty()) {
    status = why;
    return;
  }
  if (refusedDuringReport("optimise")) return;
  // "Before" is the document's own run, judged on its predicted deviation too.
  if (doc->machineKnown && loadFeedbackFirst([this, first, last, measuredBox] { startOptimise(first, last, measuredBox); }))
    return;
  vis::QualityMapRequest request = mapRequest();
  request.fixedRange = doc->map.style.range;  // the same colours on both sides
  request.caption = mapCaption(*doc);         // simulated with the document's machine, as the map beside
  auto result = std::make_shared<JobResult>(OptimisedRegion{doc->samples, nullptr});
  pending = result;
  const std::string path = doc->programPath;
  std::shared_ptr<const Program> program = doc->program;
  // A trace is measured, not simulated: the program is simulated for "before" too, so that
  // both sides are judged alike (as `optimize` does).
  std::shared_ptr<const Trajectory> documentSamples = doc->machineKnown ? doc->samples : nullptr;
  const Machine machine = doc->machine;  // the document's own, as the CLI's --machine
  const auto objective = static_cast<Objective>(std::clamp(dialogs.optimise.objective, 0, 2));
  job.start(fmt::format("optimising lines {}-{}", first, last),
            [result, path, program, documentSamples, request, first, last, measuredBox, machine,
             objective](app_model::JobControl& control) {
              std::ifstream in(path, std::ios::binary);
              std::stringstream text;
              text << in.rdbuf();
              // The whole surface, not the map's (thinned on large programs), as `optimize`.
              if (!documentSamples) control.stage("simulating the program as it is");
              const std::shared_ptr<const Trajectory> before =
                  documentSamples ? documentSamples : std::make_shared<const Trajectory>(simulateRun(*program, machine));
              const SurfaceRun beforeRun = surfaceRun(before, program.get(), request.gapLimit);
              RegionRequest region;
              region.lines = LineRange{first, last};
              region.box = measuredBox;
              region.objective = objective;
              region.onCandidate = [&control](const std::string& which) { control.stage(which); };
              const RegionOptimisation r = optimiseRegion(text.str(), *program, beforeRun, machine, region,
                                                          [&](double f) { control.progress(0.8 * f); });
              auto c = std::make_shared<Comparison>();
              c->text = r.result.text;
              c->first = first;
              c->last = last;
              c->program = r.program;
              c->samples = r.after.samples;
              control.stage("making the maps");
              c->map = vis::buildQualityMap(*c->samples, c->program.get(), request);
              c->scene = std::make_shared<vis::QualityScene>(c->map.data, c->map.style);
              control.progress(0.9);
              c->difference = compareOptimizedRuns(*before, *c->samples, r.result);
              control.progress(0.95);
              buildDifferenceView(vis::regionDifferenceMapRequest(c->difference, *before, LineRange{first, last}), request,
                                  *before, program.get(), c->differenceMap, c->differenceScene);
              control.progress(1.0);  // a Cancel pressed while the maps were made still cancels
              c->timeBefore = r.timeBefore;
              c->timeAfter = r.timeAfter;
              c->kept = r.kept;
              // The difference map's colours span its 1-99 % range, not the largest difference
              // the text gives: said, so that a colour at the end of the bar is not read as the most.
              const auto& colours = c->differenceMap.style.range;
              // Whether it is kept first: the panel shows the start of a long summary and scrolls the rest.
              c->summary = regionVerdict(r) + ". " + regionFigures(r) + passDifferenceText(c->difference, r.result) +
                           fmt::format(" (the difference map's colours span {:+.0f} .. {:+.0f} mm/min)", colours.lo,
                                       colours.hi);
              std::get<OptimisedRegion>(*result).comparison = c;
            });
}

void Inspector::State::showOptimisedDifference(bool difference) {
  if (!comparison) return;
  comparison->showDifference = difference;
  afterView.setScene(difference ? comparison->differenceScene : comparison->scene);
}

// A dialog opened with no range chosen yet (nor a box dragged) starts at the pass of the
// selected line, where the user was looking, rather than at line 1.
void startAtTheSelectedPass(Inspector::State& s) {
  const Document* doc = s.activeDocument();
  const auto& line = s.selection.current().line;
  if (s.dialogs.optimise.box || s.dialogs.optimise.first != 1 || s.dialogs.optimise.last != 1 || !line || !doc || !doc->samples) return;
  if (const auto pass = passOfLine(SurfaceRun{doc->samples, doc->map.passes, nullptr}, *line)) {
    s.dialogs.optimise.first = static_cast<int>(pass->first);
    s.dialogs.optimise.last = static_cast<int>(pass->last);
  }
}

std::string unsavedResultReplaced(const Inspector::State& s) {
  if (!s.comparison || !s.comparison->kept || s.comparison->saved) return "";
  return fmt::format("The re-optimised program of lines {}-{} is kept but not saved: optimising again replaces it "
                     "(Save program, beside the map, keeps it).",
                     s.comparison->first, s.comparison->last);
}

// The regions the dialog offers besides typed lines: the worst one, the whole program, the
// selected line's pass.
void drawRegionButtons(Inspector::State& s, Document* doc) {
  const bool worst = ImGui::Button("Worst predicted region");
  noteControl(s, "optimise.worst");
  if (worst && doc && doc->samples && doc->map.mesh) {
    // The regions are judged on the predicted deviation too, as `optimize --auto` judges them.
    if (!s.loadFeedbackFirst([&s] { chooseWorstRegion(s); })) chooseWorstRegion(s);
  }
  ImGui::SameLine();
  const bool whole = ImGui::Button("Whole program");
  noteControl(s, "optimise.whole");
  if (whole && doc && doc->samples && doc->map.mesh) {
    try {
      // As `optimize --all`: every pass, the figures taken over all of them.
      const SurfaceRun run{doc->samples, doc->map.passes, vis::figuresMesh(*doc->samples, doc->map), doc->map.request.gapLimit};
      holdRegion(s, wholeProgramRegion(run, doc->name), "whole program");
    } catch (const InputError& e) {
      s.status = s.dialogs.optimise.notice = e.what();
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Selected line's pass") && s.selection.current().line && doc && doc->samples) {
    const SurfaceRun run{doc->samples, doc->map.passes, nullptr};
    if (const auto pass = passOfLine(run, *s.selection.current().line)) {
      s.dialogs.optimise.hold(*pass);
      s.status = fmt::format("the pass of line {}: lines {}-{}", *s.selection.current().line, pass->first, pass->last);
    } else {
      s.status = s.dialogs.optimise.notice = "line " + std::to_string(*s.selection.current().line) + " is on no cutting pass";
    }
  }
}

void drawOptimiseDialog(Inspector::State& s) {
  if (s.dialogs.optimise.opening) {
    const Document* active = s.activeDocument();
    s.dialogs.optimise.forgetTheRegionOfAnotherProgram(active ? active->programPath : std::string());
    startAtTheSelectedPass(s);
    ImGui::OpenPopup("Optimise region");
  }
  s.dialogs.optimise.opening = false;
  s.dialogs.optimise.open = beginDialog("Optimise region");
  if (!s.dialogs.optimise.open) {
    // The box stays with its lines for the next opening; where it was dragged on the screen
    // does not, as the camera may move meanwhile.
    s.dialogs.optimise.boxOnView = {};
    s.dialogs.optimise.notice.clear();
    return;
  }
  Document* doc = s.activeDocument();
  const std::string why = whyNotOptimisable(doc);
  s.dialogs.optimise.problem = why;
  if (!why.empty()) {
    // Nothing to optimise: say why here, where the user looks, and offer only Close.
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", why.c_str());
    if (ImGui::Button("Close") || escapeCloses(s)) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return;
  }
  ImGui::TextWrapped("%s", "The paper's constant speed intervals and Akima fitting first, then other plans (corners rounded, "
                     "points drawn taut, feeds capped); each simulated, and kept only when no figure is worse by more "
                     "than 2 % and the time or a figure is better by 2 % or more. The G1 moves of the lines:");
  ImGui::InputInt("first line", &s.dialogs.optimise.first);
  noteControl(s, "optimise.first");
  ImGui::InputInt("last line", &s.dialogs.optimise.last);
  noteControl(s, "optimise.last");
  // What the lines cost before the button does: every plan simulates them (the worst region of a
  // raster is widened to the passes joined to it, which on a relief can be all of them).
  if (const std::optional<double> share = linesTimeShare(*doc, s.dialogs.optimise.first, s.dialogs.optimise.last)) {
    const Trajectory& t = *doc->samples;
    const double total = t.timeAt(t.size() - 1) - t.timeAt(0);
    ImGui::TextWrapped("Lines %d-%d run %.0f s of the program's %.0f s (%.1f %%): each plan simulates them%s",
                       s.dialogs.optimise.first, s.dialogs.optimise.last, *share * total, total, 100 * *share,
                       *share > 0.5 ? ", which takes a while" : "");
  }
  // The box only stands for the region while the lines are still its own.
  const bool boxed = s.dialogs.optimise.boxed();
  // Always a line here, so that the buttons below stay where they were when a box is chosen.
  if (boxed) {
    const app_model::BoxSelection& b = *s.dialogs.optimise.box;
    ImGui::TextWrapped("Box: X %.2f .. %.2f  Y %.2f .. %.2f mm, %zu surface samples; the figures are taken inside it",
                b.lower.x(), b.upper.x(), b.lower.y(), b.upper.y(), b.samples);
    // A region widened to every pass joined to it may be most of the program: the passes it lies
    // on alone are offered (a seam beside them is the price), and back.
    if (const std::optional<LineRange> other = s.dialogs.optimise.otherWidth()) {
      const bool widened = other->last - other->first < static_cast<std::uint32_t>(s.dialogs.optimise.last - s.dialogs.optimise.first);
      const std::string label = fmt::format("{}: lines {}-{}###width", widened ? "Only the passes it lies on" : "With the passes joined to it",
                                            other->first, other->last);
      if (ImGui::SmallButton(label.c_str())) s.dialogs.optimise.holdOtherWidth();
      noteControl(s, "optimise.width");
    } else {
      ImGui::Dummy(ImVec2(0, ImGui::GetTextLineHeight()));  // its room kept: the buttons below stay put
    }
  } else {
    ImGui::TextWrapped("%s", "No box: the figures are taken where the first plan re-fits the path");
    ImGui::Dummy(ImVec2(0, ImGui::GetTextLineHeight()));
  }
  drawRegionButtons(s, doc);
  // Said here too, where the user looks: the lines above are still those chosen before.
  if (!s.dialogs.optimise.notice.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s (the lines above are unchanged)", s.dialogs.optimise.notice.c_str());
  // As `optimize --objective`: what the closed loop chooses among candidates no figure of which is worse.
  static const char* const kObjectiveHelp[] = {"no figure worse, time not longer: the best figures and time together",
                                                "no figure worse, time not longer: the fastest such candidate",
                                                "no figure worse, up to 5 % longer: the best figures"};
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8);
  ImGui::Combo("objective", &s.dialogs.optimise.objective, "balanced\0time\0quality\0");
  s.dialogs.optimise.objective = std::clamp(s.dialogs.optimise.objective, 0, 2);
  ImGui::SameLine();
  ImGui::TextDisabled("%s", kObjectiveHelp[s.dialogs.optimise.objective]);
  // Said where the user looks, and the button greyed: a click that did nothing would say nothing.
  const std::string rangeProblem = s.dialogs.optimise.rangeProblem();
  if (!rangeProblem.empty()) ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", rangeProblem.c_str());
  // A kept program not saved lives only beside the map: said before a new result replaces it.
  if (const std::string replaced = unsavedResultReplaced(s); !replaced.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", replaced.c_str());
  ImGui::BeginDisabled(!rangeProblem.empty());
  const bool run = ImGui::Button(unsavedResultReplaced(s).empty() ? "Optimise###run" : "Optimise, replacing it###run");
  noteControl(s, "optimise.run");
  ImGui::EndDisabled();
  if (run && rangeProblem.empty()) {
    std::optional<std::pair<Vec3, Vec3>> measured;
    if (boxed) measured = std::make_pair(s.dialogs.optimise.box->lower, s.dialogs.optimise.box->upper);
    s.startOptimise(static_cast<std::uint32_t>(s.dialogs.optimise.first), static_cast<std::uint32_t>(s.dialogs.optimise.last), measured);
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Close") || escapeCloses(s)) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

namespace {

// The text's lines wrapped at its spaces only: ImGui's own wrapping also breaks a line after a
// full stop, inside a number too ("34." then "0 mm/min").
std::vector<std::string> wrappedAtSpaces(const std::string& text, float width) {
  const float space = ImGui::CalcTextSize(" ").x;
  std::vector<std::string> lines(1);
  float lineWidth = 0;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    const float w = ImGui::CalcTextSize(word.c_str()).x;
    if (!lines.back().empty() && lineWidth + space + w > width) lines.emplace_back(), lineWidth = 0;
    if (!lines.back().empty()) lines.back() += ' ', lineWidth += space;
    lines.back() += word;
    lineWidth += w;
  }
  return lines;
}

// Of the panel's height, the most its summary takes: the rest is the map's, and the summary
// scrolls.
constexpr float kSummaryShare = 0.35f;

}  // namespace

void beginBesidePanel(const char* name, const std::string& summary, float x, float y, float w, float h) {
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
  beginPanel(name, x, y, w, h, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  const float width = ImGui::GetContentRegionAvail().x;
  const std::vector<std::string> lines = wrappedAtSpaces(summary, width - ImGui::GetStyle().ScrollbarSize);
  const float needed = float(lines.size()) * ImGui::GetTextLineHeightWithSpacing();
  // A child of its own for each summary: a new result opens at its top, where its verdict is,
  // not where the last one was scrolled to.
  ImGui::BeginChild(ImGui::GetID(summary.c_str()), ImVec2(width, std::min(needed, kSummaryShare * h)));
  for (const std::string& line : lines) ImGui::TextUnformatted(line.c_str());
  ImGui::EndChild();
}

bool endBesidePanel(Inspector::State& s, bool close) {
  // Seen from where the map beside it is seen.
  if (s.view.scene() && s.afterView.scene()) s.afterView.copyCameraFrom(s.view);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size = ImGui::GetContentRegionAvail();
  const unsigned int texture = s.afterView.render(static_cast<int>(size.x), static_cast<int>(size.y));
  if (texture) {
    drawViewFrame(texture, size);
    drawScaleBar(s.units(), s.afterView.millimetresPerPixel(), ImGui::GetWindowDrawList(), origin, size);
  }
  ImGui::End();
  ImGui::PopStyleVar();
  if (close) {
    s.afterView.setScene(nullptr);
    s.view.refit();  // the main view has the whole width again
  }
  return close;
}

namespace {

// Whether the user, asked, lets the kept program go unsaved; Esc or "Keep it" keeps it open.
bool askToDiscard(Inspector::State& s, Comparison& c) {
  constexpr const char* kTitle = "Close without saving?";
  if (!ImGui::IsPopupOpen(kTitle)) ImGui::OpenPopup(kTitle);
  if (!beginDialog(kTitle)) return false;
  ImGui::Text("The re-optimised program of lines %u-%u is kept but not saved.", c.first, c.last);
  ImGui::TextUnformatted("Closed, it is gone (optimising again makes it anew).");
  const bool discard = ImGui::Button("Close without saving");
  noteControl(s, "discard.yes");
  ImGui::SameLine();
  const bool keep = ImGui::Button("Keep it");
  noteControl(s, "discard.no");
  if (discard || keep || s.takeEscape()) {
    c.discardQuestion = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
  return discard;
}

}  // namespace

void drawComparisonView(Inspector::State& s, float x, float y, float w, float h) {
  Comparison& c = *s.comparison;
  beginBesidePanel("After re-optimisation",
                   c.supersededBy.empty() ? c.summary
                                          : fmt::format("Earlier result, lines {}-{} ({}): {}", c.first, c.last,
                                                        c.supersededBy, c.summary),
                   x, y, w, h);
  if (const auto difference = drawDifferenceToggle(c.showDifference, "Difference (after - before)"))
    s.showOptimisedDifference(*difference);
  if (c.kept) {
    ImGui::SetNextItemWidth(w * 0.5f);
    inputText("##save", s.dialogs.optimise.savePath);
    noteControl(s, "optimised.path");
    ImGui::SameLine();
    if (ImGui::Button("Save program") && !s.dialogs.optimise.savePath.empty())
      s.save(s.dialogs.optimise.savePath, c.text, "re-optimised program");
    noteControl(s, "optimised.save");
    ImGui::SameLine();
  }  // else nothing to save: the summary ends with why the program stays as it is
  bool close = ImGui::Button("Close");
  noteControl(s, "optimised.close");
  // A kept program not saved is only in the window: closed, it would be lost without a word.
  if (close && c.kept && !c.saved) {
    c.discardQuestion = true;
    close = false;
  }
  if (c.discardQuestion) close = askToDiscard(s, c);
  if (endBesidePanel(s, close)) s.comparison.reset();
}

}  // namespace isurface::panels
