// The G-code pane and the data bar: virtualised lists (only visible rows are drawn, so millions
// of lines scroll smoothly) that highlight the selection and scroll to it when it changes.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "inspector_state.h"

namespace isurface::panels {

namespace {

constexpr ImGuiWindowFlags kPanel = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;

// Scrolls a list of fixed-height rows so that `row` is in the middle, once per selection change.
void scrollToRow(std::size_t row, float rowHeight) {
  const float target = row * rowHeight - ImGui::GetWindowHeight() * 0.5f;
  ImGui::SetScrollY(std::max(0.0f, target));
}

}  // namespace

void drawGcodePane(Inspector::State& s, float x, float y, float w, float h) {
  beginPanel("G-code", x, y, w, h);
  Document* doc = s.activeDocument();
  if (!doc || !doc->text) {
    ImGui::TextDisabled("no program");
    ImGui::End();
    return;
  }
  const app_model::Selection& sel = s.selection.current();
  ImGui::BeginChild("lines", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
  const float rowHeight = ImGui::GetTextLineHeightWithSpacing();
  if (sel.line && sel.generation != s.gcodeScrolledFor) {
    scrollToRow(*sel.line - 1, rowHeight);
    s.gcodeScrolledFor = sel.generation;
  }
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(doc->text->count()), rowHeight);
  while (clipper.Step()) {
    for (int row = clipper.DisplayStart; row < clipper.DisplayEnd; ++row) {
      const std::uint32_t line = static_cast<std::uint32_t>(row + 1);
      const std::string_view text = doc->text->line(line);
      char number[16];
      std::snprintf(number, sizeof number, "%7u  ", line);
      const bool selected = sel.line && *sel.line == line;
      ImGui::PushID(row);
      if (ImGui::Selectable(number, selected, ImGuiSelectableFlags_AllowDoubleClick)) {
        if (!s.selection.selectLine(line)) s.status = "line " + std::to_string(line) + " produced no samples";
      }
      ImGui::SameLine(0, 0);
      ImGui::TextUnformatted(text.data(), text.data() + text.size());
      ImGui::PopID();
    }
  }
  ImGui::EndChild();
  ImGui::End();
}

void drawDataBar(Inspector::State& s, float x, float y, float w, float h) {
  beginPanel("Data", x, y, w, h);
  Document* doc = s.activeDocument();
  if (!doc || !doc->samples || doc->curves.size() < 3) {
    ImGui::TextDisabled("no samples");
    ImGui::End();
    return;
  }
  const Trajectory& t = *doc->samples;
  const bool feedback = t.hasFeedback();
  const int columns = feedback ? 12 : 9;
  const app_model::Selection& sel = s.selection.current();
  const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_ScrollX | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_BordersV | ImGuiTableFlags_SizingFixedFit;
  if (ImGui::BeginTable("samples", columns, flags)) {
    ImGui::TableSetupScrollFreeze(1, 1);
    for (const char* name : {"sample", "t [s]", "line", "X [mm]", "Y [mm]", "Z [mm]", "v [mm/min]", "a [mm/s2]",
                             "j [mm/s3]"})
      ImGui::TableSetupColumn(name);
    if (feedback)
      for (const char* name : {"fb X", "fb Y", "fb Z"}) ImGui::TableSetupColumn(name);
    ImGui::TableHeadersRow();
    const float rowHeight = ImGui::GetTextLineHeightWithSpacing();
    if (sel.sample && sel.generation != s.dataScrolledFor) {
      scrollToRow(*sel.sample, rowHeight);
      s.dataScrolledFor = sel.generation;
    }
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(t.size()), rowHeight);
    while (clipper.Step()) {
      for (int row = clipper.DisplayStart; row < clipper.DisplayEnd; ++row) {
        const std::size_t i = static_cast<std::size_t>(row);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        char index[24];
        std::snprintf(index, sizeof index, "%zu", i);
        if (ImGui::Selectable(index, sel.sample && *sel.sample == i, ImGuiSelectableFlags_SpanAllColumns))
          s.selection.selectSample(i);
        ImGui::TableNextColumn();
        ImGui::Text("%.3f", t.time[i]);
        ImGui::TableNextColumn();
        ImGui::Text("%u", t.line[i]);
        for (double v : {t.x[i], t.y[i], t.z[i]}) {
          ImGui::TableNextColumn();
          ImGui::Text("%.4f", v);
        }
        for (int k = 0; k < 3; ++k) {
          ImGui::TableNextColumn();
          ImGui::Text("%.5g", doc->curves[k].values.value(i));
        }
        if (feedback)
          for (double v : {t.fbX[i], t.fbY[i], t.fbZ[i]}) {
            ImGui::TableNextColumn();
            ImGui::Text("%.4f", v);
          }
      }
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace isurface::panels
