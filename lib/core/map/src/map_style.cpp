#include "isurface/map/map_style.h"

namespace isurface::vis {

std::optional<ViewDirection> parseView(const std::string& name) {
  if (name == "iso") return ViewDirection::Iso;
  if (name == "top") return ViewDirection::Top;
  if (name == "front") return ViewDirection::Front;
  if (name == "left") return ViewDirection::Left;
  return std::nullopt;
}

std::string resolveColorMap(const std::string& name, bool signedValues) {
  if (name != kAutoColorMap) return name;
  return signedValues ? "coolwarm" : "rainbow";
}

}  // namespace isurface::vis
