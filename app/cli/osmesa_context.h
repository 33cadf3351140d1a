#pragma once
// A headless OpenGL context through OSMesa (Mesa's software renderer), no X server needed.
// Kept apart from VTK's GL headers, which make <GL/osmesa.h> uncompilable.
namespace isurface::cli {

class OsMesaContext {
 public:
  // Creates a core-profile 3.2 context (llvmpipe gives more) rendering into memory.
  OsMesaContext(int width, int height);
  ~OsMesaContext();
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  bool makeCurrent();
  bool isCurrent() const;

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace isurface::cli
