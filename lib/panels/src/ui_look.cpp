#include "isurface/panels/ui_look.h"

#include <imgui.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "isurface/vis/resources.h"

namespace isurface::panels {

UiLook uiLook() {
  UiLook look;
  const nlohmann::json settings = nlohmann::json::parse(vis::resourceText("resources/ui/ui.json"));
  for (const auto& file : settings.value("font_files", nlohmann::json::array())) {
    std::error_code error;
    if (file.is_string() && std::filesystem::exists(file.get<std::string>(), error)) {
      look.fontFile = file.get<std::string>();
      break;
    }
  }
  look.fontSize = settings.value("font_size_px", 14.0f);
  look.iconPng = vis::resourceText("resources/" + settings.value("window_icon", std::string()));
  return look;
}

void applyTheme(const std::string& theme, float scale) {
  ImGuiStyle style;
  if (theme == "light") ImGui::StyleColorsLight(&style);
  else ImGui::StyleColorsDark(&style);
  style.WindowRounding = 0;
  style.FrameRounding = 2;
  style.WindowBorderSize = 1;
  // A selected row stands out more than a row under the pointer (the dark style has it the other
  // way round, so that a click seemed to select the wrong row).
  style.Colors[ImGuiCol_Header] = ImVec4(0.26f, 0.59f, 0.98f, 0.85f);
  style.Colors[ImGuiCol_HeaderHovered] = ImVec4(0.26f, 0.59f, 0.98f, 0.30f);
  style.Colors[ImGuiCol_HeaderActive] = ImVec4(0.26f, 0.59f, 0.98f, 1.00f);
  // A dialog over the map is read, not looked through: the map behind made its text hard to read.
  style.Colors[ImGuiCol_PopupBg].w = 1.0f;
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
  ImGui::GetIO().FontGlobalScale = scale;
}

void applyUiLook(const UiLook& look) {
  applyTheme("dark", 1.0f);
  ImGuiIO& io = ImGui::GetIO();
  if (!look.fontFile.empty()) io.Fonts->AddFontFromFileTTF(look.fontFile.c_str(), look.fontSize);
}

}  // namespace isurface::panels
