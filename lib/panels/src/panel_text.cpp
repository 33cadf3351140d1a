// The G-code pane and the data bar: virtualised lists (only visible rows are drawn, so millions
// of lines scroll smoothly) that highlight the selection and scroll to it when it changes.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <optional>

#include "inspector_state.h"
#include "isurface/base/time_format.h"
#include "text_input.h"

namespace isurface::panels {

namespace {

// Brings `row` of a list of fixed-height rows into view, once per selection change: not at all
// when it is in view already (a row clicked stays under the pointer), by the least scroll when
// it is just out of view (stepping with the keys), else to the middle. `covered` is the height
// of frozen rows over the top of the list.
void scrollToRow(std::size_t row, float rowHeight, float covered = 0) {
  const float rowTop = row * rowHeight + covered, scroll = ImGui::GetScrollY();
  const float viewTop = scroll + covered, viewBottom = scroll + ImGui::GetWindowHeight();
  if (rowTop >= viewTop && rowTop + rowHeight <= viewBottom) return;
  const float page = viewBottom - viewTop;
  if (rowTop < viewTop && viewTop - rowTop <= page) ImGui::SetScrollY(std::max(0.0f, rowTop - covered));
  else if (rowTop > viewTop && rowTop + rowHeight - viewBottom <= page)
    ImGui::SetScrollY(rowTop + rowHeight - ImGui::GetWindowHeight());
  else ImGui::SetScrollY(std::max(0.0f, rowTop - covered - page * 0.5f));
}

// The row the keys step to while this pane has the keyboard: a row with the arrows, a page with
// Page Up / Page Down, the ends with Home / End.
std::optional<std::size_t> steppedRow(std::optional<std::size_t> current, std::size_t count, float rowHeight) {
  if (count == 0 || ImGui::GetIO().WantTextInput || !ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows))
    return std::nullopt;
  auto pressed = [](ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), true); };
  const long page = std::max(1L, static_cast<long>(ImGui::GetWindowHeight() / rowHeight) - 1);
  const long row = current ? static_cast<long>(*current) : -1;
  long next = row;
  if (pressed(ImGuiKey_DownArrow)) next = row + 1;
  else if (pressed(ImGuiKey_UpArrow)) next = row - 1;
  else if (pressed(ImGuiKey_PageDown)) next = row + page;
  else if (pressed(ImGuiKey_PageUp)) next = row - page;
  else if (pressed(ImGuiKey_Home)) next = 0;
  else if (pressed(ImGuiKey_End)) next = static_cast<long>(count) - 1;
  else return std::nullopt;
  return static_cast<std::size_t>(std::clamp(next, 0L, static_cast<long>(count) - 1));
}

// The search field over the lines: Enter (or Next) goes to the next line holding the text,
// Shift+Enter (or Previous) to the one before, from the selected line, round past the ends.
void drawSearchField(Inspector::State& s, const app_model::TextLines& text) {
  Dialogs::GcodeSearch& search = s.dialogs.gcodeSearch;
  if (search.focus) ImGui::SetKeyboardFocusHere(), startTypeAhead(search.typing, 0);
  search.focus = false;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 12);
  const bool enter =
      typeAheadField("##find", "find (Ctrl+F)", search.text, ImGuiInputTextFlags_EnterReturnsTrue, search.typing);
  noteControl(s, "gcode.find");
  const bool back = enter && ImGui::GetIO().KeyShift;
  if (enter) ImGui::SetKeyboardFocusHere(-1);  // the field keeps the keyboard for the next Enter
  ImGui::SameLine();
  const bool next = ImGui::SmallButton("Next");
  ImGui::SameLine();
  const bool previous = ImGui::SmallButton("Previous");
  if (!enter && !next && !previous) {
    if (!search.message.empty()) ImGui::SameLine(), ImGui::TextDisabled("%s", search.message.c_str());
    return;
  }
  const auto& line = s.selection.current().line;
  const auto found = app_model::findLine(text, search.text, line ? *line : 0, back || previous);
  search.message = found || search.text.empty() ? "" : "no line holds \"" + search.text + "\"";
  if (found) s.selection.selectLine(static_cast<std::uint32_t>(*found));
  if (!search.message.empty()) ImGui::SameLine(), ImGui::TextDisabled("%s", search.message.c_str());
}

// "  0.123" s on the line and "1:02.345" from the start, or blanks for a line without samples.
std::string lineTimeColumns(const app_model::LineTimes& times, std::uint32_t line) {
  const std::optional<app_model::LineTime> t = times.of(line);
  if (!t) return std::string(19, ' ');
  char out[48];
  std::snprintf(out, sizeof out, "%8.3f %10s", t->seconds, formatDuration(t->start).c_str());
  return out;
}

}  // namespace

void drawGcodePane(Inspector::State& s, float x, float y, float w, float h) {
  beginPanel("G-code", x, y, w, h);
  s.chrome.controls["gcode"] = {x, y, x + w, y + h};
  Document* doc = s.activeDocument();
  if (!doc || !doc->text) {
    ImGui::TextDisabled("no program");
    ImGui::End();
    return;
  }
  drawSearchField(s, *doc->text);
  const app_model::Selection& sel = s.selection.current();
  // Each line's time and when it starts, from the samples (s; blank where a line made none).
  const bool timed = doc->samples != nullptr;
  if (timed) ImGui::TextDisabled("%9s %8s %10s", "line", "time [s]", "starts at");
  // A pane of its own for each document: a new one starts at its top, and each keeps its scroll.
  ImGui::PushID(static_cast<int>(doc->serial));
  ImGui::BeginChild("lines", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
  const float rowHeight = ImGui::GetTextLineHeightWithSpacing();
  const std::size_t lines = doc->text->count();
  const std::optional<std::size_t> lineRow = sel.line ? std::optional<std::size_t>(*sel.line - 1) : std::nullopt;
  if (const std::optional<std::size_t> row = steppedRow(lineRow, lines, rowHeight))
    s.selection.selectLine(static_cast<std::uint32_t>(*row + 1));
  if (sel.line && sel.generation != s.follow.gcodeScrolledFor) {
    scrollToRow(*sel.line - 1, rowHeight);
    s.follow.gcodeScrolledFor = sel.generation;
  }
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(lines), rowHeight);
  s.follow.gcodeTopLine = static_cast<std::size_t>(ImGui::GetScrollY() / rowHeight) + 1;
  while (clipper.Step()) {
    for (int row = clipper.DisplayStart; row < clipper.DisplayEnd; ++row) {
      const std::uint32_t line = static_cast<std::uint32_t>(row + 1);
      const std::string_view text = doc->text->line(line);
      char number[16];
      std::snprintf(number, sizeof number, "%7u  ", line);
      const std::string label = timed ? number + lineTimeColumns(doc->lineTimes, line) + "  " : std::string(number);
      const bool selected = sel.line && *sel.line == line;
      ImGui::PushID(row);
      if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
        if (!s.selection.selectLine(line)) s.status = "line " + std::to_string(line) + " produced no samples";
      }
      ImGui::SameLine(0, 0);
      ImGui::TextUnformatted(text.data(), text.data() + text.size());
      ImGui::PopID();
    }
  }
  ImGui::EndChild();
  ImGui::PopID();
  ImGui::End();
}

void drawDataBar(Inspector::State& s, float x, float y, float w, float h) {
  beginPanel("Data", x, y, w, h);
  s.chrome.controls["data"] = {x, y, x + w, y + h};
  Document* doc = s.activeDocument();
  if (!doc || !doc->samples || doc->curves.size() < 3) {
    ImGui::TextDisabled("no samples");
    ImGui::End();
    return;
  }
  const Trajectory& t = *doc->samples;
  const bool feedback = t.hasFeedback();
  if (t.thinning > 1)
    ImGui::TextDisabled("1 sample in %zu of the dump: sample i here is its record %zu x i", t.thinning, t.thinning);
  if (!feedback && doc->feedbackAvailable()) {
    // Loaded when first asked for (12 bytes a sample): here, or by what shows it.
    if (ImGui::SmallButton("Load the feedback positions (fb X Y Z)")) s.loadFeedbackFirst({});
    noteControl(s, "data.feedback");
  }
  const int columns = feedback ? 12 : 9;
  const app_model::Selection& sel = s.selection.current();
  const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_ScrollX | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_BordersV | ImGuiTableFlags_SizingFixedFit;
  const DisplayUnits units = s.units();
  ImGui::PushID(static_cast<int>(doc->serial));  // each document's rows scroll on their own, a new one from its top
  if (ImGui::BeginTable("samples", columns, flags)) {
    ImGui::TableSetupScrollFreeze(1, 1);
    for (const char* name : {"sample", "t [s]", "line"}) ImGui::TableSetupColumn(name);
    const std::string length = std::string(" [") + units.lengthUnit() + "]";
    for (const char* axis : {"X", "Y", "Z"}) ImGui::TableSetupColumn((axis + length).c_str());
    ImGui::TableSetupColumn((std::string("v [") + units.feedUnit() + "]").c_str());
    ImGui::TableSetupColumn((std::string("a [") + units.accelerationUnit() + "]").c_str());
    ImGui::TableSetupColumn((std::string("j [") + units.jerkUnit() + "]").c_str());
    if (feedback)
      for (const char* axis : {"fb X", "fb Y", "fb Z"}) ImGui::TableSetupColumn((axis + length).c_str());
    ImGui::TableHeadersRow();
    const float rowHeight = ImGui::GetTextLineHeightWithSpacing();
    if (const std::optional<std::size_t> row = steppedRow(sel.sample, t.size(), rowHeight)) s.selection.selectSample(*row);
    if (sel.sample && sel.generation != s.follow.dataScrolledFor) {
      scrollToRow(*sel.sample, rowHeight, rowHeight);  // under the frozen header row
      s.follow.dataScrolledFor = sel.generation;
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
        ImGui::Text("%.3f", t.timeAt(i));
        ImGui::TableNextColumn();
        ImGui::Text("%u", t.line[i]);
        for (double v : {t.x[i], t.y[i], t.z[i]}) {
          ImGui::TableNextColumn();
          ImGui::Text("%.*f", units.lengthDecimals(), units.length(v));
        }
        for (int k = 0; k < 3; ++k) {
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(readableValue(units.length(doc->curves[k].values.value(i)), units.motionResolution(k)).c_str());
        }
        if (feedback)
          for (const double v : {t.feedback(i).x(), t.feedback(i).y(), t.feedback(i).z()}) {
            ImGui::TableNextColumn();
            ImGui::Text("%.*f", units.lengthDecimals(), units.length(v));
          }
      }
    }
    ImGui::EndTable();
  }
  ImGui::PopID();
  ImGui::End();
}

}  // namespace isurface::panels
