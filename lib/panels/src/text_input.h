#pragma once
// ImGui's text fields over a std::string, so that the model holds text as std::string and not as
// fixed buffers: the field grows with what is typed.
#include <imgui.h>

#include <string>

namespace isurface::panels {

bool inputText(const char* label, std::string& text, ImGuiInputTextFlags flags = 0);
bool inputTextWithHint(const char* label, const char* hint, std::string& text, ImGuiInputTextFlags flags = 0);

}  // namespace isurface::panels
