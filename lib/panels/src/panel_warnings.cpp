// The warnings window: every warning of every open document (units assumed, feeds capped, passes
// not joined, a dump not joined, words ignored), kept as long as the document is open, where the
// status line shows only the last message. A warning that names a line of the document's program
// goes there when clicked.
#include <imgui.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "inspector_state.h"

namespace isurface::panels {

std::optional<std::uint32_t> warningLine(const Document& doc, const std::string& warning) {
  const std::string& program = doc.programPath;
  if (program.empty() || warning.size() <= program.size() + 1 || warning.compare(0, program.size(), program) != 0 ||
      warning[program.size()] != ':')
    return std::nullopt;
  const char* digits = warning.c_str() + program.size() + 1;
  char* end = nullptr;
  const unsigned long line = std::strtoul(digits, &end, 10);
  if (end == digits || *end != ':' || line == 0 || line > 0xffffffffUL) return std::nullopt;
  return static_cast<std::uint32_t>(line);
}

bool beginListWindow(const char* name, bool* open, float heightShare) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->Size.x * 0.5f, viewport->Size.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(viewport->Size.x * 0.6f, viewport->Size.y * heightShare), ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(1.0f);  // the map behind would make the text hard to read
  return ImGui::Begin(name, open, ImGuiWindowFlags_NoCollapse);
}

void drawWarningsWindow(Inspector::State& s) {
  if (!s.dialogs.warningsOpen) return;
  if (beginListWindow("Warnings", &s.dialogs.warningsOpen, 0.4f)) {
    bool any = false;
    for (std::size_t d = 0; d < s.documents.size(); ++d) {
      const Document& doc = *s.documents[d];
      if (doc.warnings.empty()) continue;
      any = true;
      ImGui::TextDisabled("%s", doc.name.c_str());
      for (std::size_t k = 0; k < doc.warnings.size(); ++k) {
        const std::string& warning = doc.warnings[k];
        const std::optional<std::uint32_t> line = warningLine(doc, warning);
        ImGui::PushID(static_cast<int>(d * 4096 + k));
        // Wrapped to the window: a Selectable's own label would be cut at its edge.
        const float wrap = ImGui::GetContentRegionAvail().x;
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const float height = ImGui::CalcTextSize(warning.c_str(), nullptr, false, wrap).y;
        const bool chosen = ImGui::Selectable("##warning", false, line ? 0 : ImGuiSelectableFlags_Disabled, ImVec2(0, height));
        noteControl(s, "warnings.item:" + std::to_string(d) + ":" + std::to_string(k));
        ImGui::GetWindowDrawList()->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at,
                                            ImGui::GetColorU32(line ? ImGuiCol_Text : ImGuiCol_TextDisabled),
                                            warning.c_str(), nullptr, wrap);
        if (line && ImGui::IsItemHovered()) ImGui::SetTooltip("go to line %u of %s", *line, doc.name.c_str());
        if (chosen && line) {
          s.activate(d);
          if (!s.selection.selectLine(*line)) s.status = "line " + std::to_string(*line) + " produced no samples";
        }
        ImGui::PopID();
      }
    }
    if (!any) ImGui::TextDisabled("no warnings in the open documents");
    if (ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) && s.takeEscape()) s.dialogs.warningsOpen = false;
  }
  ImGui::End();
}

}  // namespace isurface::panels
