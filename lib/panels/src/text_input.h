#pragma once
// ImGui's text fields over a std::string, so that the model holds text as std::string and not as
// fixed buffers: the field grows with what is typed.
#include <imgui.h>

#include <string>

namespace isurface::panels {

bool inputText(const char* label, std::string& text, ImGuiInputTextFlags flags = 0);
bool inputTextWithHint(const char* label, const char* hint, std::string& text, ImGuiInputTextFlags flags = 0);
// Call right after a field of a dialog that has just opened: what was typed in the frames before
// the field took the keyboard (it takes it a frame late) is added to `text` instead of lost.
// `inItsWindow`: only when the field's window has the keyboard (a dialog's).
void takeTextTypedBeforeTheField(std::string& text, bool inItsWindow = true);

}  // namespace isurface::panels
