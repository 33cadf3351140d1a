// The window's layout holds at small sizes: a long status is cut at its end, the picked
// sample's read-out stays inside a narrow view.
#include <gtest/gtest.h>
#include <imgui.h>

#include <array>
#include <nlohmann/json.hpp>
#include <string>

#include "isurface/panels/headless_ui.h"
#include "test_support.h"
#include "ui_driving.h"

using namespace isurface;
using test::settle, test::described, test::waitForJobs, test::clickControl, test::tap;

namespace {

// Whether the text is whole UTF-8 characters (a cut inside one leaves a broken sequence).
bool wholeUtf8Characters(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const std::size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (length == 0 || i + length > text.size()) return false;
    for (std::size_t k = 1; k < length; ++k)
      if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return false;
    i += length;
  }
  return true;
}

}  // namespace

// A status wider than the window (here a long path that does not open) is cut with "..." so the
// bar keeps its end on screen; the whole text stays for the pointer's tooltip. A short one is
// shown whole.
TEST(windowLayout, AStatusWiderThanTheWindowIsCutAtItsEnd) {
  panels::HeadlessUi ui(640, 480, app_model::Settings{});
  ui.inspector().open(test::sourcePath("samples/transition-surface.nc"));
  waitForJobs(ui);
  nlohmann::json state = described(ui);
  ASSERT_LT(state["status"].get<std::string>().size(), 60u) << state["status"];
  EXPECT_EQ(state["status_shown"], state["status"]);

  std::string folder;  // two-byte UTF-8 characters, so that the cut falls among them
  for (int i = 0; i < 120; ++i) folder += "µ";
  const std::string missing = "/tmp/" + folder + "/no-such-program.nc";
  ui.inspector().open(missing);
  waitForJobs(ui);
  settle(ui);
  state = described(ui);
  const std::string status = state["status"].get<std::string>(), shown = state["status_shown"].get<std::string>();
  ASSERT_NE(status.find("no-such-program.nc"), std::string::npos) << status;
  ASSERT_GT(shown.size(), 3u);
  EXPECT_EQ(shown.substr(shown.size() - 3), "...");
  EXPECT_EQ(status.compare(0, shown.size() - 3, shown, 0, shown.size() - 3), 0) << shown << " | " << status;
  EXPECT_TRUE(wholeUtf8Characters(shown)) << shown;
  EXPECT_LT(shown.size(), 200u) << "640 pixels hold about 90 characters";
  EXPECT_GT(shown.size(), 40u);
}

// With the re-optimised map beside it in a small window, the main view is narrow: the picked
// sample's read-out is laid out in more lines rather than running over the map beside it.
TEST(windowLayout, TheReadOutStaysInsideANarrowView) {
  panels::HeadlessUi ui(1024, 640, app_model::Settings{});
  ui.inspector().open(test::sourcePath("samples/transition-surface.nc"));
  waitForJobs(ui);
  ASSERT_TRUE(ui.inspector().selectLine(200));
  settle(ui);
  const auto wide = described(ui)["controls"];
  ASSERT_TRUE(wide.contains("view.readout"));
  const float wideHeight = wide["view.readout"][3].get<float>() - wide["view.readout"][1].get<float>();
  ui.inspector().optimise(105, 400);
  waitForJobs(ui);
  settle(ui);
  ASSERT_NE(ui.inspector().optimisedDifference(), nullptr) << ui.inspector().statusText();
  const nlohmann::json controls = described(ui)["controls"];
  ASSERT_TRUE(controls.contains("view.readout"));
  const auto view = controls["view"].get<std::array<float, 4>>();
  const auto readout = controls["view.readout"].get<std::array<float, 4>>();
  EXPECT_LT(view[2] - view[0], wide["view"][2].get<float>() - wide["view"][0].get<float>()) << "the map beside it";
  EXPECT_GE(readout[0], view[0]);
  EXPECT_LE(readout[2], view[0] + 0.84f * (view[2] - view[0])) << "the read-out runs over the colour legend";
  EXPECT_GE(readout[1], view[1]);
  EXPECT_LE(readout[3], view[3]);
  EXPECT_GT(readout[3] - readout[1], wideHeight) << "more lines where the view is narrower";
}

// Esc closes an open menu of the bar, as in any desktop application.
TEST(windowLayout, EscClosesAnOpenMenu) {
  panels::HeadlessUi ui(1280, 800, app_model::Settings{});
  settle(ui);
  clickControl(ui, "menu.file");
  settle(ui);
  ASSERT_TRUE(described(ui)["windows"]["menu"].get<bool>());
  tap(ui, ImGuiKey_Escape);
  settle(ui);
  EXPECT_FALSE(described(ui)["windows"]["menu"].get<bool>());
}


// At 1000 x 700 the Colour panel's choices are whole inside it: the column widens for them, and
// a choice that does not fit beside another goes below it.
TEST(windowLayout, TheColourPanelsChoicesAreWholeOnASmallWindow) {
  panels::HeadlessUi ui(1000, 700, app_model::Settings{});
  ui.inspector().open(test::sourcePath("samples/transition-surface.nc"));
  waitForJobs(ui);
  settle(ui);
  const auto panel = ui.inspector().controlRect("colour");
  ASSERT_TRUE(panel.has_value());
  for (const char* control : {"surface.feedback", "surface.gap", "surface.pattern", "range.fixed"}) {
    const auto rect = ui.inspector().controlRect(control);
    ASSERT_TRUE(rect.has_value()) << control;
    EXPECT_LE((*rect)[2], (*panel)[2]) << control << " reaches past the panel's right edge";
  }
}

// With text at 150 % in a 1000 x 700 window, the machine window (its axis table, its name field)
// stays inside the application's window, scrolling instead of reaching past the edges.
TEST(windowLayout, TheMachineWindowStaysInsideASmallWindow) {
  app_model::Settings settings;
  settings.uiScale = 1.5f;
  settings.uiScaleChosen = true;
  panels::HeadlessUi ui(1000, 700, settings);
  ui.inspector().open(test::sourcePath("samples/transition-surface.nc"));
  waitForJobs(ui);
  test::tapLetter(ui, 'M');
  settle(ui, 4);
  const auto inside = [&](int width, int height) {
    const auto rect = ui.inspector().controlRect("machine");
    ASSERT_TRUE(rect.has_value());
    EXPECT_GE((*rect)[0], 0.0f);
    EXPECT_GE((*rect)[1], 0.0f);
    EXPECT_LE((*rect)[2], float(width)) << "the machine window reaches past the right edge";
    EXPECT_LE((*rect)[3], float(height)) << "the machine window reaches past the bottom";
  };
  inside(1000, 700);
}

// A problem line appearing in the Export dialog (here: no file given) does not move the Export
// button down under the pointer.
TEST(windowLayout, TheExportButtonStaysPutWhenAProblemIsSaid) {
  panels::HeadlessUi ui(1600, 1000, app_model::Settings{});
  ui.inspector().open(test::sourcePath("samples/transition-surface.nc"));
  waitForJobs(ui);
  test::tapLetter(ui, 'E', true);
  ASSERT_TRUE(described(ui)["windows"]["export"].get<bool>());
  test::typeInto(ui, "export.path", "map.png");
  const auto withPath = ui.inspector().controlRect("export.write");
  test::typeInto(ui, "export.path", "");
  ui.key(ImGuiKey_Backspace, true);
  ui.frame();
  ui.key(ImGuiKey_Backspace, false);
  settle(ui, 2);
  ASSERT_EQ(described(ui)["export_path"], "");
  const auto withoutPath = ui.inspector().controlRect("export.write");
  ASSERT_TRUE(withPath && withoutPath);
  EXPECT_EQ((*withPath)[1], (*withoutPath)[1]);
  // Nor does another kind of export, with settings of its own or none.
  for (const char* kind : {"export.json", "export.report", "export.csv", "export.dump", "export.png"}) {
    test::clickControl(ui, kind);
    const auto rect = ui.inspector().controlRect("export.write");
    ASSERT_TRUE(rect.has_value());
    EXPECT_EQ((*rect)[1], (*withPath)[1]) << kind;
  }
}
