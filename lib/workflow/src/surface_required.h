#pragma once
#include <string>

#include "isurface/workflow/region_optimisation.h"

namespace isurface {

// The figures are measured between neighbouring passes on the surface: a run whose passes make
// no triangle would be judged on nothing. Throws InputError naming `source` and why there is
// none.
void requireSurface(const SurfaceRun& run, const std::string& source);

}  // namespace isurface
