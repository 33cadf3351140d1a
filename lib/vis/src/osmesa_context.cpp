#include "isurface/vis/osmesa_context.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/glext.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

// VTK loads OpenGL through GLEW, which asks GLX for function pointers and fails without an X
// display. These two definitions take precedence over the libraries' own: OSMesa answers. They
// are exported whatever the build's default visibility, or GLEW still calls its own glxewInit
// and VTK prints "GLEW could not be initialized" on every render.
extern "C" {
__attribute__((visibility("default"))) void (*glXGetProcAddressARB(const unsigned char* name))() {
  return reinterpret_cast<void (*)()>(OSMesaGetProcAddress(reinterpret_cast<const char*>(name)));
}
__attribute__((visibility("default"))) unsigned int glxewInit() { return 0; }
}

namespace isurface::vis {

struct OsMesaContext::Impl {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> buffer;
  int width = 0, height = 0;
};

OsMesaContext::OsMesaContext(int width, int height) : impl_(new Impl) {
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                            OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                            OSMESA_CONTEXT_MINOR_VERSION, 2, 0};
  impl_->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!impl_->context) {
    delete impl_;
    throw std::runtime_error("cannot create an OSMesa OpenGL 3.2 core context");
  }
  impl_->width = width;
  impl_->height = height;
  impl_->buffer.resize(static_cast<std::size_t>(width) * height * 4);
  if (!makeCurrent()) {
    OSMesaDestroyContext(impl_->context);
    delete impl_;
    throw std::runtime_error("cannot make the OSMesa context current");
  }
}

OsMesaContext::~OsMesaContext() {
  OSMesaDestroyContext(impl_->context);
  delete impl_;
}

bool OsMesaContext::makeCurrent() {
  return OSMesaMakeCurrent(impl_->context, impl_->buffer.data(), GL_UNSIGNED_BYTE, impl_->width, impl_->height);
}

bool OsMesaContext::isCurrent() const { return OSMesaGetCurrentContext() == impl_->context; }
int OsMesaContext::width() const { return impl_->width; }
int OsMesaContext::height() const { return impl_->height; }

void OsMesaContext::clearFrame(float r, float g, float b) {
  makeCurrent();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, impl_->width, impl_->height);
  glClearColor(r, g, b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

void OsMesaContext::finish() {
  makeCurrent();
  glFinish();
}

std::vector<unsigned char> OsMesaContext::readPixels() {
  makeCurrent();
  glFinish();
  // OSMesa's buffer holds the bottom row first.
  const std::size_t row = static_cast<std::size_t>(impl_->width) * 4;
  std::vector<unsigned char> top(impl_->buffer.size());
  for (int y = 0; y < impl_->height; ++y)
    std::copy_n(&impl_->buffer[(impl_->height - 1 - y) * row], row, &top[y * row]);
  return top;
}

}  // namespace isurface::vis
