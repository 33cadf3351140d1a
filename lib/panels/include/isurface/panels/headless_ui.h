#pragma once
// The whole application drawn into an OSMesa context: Dear ImGui with its OpenGL 3 renderer
// and the inspector's panels, fed with input directly. Used by ui-snapshot and the UI benchmark.
#include <memory>
#include <string>
#include <vector>

#include "isurface/panels/inspector.h"

namespace isurface::vis {
class OsMesaContext;
}

namespace isurface::panels {

class HeadlessUi {
 public:
  // Throws std::runtime_error when no OSMesa context can be made.
  HeadlessUi(int width, int height, app_model::Settings settings);
  ~HeadlessUi();
  HeadlessUi(const HeadlessUi&) = delete;
  HeadlessUi& operator=(const HeadlessUi&) = delete;

  panels::Inspector& inspector() { return *inspector_; }
  // Mouse state for the next frame, in window pixels.
  void mouse(float x, float y, bool leftDown);
  // The mouse wheel turned by `steps` notches (positive: away from the user, zooming in) in the next frame.
  void wheel(float steps);
  // A named key (an ImGuiKey_ value: arrows, pages, Home, End, Escape, ...) held or not for the
  // next frame.
  void key(int imguiKey, bool down);
  // A letter key ('A'..'Z', as the window's shortcuts read them) held or not for the next frame.
  void letter(char upperCase, bool down);
  void ctrl(bool down);
  void shift(bool down);
  // Text typed into the field that has the keyboard, in the next frame.
  void type(const std::string& text);
  // Draws one frame of the whole window and finishes it.
  void frame();
  // The window as RGBA rows, top row first.
  std::vector<unsigned char> pixels();
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  std::unique_ptr<vis::OsMesaContext> context_;
  std::unique_ptr<panels::Inspector> inspector_;
};

}  // namespace isurface::panels
