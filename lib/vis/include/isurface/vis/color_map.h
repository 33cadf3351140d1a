#pragma once
// Colour maps of the quality map (resources/colormaps/*.json: anchor colours, interpolated).
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "isurface/map/map_style.h"

class vtkLookupTable;

namespace isurface::vis {

// "rainbow" (the paper's blue-to-red, the default), "viridis", "turbo", "coolwarm", "grey".
std::vector<std::string> colorMapNames();

// resolveColorMap(): isurface/map/map_style.h.

// A 256-entry table over [lo, hi]; values outside take the end colours, NaN a neutral grey.
// Throws InputError for an unknown name.
vtkSmartPointer<vtkLookupTable> makeLookupTable(const std::string& name, double lo, double hi);

}  // namespace isurface::vis
