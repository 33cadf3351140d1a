// The 3D view panel: VTK's frame as an image, mouse input to the camera, click to pick,
// rectangle zoom, and a rectangle that chooses the region to optimise.
#include <GL/gl.h>
#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "inspector_state.h"
#include "isurface/analysis/locate.h"
#include "isurface/vis/quality_scene.h"

namespace isurface::panels {

namespace {

// The scale bar's right end (a share of the view's width) and its foot (pixels above the view's).
constexpr float kScaleBarRight = 0.82f, kScaleBarFoot = 14;

// The lines of the surface's samples inside a rectangle dragged over the view (pixels from its
// top-left corner) go into the Optimise dialog, which opens.
void chooseRegion(Inspector::State& s, const app_model::ScreenRectangle& rectangle) {
  Document* doc = s.activeDocument();
  if (!doc || !doc->samples || !doc->map.mesh) return;
  const auto chosen = app_model::selectInRectangle(*doc->samples, doc->map.passes, s.view.projection(), rectangle);
  if (!chosen) {
    s.status = "no cutting sample of the surface inside the box";
    return;
  }
  s.dialogs.optimise.forgetTheRegionOfAnotherProgram(doc->programPath);
  s.dialogs.optimise.hold(chosen->lines, *chosen);
  s.dialogs.optimise.boxOnView = rectangle;
  s.dialogs.optimise.opening = true;
}

// A five-axis run's joints at sample k: the slides (in the length unit shown) and the rotary
// axes (deg); none for a run without joints.
std::vector<std::string> jointFields(const Trajectory& t, std::size_t k, const DisplayUnits& u) {
  std::vector<std::string> fields;
  const char* linear[] = {"joint_x", "joint_y", "joint_z"};
  for (int i = 0; i < 3; ++i) {
    const std::vector<double>* c = t.extraChannel(linear[i]);
    if (!c) return {};
    fields.push_back(fmt::format("{}{} {:.{}f}{}", i == 0 ? "joints " : "", char('X' + i), u.length((*c)[k]),
                                 u.lengthDecimals(), i == 2 ? std::string(" ") + u.lengthUnit() : ""));
  }
  for (const char* rotary : {"joint_a", "joint_b", "joint_c"})
    if (const std::vector<double>* c = t.extraChannel(rotary))
      fields.push_back(fmt::format("{} {:.3f} deg", char(rotary[6] - 'a' + 'A'), (*c)[k]));
  return fields;
}

// The picked sample's values, as the paper's window shows them (line, point, speed), right of
// the orientation axes in the lower left corner: a line each for the sample, the point and the
// feed where the view is wide enough, else more lines, never over the colour legend.
void drawSelectionReadout(Inspector::State& s, ImDrawList* draw, ImVec2 origin, ImVec2 size) {
  s.chrome.controls.erase("view.readout");
  const app_model::Selection& sel = s.selection.current();
  const Document* doc = s.activeDocument();
  if (!doc || !doc->samples || !sel.sample || *sel.sample >= doc->samples->size() || doc->curves.size() < 3) return;
  const std::size_t k = *sel.sample;
  const Trajectory& t = *doc->samples;
  // A marker on the selected sample straight away; the scene's own glow follows.
  if (const auto at = s.view.project(t.commanded(k))) {
    const ImVec2 centre(origin.x + static_cast<float>(at->first), origin.y + static_cast<float>(at->second));
    draw->AddCircle(centre, 9, IM_COL32(255, 230, 60, 255), 24, 2.0f);
    draw->AddCircle(centre, 13, IM_COL32(0, 0, 0, 160), 24, 1.5f);
  }
  const DisplayUnits u = s.units();
  const int d = u.lengthDecimals();
  std::vector<std::vector<std::string>> groups = {
      {sampleName(t, k), fmt::format("line {}", t.line[k]), fmt::format("t {:.3f} s", t.timeAt(k))},
      {fmt::format("X {:.{}f}", u.length(t.x[k]), d), fmt::format("Y {:.{}f}", u.length(t.y[k]), d),
       fmt::format("Z {:.{}f} {}", u.length(t.z[k]), d, u.lengthUnit())},
      // As the data table reads them (no "-0.0" for an acceleration below what is told apart).
      {fmt::format("v {} {}", readableValue(u.length(doc->curves[0].values.value(k)), u.motionResolution(0)), u.feedUnit()),
       fmt::format("a {} {}", readableValue(u.length(doc->curves[1].values.value(k)), u.motionResolution(1)),
                   u.accelerationUnit()),
       fmt::format("j {} {}", readableValue(u.length(doc->curves[2].values.value(k)), u.motionResolution(2)), u.jerkUnit())}};
  if (std::vector<std::string> joints = jointFields(t, k, u); !joints.empty()) groups.push_back(std::move(joints));
  const float left = size.x * static_cast<float>(vis::kAxesCornerWidth) + 10;
  const float room = size.x * static_cast<float>(vis::kLegendLeft) - left - 8;
  // Each group on lines of its own, as many of its values on a line as fit.
  std::string text;
  for (const auto& group : groups) {
    std::string line;
    for (const std::string& field : group) {
      const std::string longer = line.empty() ? field : line + "   " + field;
      if (!line.empty() && ImGui::CalcTextSize(longer.c_str()).x > room) {
        text += (text.empty() ? "" : "\n") + line;
        line = field;
      } else {
        line = longer;
      }
    }
    text += (text.empty() ? "" : "\n") + line;
  }
  const ImVec2 extent = ImGui::CalcTextSize(text.c_str());
  // Its foot a line above the view's; above the scale bar's label where it reaches over the bar.
  const float scaleBar = scaleBarFor(u, s.view.millimetresPerPixel(), size.x).pixels;
  const bool overScaleBar = left + extent.x + 8 > size.x * kScaleBarRight - scaleBar;
  const float foot = overScaleBar ? kScaleBarFoot + ImGui::GetTextLineHeight() + 10
                                  : ImGui::GetTextLineHeightWithSpacing();
  const ImVec2 at(origin.x + left, origin.y + size.y - foot - extent.y);
  const ImVec2 lower(at.x - 4, at.y - 3), upper(at.x + extent.x + 4, at.y + extent.y + 3);
  draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  draw->AddRectFilled(lower, upper, IM_COL32(0, 0, 0, 150), 3);
  draw->AddText(at, IM_COL32(255, 230, 120, 255), text.c_str());
  draw->PopClipRect();
  s.chrome.controls["view.readout"] = {lower.x, lower.y, upper.x, upper.y};
}

// A pick while measuring: the first end, then the second; a third starts a new distance.
void measurePick(Inspector::State& s, const Vec3& point) {
  if (!s.pointer.measureA || s.pointer.measureB) {
    s.pointer.measureA = point;
    s.pointer.measureB.reset();
    s.status = "measure: pick the second point";
    return;
  }
  s.pointer.measureB = point;
  const Vec3 d = *s.pointer.measureB - *s.pointer.measureA;
  const DisplayUnits u = s.units();
  const int n = u.lengthDecimals();
  char text[200];
  std::snprintf(text, sizeof text, "distance %.*f %s (dX %.*f  dY %.*f  dZ %.*f %s)", n, u.length(d.norm()), u.lengthUnit(),
                n, u.length(d.x()), n, u.length(d.y()), n, u.length(d.z()), u.lengthUnit());
  s.status = text;
}

// The measured ends and the line between them, with the distance beside it.
void drawMeasure(Inspector::State& s, ImDrawList* draw, ImVec2 origin) {
  if (!s.pointer.measureA) return;
  const auto a = s.view.project(*s.pointer.measureA);
  const auto b = s.pointer.measureB ? s.view.project(*s.pointer.measureB) : std::nullopt;
  const ImU32 colour = IM_COL32(80, 255, 255, 255);
  if (a) draw->AddCircleFilled(ImVec2(origin.x + float(a->first), origin.y + float(a->second)), 4, colour);
  if (!a || !b) return;
  const ImVec2 pa(origin.x + float(a->first), origin.y + float(a->second));
  const ImVec2 pb(origin.x + float(b->first), origin.y + float(b->second));
  draw->AddCircleFilled(pb, 4, colour);
  draw->AddLine(pa, pb, colour, 2.0f);
  char text[64];
  const DisplayUnits u = s.units();
  std::snprintf(text, sizeof text, "%.*f %s", u.lengthDecimals(), u.length((*s.pointer.measureB - *s.pointer.measureA).norm()), u.lengthUnit());
  const ImVec2 mid((pa.x + pb.x) * 0.5f + 6, (pa.y + pb.y) * 0.5f - 18);
  const ImVec2 extent = ImGui::CalcTextSize(text);
  draw->AddRectFilled(ImVec2(mid.x - 3, mid.y - 2), ImVec2(mid.x + extent.x + 3, mid.y + extent.y + 2), IM_COL32(0, 0, 0, 170), 3);
  draw->AddText(mid, colour, text);
}

// The value under the pointer once it rests over the surface: the nearest sample's, without
// changing the selection. One pick per resting place, so moving costs nothing.
void drawHoverValue(Inspector::State& s, double mx, double my) {
  Document* doc = s.activeDocument();
  if (!doc || !doc->samples || doc->curves.empty()) return;
  const ImGuiIO& io = ImGui::GetIO();
  const bool resting = io.MouseDelta.x == 0 && io.MouseDelta.y == 0;
  if (!resting) {
    s.pointer.hoverRestFrames = 0;
    s.pointer.hoverSample.reset();
    return;
  }
  // Picked again every so many frames at rest: the map under a resting pointer can change (a
  // new map, the view split for one beside it).
  if (++s.pointer.hoverRestFrames % kHoverRestFrames == 0) {
    s.pointer.hoverSample.reset();
    if (const auto hit = s.view.pick(mx, my)) s.pointer.hoverSample = sampleAtHit(*doc->samples, *doc->map.mesh, *hit);
  }
  if (!s.pointer.hoverSample || *s.pointer.hoverSample >= doc->samples->size()) return;
  const std::size_t k = *s.pointer.hoverSample;
  ImGui::BeginTooltip();
  ImGui::Text("line %u   %s", doc->samples->line[k], sampleName(*doc->samples, k).c_str());
  const DisplayUnits u = s.units();
  const char* unitOf[3] = {u.feedUnit(), u.accelerationUnit(), u.jerkUnit()};
  for (std::size_t c = 0; c < doc->curves.size() && c < 3; ++c)
    ImGui::Text("%s %s %s", doc->curves[c].label.c_str(), readableValue(u.length(doc->curves[c].values.value(k)), u.motionResolution(c)).c_str(),
                unitOf[c]);
  for (std::size_t c = 3; c < doc->curves.size(); ++c)
    if (doc->curves[c].label == s.settings.channel)
      ImGui::Text("%s %s", doc->curves[c].label.c_str(), readableValue(doc->curves[c].values.value(k)).c_str());
  ImGui::EndTooltip();
}

}  // namespace

// A bar of a round length (1, 2 or 5 times a power of ten) about a sixth of the view wide, at
// its lower right, for the scale at the focal point of a view `mmPerPixel` (mm) at it.
ScaleBar scaleBarFor(const DisplayUnits& u, double mmPerPixel, float width) {
  if (!(mmPerPixel > 0) || !std::isfinite(mmPerPixel)) return {};
  const double wanted = u.length(mmPerPixel * width / 6);  // in display units
  const double power = std::pow(10.0, std::floor(std::log10(wanted)));
  const double length = power * (wanted / power < 2 ? 1 : wanted / power < 5 ? 2 : 5);
  return {length, u.lengthUnit(), static_cast<float>(length / u.length(mmPerPixel))};
}

ScaleBar drawScaleBar(const DisplayUnits& u, double mmPerPixel, ImDrawList* draw, ImVec2 origin, ImVec2 size) {
  const ScaleBar bar = scaleBarFor(u, mmPerPixel, size.x);
  if (bar.pixels <= 0) return {};
  const double length = bar.length;
  const float pixels = bar.pixels;
  const ImVec2 right(origin.x + size.x * kScaleBarRight, origin.y + size.y - kScaleBarFoot);
  const ImVec2 left(right.x - pixels, right.y);
  const ImU32 ink = IM_COL32(30, 30, 36, 255);
  draw->AddLine(left, right, ink, 2.0f);
  draw->AddLine(ImVec2(left.x, left.y - 5), ImVec2(left.x, left.y + 1), ink, 2.0f);
  draw->AddLine(ImVec2(right.x, right.y - 5), ImVec2(right.x, right.y + 1), ink, 2.0f);
  char label[48];
  std::snprintf(label, sizeof label, "%g %s", length, u.lengthUnit());
  const ImVec2 extent = ImGui::CalcTextSize(label);
  draw->AddText(ImVec2((left.x + right.x - extent.x) / 2, left.y - extent.y - 3), ink, label);
  return bar;
}

// What the view says where no map stands: why the open document has none (passes too far
// apart, no cutting moves), so that the user is not told to open what is open.
std::string emptyViewText(const Inspector::State& s) {
  if (s.job.running()) return "working...";
  const Document* doc = s.active < s.documents.size() ? s.documents[s.active].get() : nullptr;
  if (!doc) return "no quality map yet: open a program or a dump";
  for (auto w = doc->warnings.rbegin(); w != doc->warnings.rend(); ++w)
    if (w->rfind("no map: ", 0) == 0) return *w;
  return "no quality map of " + doc->name;
}

void drawViewFrame(unsigned int texture, ImVec2 size) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddCallback([](const ImDrawList*, const ImDrawCmd*) { glDisable(GL_BLEND); }, nullptr);
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture)), size, ImVec2(0, 1), ImVec2(1, 0));
  draw->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
}

void drawSceneView(Inspector::State& s, float x, float y, float w, float h) {
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  beginPanel("3D view", x, y, w, h, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size = ImGui::GetContentRegionAvail();
  s.chrome.controls["view"] = {origin.x, origin.y, origin.x + size.x, origin.y + size.y};
  refineWhereTheCameraLooks(s, static_cast<int>(size.x), static_cast<int>(size.y));
  const unsigned int texture = s.view.render(static_cast<int>(size.x), static_cast<int>(size.y));
  if (texture) {
    drawViewFrame(texture, size);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    drawSelectionReadout(s, draw, origin, size);
    drawMeasure(s, draw, origin);
    s.pointer.scaleBar = drawScaleBar(s.units(), s.view.millimetresPerPixel(), draw, origin, size);
    if (s.refinement.building.valid())
      draw->AddText(ImVec2(origin.x + size.x * 0.45f, origin.y + size.y - 2 * ImGui::GetTextLineHeightWithSpacing()),
                    IM_COL32(30, 30, 36, 255), "refining the surface in sight...");
    // The box that chose the region, while the dialog it filled is open.
    const app_model::ScreenRectangle& r = s.dialogs.optimise.boxOnView;
    if (s.dialogs.optimise.box && s.dialogs.optimise.open && r.x0 != r.x1 && r.y0 != r.y1) {
      draw->AddRect(ImVec2(origin.x + float(r.x0), origin.y + float(r.y0)), ImVec2(origin.x + float(r.x1), origin.y + float(r.y1)),
                    IM_COL32(255, 200, 40, 255), 0, 0, 2.0f);
    }
  } else {
    ImGui::Dummy(size);
    ImGui::SetCursorScreenPos(ImVec2(origin.x + 20, origin.y + 20));
    // The wrap position is the window's own, not the screen's: 20 px short of the view's right.
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + size.x - 40);
    ImGui::TextDisabled("%s", emptyViewText(s).c_str());
    ImGui::PopTextWrapPos();
  }
  const ImGuiIO& io = ImGui::GetIO();
  const double mx = io.MousePos.x - origin.x, my = io.MousePos.y - origin.y;
  const ImVec2 pressedAt(s.pointer.pressX, s.pointer.pressY);
  // A left drag draws a rectangle instead of turning the camera.
  const bool rectangleTool = s.pointer.rectangleZoom || s.pointer.boxSelect;
  if (ImGui::IsWindowHovered() && texture) {
    for (int button = 0; button < 3; ++button) {
      if (ImGui::IsMouseClicked(button)) {
        s.pointer.pressX = io.MousePos.x;
        s.pointer.pressY = io.MousePos.y;
        s.pointer.pressedInView = true;
        if (!(rectangleTool && button == 0)) s.view.mouseButton(button, true, mx, my);
      }
    }
    if (io.MouseWheel != 0) s.view.mouseWheel(io.MouseWheel, mx, my);
  }
  if (s.pointer.pressedInView && !texture) {  // the view went away under the press
    s.view.cancelDrag();
    s.pointer.pressedInView = false;
  }
  if (s.pointer.pressedInView && texture) {
    s.view.mouseMove(mx, my);
    if (rectangleTool && ImGui::IsMouseDown(0))
      ImGui::GetWindowDrawList()->AddRect(pressedAt, io.MousePos,
                                          s.pointer.boxSelect ? IM_COL32(255, 200, 40, 255) : IM_COL32(255, 255, 255, 220), 0, 0, 1.5f);
    for (int button = 0; button < 3; ++button) {
      if (!ImGui::IsMouseReleased(button)) continue;
      const double moved = std::hypot(io.MousePos.x - pressedAt.x, io.MousePos.y - pressedAt.y);
      if (s.pointer.rectangleZoom && button == 0) {
        s.view.zoomToRectangle(pressedAt.x - origin.x, pressedAt.y - origin.y, mx, my);
        s.pointer.rectangleZoom = false;
      } else if (s.pointer.boxSelect && button == 0) {
        if (moved >= 3) chooseRegion(s, app_model::ScreenRectangle{pressedAt.x - origin.x, pressedAt.y - origin.y, mx, my});
        s.pointer.boxSelect = false;
      } else {
        s.view.mouseButton(button, false, mx, my);
      }
      // A click that did not drag picks the surface: the nearest sample becomes the selection,
      // or, while measuring, the point is an end of the distance.
      if (button == 0 && moved < 3 && !s.pointer.rectangleZoom) {
        if (const auto hit = s.view.pick(mx, my)) {
          Document* doc = s.activeDocument();
          if (s.pointer.measuring) measurePick(s, hit->point);
          else if (doc && doc->samples && doc->map.mesh) s.selection.selectSample(sampleAtHit(*doc->samples, *doc->map.mesh, *hit));
        }
      }
      s.pointer.pressedInView = false;
    }
  } else if (ImGui::IsWindowHovered() && texture) {
    s.view.mouseMove(mx, my);
    drawHoverValue(s, mx, my);
  } else {
    s.pointer.hoverSample.reset();  // the pointer left the view
    s.pointer.hoverRestFrames = 0;
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace isurface::panels
