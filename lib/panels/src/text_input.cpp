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

namespace {

void appendUtf8(std::string& text, ImWchar c) {
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

struct StringEdit {
  std::string* text;
  bool cursorToEnd;
};

int editString(ImGuiInputTextCallbackData* data) {
  auto* edit = static_cast<StringEdit*>(data->UserData);
  if (data->EventFlag == ImGuiInputTextFlags_CallbackResize) {
    edit->text->resize(static_cast<std::size_t>(data->BufTextLen));
    data->Buf = edit->text->data();
  } else if (data->EventFlag == ImGuiInputTextFlags_CallbackAlways && edit->cursorToEnd) {
    data->CursorPos = data->SelectionStart = data->SelectionEnd = data->BufTextLen;
  }
  return 0;
}

}  // namespace

void startTypeAhead(TypeAhead& t, char openedBy) {
  t.framesLeft = 10;
  t.typed = false;
  t.dropFirst = openedBy;
}

bool typeAheadField(const char* label, const char* hint, std::string& text, ImGuiInputTextFlags flags, TypeAhead& t) {
  const bool waiting = t.framesLeft > 0;
  if (waiting) {
    // Taken before the field sees them: while it is not active they would be lost, and on the
    // frame it takes the keyboard they would go before the text taken so far.
    ImGuiIO& io = ImGui::GetIO();
    for (const ImWchar c : io.InputQueueCharacters) {
      if (c < 0x20 || c == 0x7f) continue;  // control characters are keys, not text
      // The opening key's own character comes first, in whichever frame the window hands it on.
      const bool opening = t.dropFirst != 0 && (c == ImWchar(t.dropFirst) || c == ImWchar(t.dropFirst | 0x20));
      t.dropFirst = 0;
      if (opening) continue;
      if (!t.typed) text.clear(), t.typed = true;
      appendUtf8(text, c);
    }
    io.InputQueueCharacters.resize(0);
  }
  StringEdit edit{&text, waiting};
  const ImGuiInputTextFlags extra = ImGuiInputTextFlags_CallbackResize | (waiting ? ImGuiInputTextFlags_CallbackAlways : 0);
  const bool result = ImGui::InputTextWithHint(label, hint, text.data(), text.capacity() + 1, flags | extra, editString, &edit);
  if (waiting) {
    // Once it has the keyboard (its cursor put after the text this frame), it takes the typing.
    if (ImGui::IsItemActive()) t.framesLeft = 0;
    else --t.framesLeft;
  }
  return result;
}

}  // namespace isurface::panels
