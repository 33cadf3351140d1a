#pragma once
// A headless OpenGL context through OSMesa (Mesa's software renderer), no X server needed.
// Kept apart from VTK's GL headers, which make <GL/osmesa.h> uncompilable.
#include <vector>

namespace isurface::vis {

class OsMesaContext {
 public:
  // Creates a core-profile 3.2 context (llvmpipe gives more) rendering into memory.
  OsMesaContext(int width, int height);
  ~OsMesaContext();
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  bool makeCurrent();
  bool isCurrent() const;
  int width() const;
  int height() const;
  // Makes the context current with its own framebuffer bound, full-size viewport, cleared.
  void clearFrame(float r, float g, float b);
  // Waits until every drawing command is done.
  void finish();
  // Finishes drawing and returns the default framebuffer as RGBA rows, top row first.
  std::vector<unsigned char> readPixels();

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace isurface::vis
