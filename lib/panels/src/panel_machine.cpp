// The machine window: the machine programs are simulated with, its limits and servo edited in
// the units of a control's panel, loaded from and saved to a description, and applied by
// simulating the active program again.
#include <imgui.h>

#include <algorithm>
#include <optional>

#include "inspector_state.h"
#include "text_input.h"
#include "isurface/base/units.h"

namespace isurface::panels {

namespace {

// A value edited in display units (`scale` display units per stored unit).
bool editScaled(const char* label, double& stored, double scale, const char* format) {
  double shown = stored * scale;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7);
  if (!ImGui::InputDouble(label, &shown, 0, 0, format)) return false;
  stored = shown / scale;
  return true;
}

void drawAxisTable(Inspector::State& s) {
  Machine& m = s.dialogs.machine.edit;
  static const char* const kRows[] = {"max velocity [mm/min]", "max acceleration [mm/s^2]", "max jerk [mm/s^3] (0: none)",
                                      "position gain [1/s]",   "velocity feed-forward [0..1]",
                                      "velocity loop lag [ms]"};
  if (!ImGui::BeginTable("axes", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) return;
  ImGui::TableSetupColumn("axis limit");
  for (const char* axis : {"X", "Y", "Z"}) ImGui::TableSetupColumn(axis);
  ImGui::TableHeadersRow();
  for (int row = 0; row < 6; ++row) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(kRows[row]);
    for (int axis = 0; axis < 3; ++axis) {
      ImGui::TableNextColumn();
      ImGui::PushID(row * 3 + axis);
      AxisLimits& a = m.axes[static_cast<std::size_t>(axis)];
      switch (row) {
        case 0:
          editScaled("##v", a.maxVelocity, kSecondsPerMinute, "%.0f");
          noteControl(s, std::string("machine.velocity.") + "xyz"[axis]);
          break;
        case 1: editScaled("##a", a.maxAcceleration, 1.0, "%.0f"); break;
        case 2: editScaled("##j", a.maxJerk, 1.0, "%.0f"); break;
        case 3: editScaled("##kp", a.positionGain, 1.0, "%.1f"); break;
        case 4: editScaled("##ff", a.velocityFeedForward, 1.0, "%.3f"); break;
        default: editScaled("##tv", a.velocityLoopTimeConstant, 1000.0, "%.2f"); break;
      }
      ImGui::PopID();
    }
  }
  ImGui::EndTable();
}

void drawLoadAndSave(Inspector::State& s) {
  app_model::MachineWindow& w = s.dialogs.machine;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 24);
  const bool enter =
      inputTextWithHint("##load", "machine description to load (.json)", w.loadPath, ImGuiInputTextFlags_EnterReturnsTrue);
  noteControl(s, "machine.loadPath");
  ImGui::SameLine();
  const bool load = ImGui::Button("Load description");
  noteControl(s, "machine.load");
  if (load || enter) w.load();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 24);
  inputTextWithHint("##save", "file to save the description to (.json)", w.savePath);
  noteControl(s, "machine.savePath");
  ImGui::SameLine();
  const bool save = ImGui::Button("Save description");
  noteControl(s, "machine.save");
  if (save && !w.savePath.empty()) {
    if (const std::optional<Machine> named = w.checkedEdit()) {
      w.edit.name = named->name;
      s.save(w.savePath, machineDescriptionJson(*named), "machine description");
      w.message.clear();
    }
  }
}

}  // namespace

void drawMachineWindow(Inspector::State& s) {
  app_model::MachineWindow& w = s.dialogs.machine;
  if (!w.open) return;
  if (w.appearing) ImGui::SetNextWindowFocus();
  w.appearing = false;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->Size.x * 0.5f, viewport->Size.y * 0.45f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(1.0f);  // the map behind would make the figures hard to read
  // Never larger than the application's window: on a small one it scrolls instead of reaching
  // past its edges.
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), viewport->WorkSize);
  const ImGuiWindowFlags flags =
      ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_HorizontalScrollbar;
  if (ImGui::Begin("Machine", &w.open, flags)) {
    // Kept inside the application's window when that is made smaller.
    const ImVec2 size = ImGui::GetWindowSize();
    ImVec2 at = ImGui::GetWindowPos();
    const ImVec2 inside(std::clamp(at.x, viewport->WorkPos.x, std::max(viewport->WorkPos.x, viewport->WorkPos.x + viewport->WorkSize.x - size.x)),
                        std::clamp(at.y, viewport->WorkPos.y, std::max(viewport->WorkPos.y, viewport->WorkPos.y + viewport->WorkSize.y - size.y)));
    if (inside.x != at.x || inside.y != at.y) ImGui::SetWindowPos(at = inside);
    s.chrome.controls["machine"] = {at.x, at.y, at.x + size.x, at.y + size.y};
    // Long names (an edited machine lists its edits) wrap rather than widen the window.
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + ImGui::GetFontSize() * 44);
    // Where it comes from when that is a file: an edited machine's name says so already.
    const bool fromFile = w.source != "edited" && w.source != "built-in default";
    ImGui::TextWrapped("Simulations use: %s%s%s%s", w.inUse.name.c_str(), fromFile ? " (" : "",
                       fromFile ? w.source.c_str() : "", fromFile ? ")" : "");
    // The line is there without a map too, so that nothing below moves when one comes.
    const Document* doc = s.activeDocument();
    if (doc && doc->samples)
      ImGui::TextDisabled("The map of %s was made with: %s", doc->name.c_str(),
                          doc->machineKnown ? doc->machine.name.c_str() : "a machine its dump does not name");
    else ImGui::TextDisabled("No map is open.");
    ImGui::PopTextWrapPos();
    ImGui::Separator();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 40);
    inputText("name", w.edit.name);
    editScaled("interpolation cycle [ms]", w.edit.cycle, 1000.0, "%.3f");
    ImGui::SameLine();
    editScaled("rapid [mm/min]", w.edit.rapidVelocity, kSecondsPerMinute, "%.0f");
    ImGui::SameLine();
    editScaled("chord tolerance [mm]", w.edit.chordTolerance, 1.0, "%.4f");
    if (w.edit.control.planner == TrajectoryPlanner::Generic) {
      ImGui::Checkbox("smooth chords within the tolerance (the control's compressor)", &w.edit.control.chordSmoothing);
      noteControl(s, "machine.chordSmoothing");
    }
    drawAxisTable(s);
    const bool simulatable = s.activeDocument() && !s.activeDocument()->programPath.empty();
    const bool simulate = ImGui::Button("Simulate with this machine");
    noteControl(s, "machine.simulate");
    if (simulate && w.apply()) {
      // The program reopens with it next time (the default machine: nothing to remember); other
      // programs opened meanwhile do not take it.
      if (simulatable) s.persistent.rememberMachine(s.activeDocument()->programPath, machineDescriptionJson(w.inUse));
      w.appliedFor = simulatable ? s.activeDocument()->programPath : std::string();
      if (simulatable) s.simulateAgain();
      else w.message = "used for the next program opened: no program is open";
    }
    ImGui::SameLine();
    if (ImGui::Button("Revert")) w.revert();
    ImGui::SameLine();
    if (ImGui::Button("Default machine")) w.edit = defaultMachine();
    noteControl(s, "machine.default");
    ImGui::SameLine();
    const bool close = ImGui::Button("Close");
    noteControl(s, "machine.close");
    // Esc closes the window when it has the keyboard and no field is being edited.
    if (close || (ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) && !ImGui::GetIO().WantTextInput &&
                  s.takeEscape()))
      w.open = false;
    ImGui::Separator();
    drawLoadAndSave(s);
    if (!w.message.empty()) ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", w.message.c_str());
  }
  ImGui::End();
}

}  // namespace isurface::panels
