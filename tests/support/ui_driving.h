#pragma once
// Driving the headless window as a user would: clicks, key taps and typing, each followed by
// the frames the window needs to act on them.
#include <memory>
#include <gtest/gtest.h>
#include <imgui.h>

#include <nlohmann/json.hpp>
#include <string>

#include "isurface/panels/headless_ui.h"
#include "isurface/panels/inspector.h"

namespace isurface::test {

inline void settle(panels::HeadlessUi& ui, int frames = 3) {
  for (int i = 0; i < frames; ++i) ui.frame();
}

// The window's state as a script reads it (Inspector::describe()).
inline nlohmann::json described(panels::HeadlessUi& ui) { return nlohmann::json::parse(ui.inspector().describe()); }

// Lets the background work end and the window take its results in.
inline void waitForJobs(panels::HeadlessUi& ui) {
  ui.inspector().waitUntilIdle();
  settle(ui);
}

inline void click(panels::HeadlessUi& ui, float x, float y) {
  ui.mouse(x, y, false);
  ui.frame();
  ui.mouse(x, y, true);
  ui.frame();
  ui.mouse(x, y, false);
  settle(ui, 2);
}

// A named key (ImGuiKey_...) or, with `letter`, a letter key ('A'..'Z'), pressed and let go.
inline void tap(panels::HeadlessUi& ui, int key, bool ctrl = false, bool letter = false) {
  ui.ctrl(ctrl);
  letter ? ui.letter(static_cast<char>(key), true) : ui.key(key, true);
  ui.frame();
  letter ? ui.letter(static_cast<char>(key), false) : ui.key(key, false);
  ui.ctrl(false);
  settle(ui, 2);
}

inline void tapLetter(panels::HeadlessUi& ui, char letter, bool ctrl = false) { tap(ui, letter, ctrl, true); }

// Clicks the middle of a named control of the window; fails the test when it is not drawn.
inline void clickControl(panels::HeadlessUi& ui, const std::string& name) {
  const auto rect = ui.inspector().controlRect(name);
  ASSERT_TRUE(rect.has_value()) << name << " is not drawn";
  click(ui, ((*rect)[0] + (*rect)[2]) * 0.5f, ((*rect)[1] + (*rect)[3]) * 0.5f);
}

// Clicks a text field, selects what it holds and types over it.
inline void typeInto(panels::HeadlessUi& ui, const std::string& control, const std::string& text) {
  clickControl(ui, control);
  tap(ui, ImGuiKey_A, true);
  ui.type(text);
  settle(ui, 2);
}

// A window of `width` x `height` with the transition sample open, simulated and mapped.
inline std::unique_ptr<panels::HeadlessUi> openedSample(int width, int height) {
  auto ui = std::make_unique<panels::HeadlessUi>(width, height, app_model::Settings{});
  ui->inspector().open(sourcePath("samples/transition-surface.nc"));
  waitForJobs(*ui);
  return ui;
}

}  // namespace isurface::test
