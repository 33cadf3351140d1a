// The Open dialog: a file browser (folders first, sorted, filtered by kind, files told apart by
// their content) with a path that can be typed as well.
#include <imgui.h>

#include <cstdio>
#include <filesystem>

#include "inspector_state.h"

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

// Lists a folder again only when the folder or the filter changed (or when asked).
void relist(Inspector::State& s, const std::string& folder, bool force = false) {
  if (!force && s.browse.folder == folder && s.browseFilterListed == s.browseFilter) return;
  s.browse = app_model::listFolder(folder, static_cast<app_model::FileFilter>(s.browseFilter));
  s.browseFilterListed = s.browseFilter;
}

void enterFolder(Inspector::State& s, const std::filesystem::path& folder) {
  relist(s, folder.string());
  std::snprintf(s.openPath, sizeof s.openPath, "%s/", s.browse.folder.c_str());
}

void openTyped(Inspector::State& s) {
  std::error_code error;
  if (std::filesystem::is_directory(s.openPath, error)) return enterFolder(s, s.openPath);
  const std::string path = s.openPath;
  ImGui::CloseCurrentPopup();
  s.openFile(path);
}

void drawEntries(Inspector::State& s) {
  ImGui::BeginChild("files", ImVec2(ImGui::GetFontSize() * 44, ImGui::GetFontSize() * 18), true);
  if (!s.browse.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", s.browse.error.c_str());
  std::optional<std::filesystem::path> enter;
  std::optional<std::string> open;
  for (const app_model::FolderEntry& e : s.browse.entries) {
    const std::filesystem::path full = std::filesystem::path(s.browse.folder) / e.name;
    const std::string label = e.folder ? e.name + "/" : e.name;
    const bool chosen = !e.folder && full.string() == s.openPath;
    if (ImGui::Selectable(label.c_str(), chosen, ImGuiSelectableFlags_AllowDoubleClick | ImGuiSelectableFlags_DontClosePopups)) {
      if (e.folder) enter = full;
      // A double click opens the file its first click chose: the second click of a double
      // click that entered a folder lands on whatever file the new listing puts there.
      else if (ImGui::IsMouseDoubleClicked(0) && chosen) open = full.string();
      else std::snprintf(s.openPath, sizeof s.openPath, "%s", full.string().c_str());
    }
    noteControl(s, "open.entry:" + label);
    if (!e.folder) {
      ImGui::SameLine(ImGui::GetFontSize() * 30);
      ImGui::TextDisabled("%s", kindLabel(e.kind));
    }
  }
  if (s.browse.cut) ImGui::TextDisabled("(more entries not listed)");
  ImGui::EndChild();
  if (enter) enterFolder(s, *enter);
  if (open) {
    std::snprintf(s.openPath, sizeof s.openPath, "%s", open->c_str());
    openTyped(s);
  }
}

}  // namespace

void drawOpenDialog(Inspector::State& s) {
  if (s.openDialog) {
    ImGui::OpenPopup("Open file");
    std::error_code error;
    const std::filesystem::path typed(s.openPath);
    const std::filesystem::path folder = typed.empty() ? std::filesystem::current_path(error)
                                         : std::filesystem::is_directory(typed, error) ? typed
                                                                                       : typed.parent_path();
    relist(s, folder.string(), true);
  }
  s.openDialog = false;
  if (!ImGui::BeginPopupModal("Open file", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 44);
  const bool enter = ImGui::InputTextWithHint("##path", "a file or a folder", s.openPath, sizeof s.openPath,
                                              ImGuiInputTextFlags_EnterReturnsTrue);
  noteControl(s, "open.path");
  if (ImGui::Button("Up")) enterFolder(s, std::filesystem::path(s.browse.folder).parent_path());
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 16);
  if (ImGui::BeginCombo("##filter", app_model::fileFilterName(static_cast<app_model::FileFilter>(s.browseFilter)))) {
    for (int f = 0; f <= static_cast<int>(app_model::FileFilter::All); ++f)
      if (ImGui::Selectable(app_model::fileFilterName(static_cast<app_model::FileFilter>(f)), f == s.browseFilter))
        s.browseFilter = f;
    ImGui::EndCombo();
  }
  relist(s, s.browse.folder);
  ImGui::SameLine();
  ImGui::TextDisabled("%s", s.browse.folder.c_str());
  drawEntries(s);
  const bool open = ImGui::Button("Open");
  noteControl(s, "open.open");
  if ((open || enter) && s.openPath[0]) openTyped(s);
  ImGui::SameLine();
  if (ImGui::Button("Close") || escapeCloses(s)) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace isurface::panels
