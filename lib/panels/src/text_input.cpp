#include "text_input.h"

namespace isurface::panels {

namespace {

// ImGui asks for room as the text grows: the string grows, and ImGui writes into its buffer.
int resizeString(ImGuiInputTextCallbackData* data) {
  if (data->EventFlag == ImGuiInputTextFlags_CallbackResize) {
    auto* text = static_cast<std::string*>(data->UserData);
    text->resize(static_cast<std::size_t>(data->BufTextLen));
    data->Buf = text->data();
  }
  return 0;
}

}  // namespace

bool inputText(const char* label, std::string& text, ImGuiInputTextFlags flags) {
  return ImGui::InputText(label, text.data(), text.capacity() + 1, flags | ImGuiInputTextFlags_CallbackResize,
                          resizeString, &text);
}

bool inputTextWithHint(const char* label, const char* hint, std::string& text, ImGuiInputTextFlags flags) {
  return ImGui::InputTextWithHint(label, hint, text.data(), text.capacity() + 1,
                                  flags | ImGuiInputTextFlags_CallbackResize, resizeString, &text);
}

void takeTextTypedBeforeTheField(std::string& text, bool inItsWindow) {
  ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemActive() || io.InputQueueCharacters.empty() || (inItsWindow && !ImGui::IsWindowFocused())) return;
  for (const ImWchar c : io.InputQueueCharacters) {
    if (c < 0x20 || c == 0x7f) continue;  // control characters are keys, not text
    if (c < 0x80) {
      text += static_cast<char>(c);
    } else if (c < 0x800) {
      text += static_cast<char>(0xC0 | (c >> 6));
      text += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      text += static_cast<char>(0xE0 | (c >> 12));
      text += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      text += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  io.InputQueueCharacters.resize(0);
}

}  // namespace isurface::panels
