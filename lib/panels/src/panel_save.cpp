// Saving from the window: a file that exists is replaced only when the user says so.
#include <imgui.h>

#include <filesystem>

#include "inspector_state.h"
#include "isurface/io/atomic_file.h"

namespace isurface::panels {

namespace {

void writeNow(Inspector::State& s, const PendingSave& save) {
  try {
    if (save.write) save.write(save.path);
    else writeFileAtomically(save.path, save.content);
    s.status = "saved " + save.what + " to " + save.path;
    s.chrome.lastSaved = save.path;
    if (s.comparison && s.comparison->text == save.content) s.comparison->saved = true;
  } catch (const std::exception& e) {
    s.status = std::string("error: ") + e.what();
  }
}

}  // namespace

namespace {

// Writes it now, or asks first when the file exists.
void writeOrAsk(Inspector::State& s, PendingSave pending) {
  std::error_code error;
  if (std::filesystem::exists(pending.path, error)) s.dialogs.overwriteQuestion = std::move(pending);
  else writeNow(s, pending);
}

}  // namespace

void Inspector::State::save(const std::string& path, std::string content, const std::string& what,
                            std::function<void()> ifKept) {
  writeOrAsk(*this, PendingSave{path, std::move(content), what, {}, std::move(ifKept)});
}

void Inspector::State::saveWith(const std::string& path, std::function<void(const std::string&)> write,
                                const std::string& what, std::function<void()> ifKept) {
  writeOrAsk(*this, PendingSave{path, {}, what, std::move(write), std::move(ifKept)});
}

void drawOverwriteQuestion(Inspector::State& s) {
  if (s.dialogs.overwriteQuestion && !ImGui::IsPopupOpen("Replace file?")) ImGui::OpenPopup("Replace file?");
  if (!beginDialog("Replace file?")) return;
  if (!s.dialogs.overwriteQuestion) {
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return;
  }
  ImGui::Text("%s already exists.", s.dialogs.overwriteQuestion->path.c_str());
  ImGui::Text("Replace it with the %s?", s.dialogs.overwriteQuestion->what.c_str());
  const bool replace = ImGui::Button("Replace");
  noteControl(s, "replace.yes");
  if (replace) {
    writeNow(s, *s.dialogs.overwriteQuestion);
    s.dialogs.overwriteQuestion.reset();
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  noteControl(s, "replace.no");
  if (s.dialogs.overwriteQuestion && (cancel || s.takeEscape())) {
    s.status = "not saved: " + s.dialogs.overwriteQuestion->path + " kept";
    const std::function<void()> ifKept = std::move(s.dialogs.overwriteQuestion->ifKept);
    s.dialogs.overwriteQuestion.reset();
    ImGui::CloseCurrentPopup();
    if (ifKept) ifKept();
  }
  ImGui::EndPopup();
}

}  // namespace isurface::panels
