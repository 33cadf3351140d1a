#pragma once
// Colour maps of the quality map (resources/colormaps/*.json: anchor colours, interpolated).
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

class vtkLookupTable;

namespace isurface::vis {

// "rainbow" (the paper's blue-to-red, the default), "viridis", "turbo", "coolwarm", "grey".
std::vector<std::string> colorMapNames();

// "auto": the paper's rainbow, or "coolwarm" (diverging, white at the middle) for values of
// both signs. Any other name is itself.
constexpr const char* kAutoColorMap = "auto";
std::string resolveColorMap(const std::string& name, bool signedValues);

// A 256-entry table over [lo, hi]; values outside take the end colours, NaN a neutral grey.
// Throws InputError for an unknown name.
vtkSmartPointer<vtkLookupTable> makeLookupTable(const std::string& name, double lo, double hi);

}  // namespace isurface::vis
