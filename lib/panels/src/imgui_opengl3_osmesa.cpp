// Dear ImGui's OpenGL 3 renderer, compiled from Debian's copy of its source (libimgui-dev's
// examples) against OSMesa: the copy inside libimgui.a loads OpenGL through libGL, which has
// no current context in a headless process. Here the GL functions bind to libOSMesa.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#define IMGUI_IMPL_OPENGL_LOADER_CUSTOM
#include ISURFACE_IMGUI_OPENGL3_SOURCE
