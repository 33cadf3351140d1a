// Menu, toolbar, navigation tree, status bar and dialogs.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "inspector_state.h"
#include "isurface/panels/ui_look.h"
#include "isurface/vis/color_map.h"
#include "isurface/vis/quality_scene.h"

namespace isurface::panels {

namespace {

// The panels tile the window: clicking one never brings it over a floating window (Locate).
constexpr ImGuiWindowFlags kPanel = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                    ImGuiWindowFlags_NoBringToFrontOnFocus;

// A key pressed while no text field has the keyboard and no dialog or menu is open (letters are
// their upper-case ASCII code in both hosts). Under an open dialog a shortcut would open a
// window behind it, which Dear ImGui 1.86 does not allow (it asserts).
// A key of the window's own, unless text is being typed: into a field, into a dialog that is
// open or asked to open (what is typed right after O is the path, not shortcuts).
bool shortcut(const Inspector::State& s, int key, bool ctrl = false) {
  const ImGuiIO& io = ImGui::GetIO();
  const Dialogs& d = s.dialogs;
  const bool dialogComing = d.open.opening || d.exportTo.opening || d.optimise.opening || d.locate.opening ||
                            d.gcodeSearch.focus || d.gcodeSearch.typing.framesLeft > 0;
  return !io.WantTextInput && !dialogComing && io.KeyCtrl == ctrl &&
         !ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId) && ImGui::IsKeyPressed(key, false);
}

// The text as it fits in `width` pixels: whole, or its beginning and "...". Cut between UTF-8
// characters, never inside one.
std::string fittedToWidth(const std::string& text, float width) {
  if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  const float room = width - ImGui::CalcTextSize("...").x;
  std::size_t lo = 0, hi = text.size();  // the longest beginning that fits: lo fits, beyond hi does not
  while (lo < hi) {
    const std::size_t mid = (lo + hi + 1) / 2;
    if (ImGui::CalcTextSize(text.data(), text.data() + mid).x <= room) lo = mid;
    else hi = mid - 1;
  }
  while (lo > 0 && (static_cast<unsigned char>(text[lo]) & 0xC0) == 0x80) --lo;
  return text.substr(0, lo) + "...";
}

bool toolButton(const char* label, const char* tip) {
  const bool pressed = ImGui::Button(label);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
  ImGui::SameLine();
  return pressed;
}

// A tool that stays on until switched off: lit while on, its label unchanged, so that the buttons
// after it stay put.
bool modeButton(const char* label, const char* tip, bool on) {
  if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
  const bool pressed = toolButton(label, tip);
  if (on) ImGui::PopStyleColor();
  return pressed;
}

void toggleMeasure(Inspector::State& s) {
  s.pointer.measuring = !s.pointer.measuring;
  s.pointer.measureA.reset();
  s.pointer.measureB.reset();
  s.status = s.pointer.measuring ? "measure: click the first point on the surface (Esc ends)" : "measuring ended";
}

// Theme, size of text and controls, and the units lengths are shown in; all remembered.
void drawLookMenus(Inspector::State& s) {
  app_model::Settings& p = s.persistent;
  bool look = false;
  if (ImGui::BeginMenu("Theme")) {
    for (const char* theme : {"dark", "light"})
      if (ImGui::MenuItem(theme, nullptr, p.theme == theme)) p.theme = theme, look = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Text and controls size")) {
    for (float scale : {1.0f, 1.25f, 1.5f, 2.0f}) {
      const std::string label = std::to_string(static_cast<int>(scale * 100)) + " %";
      if (ImGui::MenuItem(label.c_str(), nullptr, p.uiScale == scale)) p.uiScale = scale, p.uiScaleChosen = look = true;
    }
    ImGui::EndMenu();
  }
  const std::string unitsBefore = p.units;
  if (ImGui::BeginMenu("Units")) {
    if (ImGui::MenuItem("as the program is written", nullptr, p.units == "auto")) p.units = "auto";
    if (ImGui::MenuItem("mm", nullptr, p.units == "mm")) p.units = "mm";
    if (ImGui::MenuItem("inch", nullptr, p.units == "inch")) p.units = "inch";
    ImGui::EndMenu();
  }
  if (look) applyTheme(p.theme, p.uiScale);
  if (p.units != unitsBefore) {
    if (s.settings.rangeMode == 2) s.settings.rangeMode = 0;  // a fixed range was in the other units
    if (!s.job.running()) s.startRecolour();                   // the map's legend in the new units
  }
}

void setView(Inspector::State& s, vis::ViewDirection view) {
  s.settings.view = view;
  if (Document* doc = s.activeDocument()) doc->viewDirection = view;
  s.view.setView(view);
}

}  // namespace

bool beginDialog(const char* title) {
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImGui::GetMainViewport()->WorkSize);
  return ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
}

void beginPanel(const char* name, float x, float y, float w, float h, int extraFlags) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin(name, nullptr, kPanel | extraFlags);
}

// Inside a menu of the bar: Esc closes it (Dear ImGui 1.86 does only with keyboard navigation on).
void closeMenuOnEscape(Inspector::State& s) {
  s.chrome.menuOpen = true;
  if (s.takeEscape()) ImGui::CloseCurrentPopup();
}

void drawMenuAndToolbar(Inspector::State& s, float toolbarTop, float width) {
  bool simulate = false, locate = false;
  const bool boxSelectWasOn = s.pointer.boxSelect;
  s.chrome.menuOpen = false;
  if (ImGui::BeginMainMenuBar()) {
    const bool fileMenu = ImGui::BeginMenu("File");
    noteControl(s, "menu.file");
    if (fileMenu) {
      if (ImGui::MenuItem("Open G-code or Biip...", "O")) s.dialogs.openedByKey = 0, s.dialogs.open.open();
      const bool recentMenu = ImGui::BeginMenu("Recent files", !s.persistent.recentFiles.empty());
      noteControl(s, "menu.recent");
      if (recentMenu) {
        std::optional<std::string> chosen;
        for (std::size_t i = 0; i < s.persistent.recentFiles.size(); ++i) {
          if (ImGui::MenuItem(s.persistent.recentFiles[i].c_str())) chosen = s.persistent.recentFiles[i];
          noteControl(s, "recent." + std::to_string(i));
        }
        if (chosen) s.openFile(*chosen);  // after the loop: opening reorders the list
        ImGui::EndMenu();
      }
      if (ImGui::MenuItem("Compare with another run...", nullptr, false, s.activeDocument() != nullptr))
        s.dialogs.compare.opening = true;
      if (ImGui::MenuItem("Export...", "Ctrl+E", false, s.activeDocument() != nullptr)) s.dialogs.exportTo.show(s.selection.current().line);
      if (ImGui::MenuItem("Close", "Ctrl+W", false, s.activeDocument() != nullptr)) s.closeActive();
      if (ImGui::MenuItem("Quit", "Ctrl+Q")) s.chrome.quit = true;
      closeMenuOnEscape(s);
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
      if (ImGui::MenuItem("Isometric", "I")) setView(s, vis::ViewDirection::Iso);
      if (ImGui::MenuItem("Top", "T")) setView(s, vis::ViewDirection::Top);
      if (ImGui::MenuItem("Front", "F")) setView(s, vis::ViewDirection::Front);
      if (ImGui::MenuItem("Left", "L")) setView(s, vis::ViewDirection::Left);
      if (ImGui::MenuItem("Reset", "R")) setView(s, s.settings.view);
      ImGui::MenuItem("Rectangle zoom", "Z", &s.pointer.rectangleZoom);
      ImGui::MenuItem("Warnings", "W", &s.dialogs.warningsOpen);
      ImGui::Separator();
      drawLookMenus(s);
      closeMenuOnEscape(s);
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Colour by")) {
      const Document* shown = s.activeDocument();
      for (const QuantityInfo& q : quantityInfos())
        if (q.needsJoints && !(shown && shown->samples && quantityAvailable(q.quantity, *shown->samples))) continue;
        else if (ImGui::MenuItem(q.label, nullptr, s.settings.quantity == q.quantity)) {
          s.settings.quantity = q.quantity;
          s.settings.channel.clear();  // a channel of the dump chosen in the Colour panel gives way
          s.persistent.quantity = q.name;
          if (s.settings.rangeMode == 2) s.settings.rangeMode = 0;  // a fixed range was the other quantity's
          s.startRecolour();
        }
      closeMenuOnEscape(s);
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Tools")) {
      if (ImGui::MenuItem("Simulate again", "S")) simulate = true;
      if (ImGui::MenuItem("Machine...", "M")) s.openMachineWindow();
      if (ImGui::MenuItem("Locate...", "Ctrl+L")) locate = true;
      if (ImGui::MenuItem("Optimise region...", "P")) s.dialogs.optimise.opening = true;
      ImGui::MenuItem("Worst regions", "Ctrl+R", &s.dialogs.regionsOpen);
      ImGui::MenuItem("Select region box", "B", &s.pointer.boxSelect);
      if (ImGui::MenuItem("Measure distance", "D", s.pointer.measuring)) toggleMeasure(s);
      closeMenuOnEscape(s);
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
      if (ImGui::MenuItem("Keys and version", "H", s.dialogs.helpOpen)) s.dialogs.helpOpen = !s.dialogs.helpOpen;
      closeMenuOnEscape(s);
      ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
  }
  ImGui::SetNextWindowPos(ImVec2(0, toolbarTop));
  ImGui::SetNextWindowSize(ImVec2(width, ImGui::GetFrameHeightWithSpacing() + 10));
  ImGui::Begin("##toolbar", nullptr, kPanel | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
  const bool openButton = toolButton("Open", "Open a G-code program or a Biip dump (O, Ctrl+O)");
  const bool openKey = shortcut(s, 'O');
  if (openButton || openKey || shortcut(s, 'O', true)) {
    s.dialogs.openedByKey = openKey && !openButton ? 'O' : 0;
    s.dialogs.open.open();
  }
  if (toolButton("Simulate", "Simulate the active program again (S)") || shortcut(s, 'S')) simulate = true;
  if (toolButton("Machine", "The machine simulations use: limits, servo, load, save (M)") || shortcut(s, 'M'))
    s.openMachineWindow();
  if (toolButton("Iso", "Isometric view (I)") || shortcut(s, 'I')) setView(s, vis::ViewDirection::Iso);
  if (toolButton("Top", "Top view (T)") || shortcut(s, 'T')) setView(s, vis::ViewDirection::Top);
  if (toolButton("Front", "Front view (F)") || shortcut(s, 'F')) setView(s, vis::ViewDirection::Front);
  if (toolButton("Left", "Left view (L)") || shortcut(s, 'L')) setView(s, vis::ViewDirection::Left);
  if (toolButton("Reset", "Reset the camera (R)") || shortcut(s, 'R')) setView(s, s.settings.view);
  if (modeButton("Zoom box", "Drag a rectangle to zoom to (Z)", s.pointer.rectangleZoom) || shortcut(s, 'Z'))
    s.pointer.rectangleZoom = !s.pointer.rectangleZoom;
  if (modeButton("Select box", "Drag a rectangle over the surface: its lines go to the Optimise dialog (B)",
                 s.pointer.boxSelect) ||
      shortcut(s, 'B'))
    s.pointer.boxSelect = !s.pointer.boxSelect;
  if (modeButton("Measure", "Click two points of the surface: their distance (D)", s.pointer.measuring) ||
      shortcut(s, 'D'))
    toggleMeasure(s);
  if (toolButton("Locate", "Locate a sample or a G-code line (Ctrl+L)") || shortcut(s, 'L', true)) locate = true;
  if (toolButton("Optimise", "Re-optimise a region and compare the maps (P)") || shortcut(s, 'P')) s.dialogs.optimise.opening = true;
  ImGui::End();
  // One rectangle tool at a time: the one switched on last.
  if (s.pointer.boxSelect && s.pointer.rectangleZoom) {
    if (boxSelectWasOn) s.pointer.boxSelect = false;
    else s.pointer.rectangleZoom = false;
  }
  if (shortcut(s, 'Q', true)) s.chrome.quit = true;
  if (shortcut(s, 'E', true) && s.activeDocument()) s.dialogs.exportTo.show(s.selection.current().line);
  if (shortcut(s, 'W', true) && s.activeDocument()) s.closeActive();
  if (shortcut(s, 'F', true) && s.activeDocument()) s.dialogs.gcodeSearch.focus = true;
  if (shortcut(s, 'R', true)) s.dialogs.regionsOpen = !s.dialogs.regionsOpen;
  if (shortcut(s, 'H')) s.dialogs.helpOpen = !s.dialogs.helpOpen;
  if (shortcut(s, 'W')) s.dialogs.warningsOpen = !s.dialogs.warningsOpen;
  if (s.pointer.measuring && s.takeEscape()) toggleMeasure(s);
  if (locate) s.dialogs.locate.show(s.selection);
  if (simulate) s.simulateAgain();
}

void drawNavigationTree(Inspector::State& s, float x, float y, float w, float h) {
  beginPanel("Navigation", x, y, w, h);
  for (std::size_t i = 0; i < s.documents.size(); ++i) {
    Document& doc = *s.documents[i];
    ImGui::PushID(static_cast<int>(i));
    // A click on the name shows the document; the arrow (or a double click) opens and closes it.
    const ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_OpenOnArrow |
                                     ImGuiTreeNodeFlags_OpenOnDoubleClick | (i == s.active ? ImGuiTreeNodeFlags_Selected : 0);
    const bool open = ImGui::TreeNodeEx(doc.name.c_str(), flags);
    if (ImGui::IsItemClicked() && i != s.active) {
      s.activate(i);
      s.status = "showing " + s.documents[i]->name;  // not what the document shown before said last
    }
    if (open) {
      bool changed = false;
      if (doc.program) {
        changed |= ImGui::Checkbox("##program", &doc.showToolpath);
        ImGui::SameLine();
        ImGui::Text("Programmed trajectory (%zu moves)", doc.program->moves.size());
      }
      if (doc.samples) {
        changed |= ImGui::Checkbox("##surface", &doc.showSurface);
        ImGui::SameLine();
        ImGui::Text("Interpolation trajectory (%zu samples)", doc.samples->size());
        ImGui::Indent();
        changed |= ImGui::Checkbox("points", &doc.showPoints);
        ImGui::Unindent();
      }
      if (changed && doc.scene) {
        doc.scene->setVisibility(doc.showSurface, doc.showToolpath, doc.showPoints, doc.showToolAxes);
        s.view.invalidate();
      }
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  ImGui::End();
}

void drawStatusBar(Inspector::State& s, float y, float width) {
  ImGui::SetNextWindowPos(ImVec2(0, y));
  ImGui::SetNextWindowSize(ImVec2(width, ImGui::GetIO().DisplaySize.y - y));
  ImGui::Begin("##status", nullptr, kPanel | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar);
  if (s.job.running()) {
    ImGui::ProgressBar(static_cast<float>(s.job.progress()), ImVec2(width * 0.3f, 0), s.job.label().c_str());
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel");
    noteControl(s, "job.cancel");
    if (cancel) s.job.cancel();
    ImGui::SameLine();
    if (const std::string stage = s.job.stage(); !stage.empty()) {
      ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.45f, 1.0f), "%s", fittedToWidth(stage, ImGui::GetContentRegionAvail().x * 0.6f).c_str());
      ImGui::SameLine();
    }
  }
  // The open documents' warnings, however many messages came after them.
  std::size_t warnings = 0;
  for (const auto& doc : s.documents) warnings += doc->warnings.size();
  if (warnings > 0) {
    const std::string label = std::to_string(warnings) + (warnings == 1 ? " warning (W)" : " warnings (W)");
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    const bool open = ImGui::SmallButton(label.c_str());
    ImGui::PopStyleColor();
    noteControl(s, "status.warnings");
    if (open) s.dialogs.warningsOpen = true;
    ImGui::SameLine();
  }
  // A status wider than the bar is cut at its end, and shown whole under the pointer.
  s.chrome.statusShown = fittedToWidth(s.status, ImGui::GetContentRegionAvail().x);
  ImGui::TextUnformatted(s.chrome.statusShown.c_str());
  if (s.chrome.statusShown != s.status && ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(std::min(width * 0.8f, ImGui::GetFontSize() * 50));
    ImGui::TextUnformatted(s.status.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
  ImGui::End();
}

namespace {

// Not modal: the panes follow each request while it is open. It starts at the selection.
void drawLocateWindow(Inspector::State& s) {
  app_model::LocateWindow& w = s.dialogs.locate;
  if (w.opening) ImGui::SetNextWindowFocus();
  w.opening = false;
  if (!w.open) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->Size.x * 0.5f, viewport->Size.y * 0.4f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  if (ImGui::Begin("Locate", &w.open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
    const Document* doc = s.activeDocument();
    const std::size_t lines = doc && doc->text ? doc->text->count() : 0;
    // The fields take what is typed as it is typed (a click on Go then goes there); Enter goes too.
    const int enter = ImGui::GetKeyIndex(ImGuiKey_Enter);
    const auto enterPressed = [enter] { return ImGui::IsItemDeactivatedAfterEdit() && ImGui::IsKeyPressed(enter); };
    if (doc && doc->samples && doc->samples->thinning > 1)
      ImGui::TextDisabled("1 sample in %zu of the dump: sample i is its record %zu x i", doc->samples->thinning,
                          doc->samples->thinning);
    ImGui::InputInt("sample", &w.sample, 1, 100);
    bool goSample = enterPressed();
    noteControl(s, "locate.sample");
    ImGui::SameLine();
    goSample |= ImGui::Button("Go to sample");
    noteControl(s, "locate.goSample");
    ImGui::InputInt("G-code line", &w.line, 1, 100);
    bool goLine = enterPressed();
    ImGui::SameLine();
    goLine |= ImGui::Button("Go to line");
    // The point in the window's length unit; the model keeps mm.
    const DisplayUnits units = s.units();
    double shown[3] = {units.length(w.point.x()), units.length(w.point.y()), units.length(w.point.z())};
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 18);
    const std::string pointLabel = std::string("X, Y, Z [") + units.lengthUnit() + "]";
    const bool pointEdited = ImGui::InputScalarN(pointLabel.c_str(), ImGuiDataType_Double, shown, 3, nullptr, nullptr,
                                                 units.inch ? "%.5f" : "%.4f");
    bool goPoint = enterPressed();
    noteControl(s, "locate.point");
    if (pointEdited)
      for (int a = 0; a < 3; ++a) w.point[a] = units.inch ? shown[a] * kMmPerInch : shown[a];
    ImGui::SameLine();
    goPoint |= ImGui::Button("Go to point");
    noteControl(s, "locate.goPoint");
    if (goSample) w.goToSample(s.selection);
    if (goLine) w.goToLine(s.selection, lines);
    if (goPoint) w.goToPoint(s.selection);
    if (!w.message.empty()) ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", w.message.c_str());
    if (ImGui::Button("Close")) w.open = false;
    // Esc closes it, as every other window, when it has the keyboard.
    if (ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) && s.takeEscape()) w.open = false;
  }
  ImGui::End();
}

}  // namespace

void drawDialogs(Inspector::State& s) {
  drawOpenDialog(s);
  drawLocateWindow(s);
  drawWarningsWindow(s);
  drawRegionsWindow(s);
}

}  // namespace isurface::panels
