#pragma once
// The cutter drawn where the selected sample puts it: a ball-end mill whose lowest point is the
// cutter-location point (the samples' convention, the tool tip), a ball of its radius and a
// shank above it, translucent grey so that the surface it stands on stays readable. Units: mm.
#include <vtkSmartPointer.h>

class vtkAssembly;

namespace isurface::vis {

// The samples' tool: a D6R3 ball-end mill.
constexpr double kShownToolRadius = 3.0;

// The tool with its tip at the origin; place it with SetPosition(tip).
vtkSmartPointer<vtkAssembly> makeBallEndMill(double radius);

}  // namespace isurface::vis
