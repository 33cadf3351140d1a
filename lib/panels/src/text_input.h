#pragma once
// ImGui's text fields over a std::string, so that the model holds text as std::string and not as
// fixed buffers: the field grows with what is typed.
#include <imgui.h>

#include <string>

namespace isurface::panels {

bool inputText(const char* label, std::string& text, ImGuiInputTextFlags flags = 0);
bool inputTextWithHint(const char* label, const char* hint, std::string& text, ImGuiInputTextFlags flags = 0);
// A field that takes the keyboard when it appears (a dialog's path, the G-code search): it gets
// the keyboard a frame or two late, so what is typed meanwhile is taken for it, replacing what it
// held, and the cursor then stands after it. Without this the first characters were lost, or ran
// as the window's shortcuts.
struct TypeAhead {
  int framesLeft = 0;      // of waiting for the field to take the keyboard (0: not waiting)
  bool typed = false;      // something was typed while waiting: it replaced the old text
  char dropFirst = 0;      // the letter of the key that opened it, whose own character is not text
};
// Starts waiting (when the field is asked to take the keyboard): `openedBy` is the letter key
// that asked, 0 for a click or a key with Ctrl.
void startTypeAhead(TypeAhead& t, char openedBy);
bool typeAheadField(const char* label, const char* hint, std::string& text, ImGuiInputTextFlags flags, TypeAhead& t);

}  // namespace isurface::panels
