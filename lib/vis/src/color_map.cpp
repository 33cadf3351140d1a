#include "isurface/vis/color_map.h"

#include <vtkLookupTable.h>

#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>

#include "isurface/base/diagnostic.h"
#include "isurface/vis/resources.h"

namespace isurface::vis {

namespace {
constexpr const char* kFolder = "resources/colormaps/";
constexpr int kEntries = 256;
}  // namespace

std::vector<std::string> colorMapNames() {
  std::vector<std::string> names;
  const std::string folder = kFolder;
  for (const auto& [path, text] : embeddedResources())
    if (path.rfind(folder, 0) == 0 && path.size() > folder.size() + 5)
      names.push_back(path.substr(folder.size(), path.size() - folder.size() - 5));
  // The paper's map first: it is the default.
  std::stable_partition(names.begin(), names.end(), [](const std::string& n) { return n == "rainbow"; });
  return names;
}

vtkSmartPointer<vtkLookupTable> makeLookupTable(const std::string& name, double lo, double hi) {
  const auto& files = embeddedResources();
  const auto found = files.find(std::string(kFolder) + name + ".json");
  if (found == files.end()) {
    std::string known;
    for (const std::string& n : colorMapNames()) known += (known.empty() ? "" : ", ") + n;
    throw InputError(Diagnostic{"", 0, 0, "unknown colour map '" + name + "' (known: " + known + ")"});
  }
  const nlohmann::json map = nlohmann::json::parse(found->second);
  std::vector<std::array<double, 4>> anchors;
  for (const auto& a : map.at("anchors")) anchors.push_back({a[0], a[1], a[2], a[3]});
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(kEntries);
  table->SetRange(lo, hi);
  for (int i = 0; i < kEntries; ++i) {
    const double t = static_cast<double>(i) / (kEntries - 1);
    std::size_t k = 1;
    while (k + 1 < anchors.size() && anchors[k][0] < t) ++k;
    const auto& a = anchors[k - 1];
    const auto& b = anchors[k];
    const double f = b[0] > a[0] ? std::clamp((t - a[0]) / (b[0] - a[0]), 0.0, 1.0) : 0.0;
    table->SetTableValue(i, a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]), a[3] + f * (b[3] - a[3]), 1.0);
  }
  table->SetNanColor(0.55, 0.55, 0.55, 1.0);
  table->UseBelowRangeColorOff();
  table->UseAboveRangeColorOff();
  return table;
}

}  // namespace isurface::vis
