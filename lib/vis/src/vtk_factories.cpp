// The VTK modules whose classes are made through VTK's object factories: OpenGL rendering, the
// chart's 2D context device, text through FreeType and the interaction styles. Registered here,
// once for every program that links isurface_vis, rather than by vtk_module_autoinit, whose
// compile definitions name a header by its absolute path in the build tree: they would make
// every object that includes VTK differ from one clone's build to another's and a shared
// compiler cache miss them all.
#include <vtkAutoInit.h>

VTK_MODULE_INIT(vtkInteractionStyle);
VTK_MODULE_INIT(vtkRenderingFreeType);
VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingContextOpenGL2);
