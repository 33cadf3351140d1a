#pragma once
// The application's fonts and window icon, as resources/ui/ui.json names them.
#include <string>

namespace isurface::panels {

struct UiLook {
  std::string fontFile;   // "" when none of the listed fonts exists: ImGui's own font
  float fontSize = 14;    // pixels
  std::string iconPng;    // the window icon, PNG bytes (compiled in: no file is looked for)
};

UiLook uiLook();
// Loads the font into the current ImGui context and sets the colours; call after
// ImGui::CreateContext() and before the renderer builds its font texture.
void applyUiLook(const UiLook& look);
// Colours of a theme ("dark" or "light") and sizes at a scale (1 = as designed), at any time.
void applyTheme(const std::string& theme, float scale);

}  // namespace isurface::panels
