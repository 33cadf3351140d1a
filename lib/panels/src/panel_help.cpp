// The Help window: every key of the window and the version.
#include <imgui.h>

#include "inspector_state.h"

namespace isurface::panels {

namespace {

struct KeyHelp {
  const char* key;
  const char* does;
};

constexpr KeyHelp kKeys[] = {
    {"O / Ctrl+O", "open a G-code program, a Biip dump or both"},
    {"Ctrl+W", "close the active file"},
    {"S", "simulate the active program again"},
    {"M", "the machine: limits, servo, load, save, simulate with it"},
    {"I / T / F / L", "isometric, top, front, left view"},
    {"R", "reset the camera"},
    {"Z", "zoom to a rectangle dragged over the view"},
    {"B", "drag a box over the view to choose the region to optimise"},
    {"D", "measure: the next two clicks on the surface are the ends of a distance"},
    {"Ctrl+L", "locate a sample, a G-code line or the sample nearest a point"},
    {"Ctrl+F", "find text in the G-code (Enter: next, Shift+Enter: previous)"},
    {"Ctrl+R", "the worst regions of the map, most severe first: a click goes to one"},
    {"W", "every warning of the open files; a click goes to the line it names"},
    {"P", "re-optimise a region and compare the maps"},
    {"Ctrl+E", "export the view (PNG), the map's figures (JSON) or samples (CSV)"},
    {"Up / Down, PgUp / PgDn, Home / End", "step through the rows of the G-code pane or the data bar"},
    {"Esc", "close the dialog or window it is pressed in, else cancel the running job or end measuring"},
    {"H", "this window"},
    {"Ctrl+Q", "quit"},
    {"mouse", "left drag turns, right drag zooms, middle drag pans, wheel zooms, click picks; rest to see the value"},
};

}  // namespace

void drawHelpWindow(Inspector::State& s) {
  if (!s.dialogs.helpOpen) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->Size.x * 0.5f, viewport->Size.y * 0.45f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(1.0f);
  if (ImGui::Begin("Help", &s.dialogs.helpOpen, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
    ImGui::Text("iSurface %s", ISURFACE_VERSION);
    ImGui::TextDisabled("Quality maps of NC interpolation: speed, acceleration, jerk, inconsistency, deviation");
    ImGui::Separator();
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
      for (const KeyHelp& k : kKeys) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(k.key);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(k.does);
      }
      ImGui::EndTable();
    }
    // Esc closes it as it closes the other windows, when it has the keyboard.
    if (ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) && escapeCloses(s)) s.dialogs.helpOpen = false;
  }
  ImGui::End();
}

}  // namespace isurface::panels
