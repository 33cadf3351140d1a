// The machine window: the machine programs are simulated with, its limits and servo edited in
// the units of a control's panel, loaded from and saved to a description, and applied by
// simulating the active program again.
#include <imgui.h>

#include <cstdio>
#include <optional>

#include "inspector_state.h"
#include "isurface/app_model/machine_edits.h"
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
  Machine& m = s.machineEdit;
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

// The edited machine as parseMachine() takes it: its checks are the ones a file gets.
std::optional<Machine> checked(Inspector::State& s) {
  try {
    return parseMachine(machineDescriptionJson(s.machineEdit), "machine window");
  } catch (const InputError& e) {
    s.machineMessage = e.what();
    return std::nullopt;
  }
}

void drawLoadAndSave(Inspector::State& s) {
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 24);
  const bool enter = ImGui::InputTextWithHint("##load", "machine description to load (.json)", s.machineLoadPath,
                                              sizeof s.machineLoadPath, ImGuiInputTextFlags_EnterReturnsTrue);
  noteControl(s, "machine.loadPath");
  ImGui::SameLine();
  const bool load = ImGui::Button("Load description");
  noteControl(s, "machine.load");
  if ((load || enter) && s.machineLoadPath[0]) {
    try {
      s.machineEdit = loadMachine(s.machineLoadPath);
      s.machineMessage = std::string("loaded ") + s.machineLoadPath + ": simulate to use it";
    } catch (const InputError& e) {
      s.machineMessage = e.what();
    }
  }
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 24);
  ImGui::InputTextWithHint("##save", "file to save the description to (.json)", s.machineSavePath,
                           sizeof s.machineSavePath);
  noteControl(s, "machine.savePath");
  ImGui::SameLine();
  const bool save = ImGui::Button("Save description");
  noteControl(s, "machine.save");
  if (save && s.machineSavePath[0]) {
    if (const std::optional<Machine> m = checked(s)) {
      const Machine named = app_model::namedAfterEdits(*m, s.machine);
      s.machineEdit.name = named.name;
      s.save(s.machineSavePath, machineDescriptionJson(named), "machine description");
      s.machineMessage.clear();
    }
  }
}

}  // namespace

void drawMachineWindow(Inspector::State& s) {
  if (!s.machineOpen) return;
  if (s.machineAppearing) {
    s.machineEdit = s.machine;
    s.machineMessage.clear();
    ImGui::SetNextWindowFocus();
  }
  s.machineAppearing = false;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->Size.x * 0.5f, viewport->Size.y * 0.45f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(1.0f);  // the map behind would make the figures hard to read
  if (ImGui::Begin("Machine", &s.machineOpen, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
    ImGui::Text("Simulations use: %s (%s)", s.machine.name.c_str(), s.machineSource.c_str());
    if (const Document* doc = s.activeDocument(); doc && doc->samples)
      ImGui::TextDisabled("The map of %s was made with: %s", doc->name.c_str(),
                          doc->machineKnown ? doc->machine.name.c_str() : "a machine its dump does not name");
    ImGui::Separator();
    char name[256];
    std::snprintf(name, sizeof name, "%s", s.machineEdit.name.c_str());
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 40);
    if (ImGui::InputText("name", name, sizeof name)) s.machineEdit.name = name;
    editScaled("interpolation cycle [ms]", s.machineEdit.cycle, 1000.0, "%.3f");
    ImGui::SameLine();
    editScaled("rapid [mm/min]", s.machineEdit.rapidVelocity, kSecondsPerMinute, "%.0f");
    ImGui::SameLine();
    editScaled("chord tolerance [mm]", s.machineEdit.chordTolerance, 1.0, "%.4f");
    drawAxisTable(s);
    const bool simulatable = s.activeDocument() && !s.activeDocument()->programPath.empty();
    const bool simulate = ImGui::Button("Simulate with this machine");
    noteControl(s, "machine.simulate");
    if (simulate) {
      if (const std::optional<Machine> m = checked(s)) {
        s.machine = app_model::namedAfterEdits(*m, s.machine);
        s.machineEdit.name = s.machine.name;
        s.machineSource = "edited";
        s.machineMessage.clear();
        if (simulatable) s.simulateAgain();
        else s.machineMessage = "used for the next program opened: no program is open";
      }
    }
    ImGui::SameLine();
    if (ImGui::Button("Revert")) {
      s.machineEdit = s.machine;
      s.machineMessage.clear();
    }
    ImGui::SameLine();
    if (ImGui::Button("Default machine")) s.machineEdit = defaultMachine();
    ImGui::SameLine();
    const bool close = ImGui::Button("Close");
    noteControl(s, "machine.close");
    // Esc closes the window when it has the keyboard and no field is being edited.
    if (close || (ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) && !ImGui::GetIO().WantTextInput &&
                  s.takeEscape()))
      s.machineOpen = false;
    ImGui::Separator();
    drawLoadAndSave(s);
    if (!s.machineMessage.empty()) ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", s.machineMessage.c_str());
  }
  ImGui::End();
}

}  // namespace isurface::panels
