// The Open dialog: a file browser (folders first, sorted, filtered by kind, files told apart by
// their content) with a path that can be typed as well.
#include <imgui.h>

#include <filesystem>

#include "inspector_state.h"
#include "text_input.h"

namespace isurface::panels {

namespace {

const char* kindLabel(const std::optional<FileKind>& kind) {
  if (!kind) return "";
  switch (*kind) {
    case FileKind::Program: return "G-code";
    case FileKind::Dump: return "Biip dump";
    case FileKind::HalsamplerTrace: return "halsampler trace";
    case FileKind::CsvTrace: return "CSV trace";
  }
  return "";
}

// Opens the file the path names; a folder is entered instead.
void openTyped(Inspector::State& s) {
  const std::optional<std::string> file = s.dialogs.open.submit();
  if (!file) return;
  ImGui::CloseCurrentPopup();
  s.openFile(*file);
}

void drawEntries(Inspector::State& s) {
  app_model::OpenDialog& d = s.dialogs.open;
  ImGui::BeginChild("files", ImVec2(ImGui::GetFontSize() * 44, ImGui::GetFontSize() * 18), true);
  if (!d.listing.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", d.listing.error.c_str());
  std::optional<std::filesystem::path> enter;
  std::optional<std::string> open;
  for (const app_model::FolderEntry& e : d.listing.entries) {
    const std::filesystem::path full = std::filesystem::path(d.listing.folder) / e.name;
    const std::string label = e.folder ? e.name + "/" : e.name;
    const bool chosen = !e.folder && full.string() == d.path;
    if (ImGui::Selectable(label.c_str(), chosen, ImGuiSelectableFlags_AllowDoubleClick | ImGuiSelectableFlags_DontClosePopups)) {
      if (e.folder) enter = full;
      // A double click opens the file its first click chose: the second click of a double
      // click that entered a folder lands on whatever file the new listing puts there.
      else if (ImGui::IsMouseDoubleClicked(0) && chosen) open = full.string();
      else d.path = full.string();
    }
    noteControl(s, "open.entry:" + label);
    if (!e.folder) {
      ImGui::SameLine(ImGui::GetFontSize() * 30);
      ImGui::TextDisabled("%s", kindLabel(e.kind));
    }
  }
  if (d.listing.cut) ImGui::TextDisabled("(more entries not listed)");
  ImGui::EndChild();
  if (enter) d.enter(enter->string());
  if (open) {
    d.path = *open;
    openTyped(s);
  }
}

}  // namespace

void drawOpenDialog(Inspector::State& s) {
  app_model::OpenDialog& d = s.dialogs.open;
  if (d.opening) ImGui::OpenPopup("Open file");
  d.opening = false;
  if (!beginDialog("Open file")) return;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 44);
  // Typing goes to the path at once, without a click in it first, replacing a path left from
  // before.
  if (ImGui::IsWindowAppearing()) {
    ImGui::SetKeyboardFocusHere();
    startTypeAhead(s.dialogs.openTyping, s.dialogs.openedByKey);
  }
  const bool enter = typeAheadField("##path", "a file or a folder", d.path, ImGuiInputTextFlags_EnterReturnsTrue,
                                    s.dialogs.openTyping);
  noteControl(s, "open.path");
  if (ImGui::Button("Up")) d.up();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 16);
  if (ImGui::BeginCombo("##filter", app_model::fileFilterName(d.filter))) {
    for (int f = 0; f <= static_cast<int>(app_model::FileFilter::All); ++f) {
      const auto filter = static_cast<app_model::FileFilter>(f);
      if (ImGui::Selectable(app_model::fileFilterName(filter), filter == d.filter)) d.filter = filter;
    }
    ImGui::EndCombo();
  }
  d.relist(d.listing.folder);
  ImGui::SameLine();
  ImGui::TextDisabled("%s", d.listing.folder.c_str());
  drawEntries(s);
  const bool open = ImGui::Button("Open");
  noteControl(s, "open.open");
  if (open || enter) openTyped(s);
  ImGui::SameLine();
  if (ImGui::Button("Close") || escapeCloses(s)) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace isurface::panels
