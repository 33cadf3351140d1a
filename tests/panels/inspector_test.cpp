// The application's selection sync through the inspector itself (no window needed: its panels
// are only drawn by frame()), and the real window under a virtual X server. (The whole UI drawn
// headless by isurface-cli ui-snapshot: tests/cli/inspector_cli_test.cpp.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "dump_fixtures.h"
#include "isurface/base/diagnostic.h"
#include "isurface/panels/inspector.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

panels::GlHooks noContext() {
  return {[] {}, [] { return false; }};
}

}  // namespace

TEST(inspector, PickedLineSelectsItsFirstSampleAndBack) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.open(sourcePath("samples/wuzhishan.nc"));
  inspector.waitUntilIdle();
  ASSERT_NE(inspector.statusText().find("samples"), std::string::npos) << inspector.statusText();
  ASSERT_TRUE(inspector.selectLine(2316));
  const app_model::Selection first = inspector.selection();
  ASSERT_TRUE(first.sample.has_value());
  EXPECT_EQ(*first.line, 2316u);
  // The sample's own line is the same line, and it is the first such sample.
  inspector.selectSample(*first.sample + 1);
  EXPECT_EQ(*inspector.selection().line, 2316u);
  EXPECT_GT(inspector.selection().generation, first.generation);
  inspector.selectSample(*first.sample - 1);
  EXPECT_NE(*inspector.selection().line, 2316u);
  // A comment line produced no sample: the line is selected, no sample.
  EXPECT_FALSE(inspector.selectLine(2));
  EXPECT_EQ(*inspector.selection().line, 2u);
  EXPECT_FALSE(inspector.selection().sample.has_value());
}

TEST(inspector, ADumpJoinsItsProgramAndBadFilesReportErrors) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  const std::string dump = (scratchDir() / "wz.biip").string();
  ASSERT_TRUE(simulateToDump(sourcePath("samples/wuzhishan.nc"), dump));
  inspector.open(sourcePath("samples/wuzhishan.nc"));
  inspector.waitUntilIdle();
  inspector.open(dump);
  inspector.waitUntilIdle();
  EXPECT_NE(inspector.statusText().find("wuzhishan"), std::string::npos) << inspector.statusText();
  EXPECT_EQ(inspector.documentCount(), 1u);  // the dump joined its program
  ASSERT_TRUE(inspector.selectLine(2316));   // and its samples carry the program's lines
  const std::string broken = (scratchDir() / "broken.nc").string();
  std::ofstream(broken) << "G1 X1..2 F100\n";
  inspector.open(broken);
  inspector.waitUntilIdle();
  EXPECT_EQ(inspector.statusText().rfind("error:", 0), 0u) << inspector.statusText();
  EXPECT_NE(inspector.statusText().find("broken.nc:1"), std::string::npos);
}

// The real window, under a virtual X server when the machine has one.
TEST(window, StartsDrawsAndQuitsUnderXvfb) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const std::string home = (scratchDir() / "home").string();
  std::filesystem::create_directories(home);
  const std::string command = "HOME=" + home + " timeout 120 xvfb-run -a -s '-screen 0 1280x800x24' " +
                              std::string(::isurface::test::guiProgram()) + " --exit-after-frames 20 " +
                              sourcePath("samples/wuzhishan.nc") + " > " + home + "/log 2>&1";
  const int status = std::system(command.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 0) << readFile(home + "/log");
  // It remembers what it opened.
  EXPECT_NE(readFile(home + "/.config/isurface/settings.json").find("wuzhishan.nc"), std::string::npos);
}

TEST(inspector, OptimisedRegionStandsBesideTheOriginal) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.open(sourcePath("samples/transition-surface.nc"));
  inspector.waitUntilIdle();
  inspector.optimise(105, 400);
  inspector.waitUntilIdle();
  EXPECT_NE(inspector.statusText().find("passes re-fitted"), std::string::npos) << inspector.statusText();
  EXPECT_NE(inspector.statusText().find("Machining time"), std::string::npos);
  inspector.optimise(1, 5);  // the header: no G1 moves to re-fit
  inspector.waitUntilIdle();
  EXPECT_EQ(inspector.statusText().rfind("error:", 0), 0u) << inspector.statusText();
}

// Another document chosen while a job runs: its result goes to the document it was made for.
TEST(inspector, AColouringEndingAfterAnotherDocumentWasChosenColoursItsOwn) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.open({sourcePath("samples/wuzhishan.nc"), sourcePath("samples/transition-surface.nc")});
  inspector.waitUntilIdle();
  ASSERT_EQ(inspector.documentCount(), 2u);
  inspector.colourBy("accel");  // the transition surface, shown last opened
  inspector.showDocument(0);    // while its map is being made
  inspector.waitUntilIdle();
  const nlohmann::json state = nlohmann::json::parse(inspector.describe());
  EXPECT_EQ(state["active"], 0);
  EXPECT_EQ(state["documents"][0]["map_quantity"], "Path speed") << state["documents"].dump();
  EXPECT_EQ(state["documents"][1]["map_quantity"], "Tangential acceleration") << state["documents"].dump();
  EXPECT_EQ(state["map"]["quantity"], "Path speed");
  // The Colour panel says what the map shown is coloured by, and a map beside it is made alike.
  EXPECT_EQ(state["colour"]["quantity"], "Path speed");
  inspector.showDocument(1);
  EXPECT_EQ(nlohmann::json::parse(inspector.describe())["colour"]["quantity"], "Tangential acceleration");
}

TEST(inspector, ARegionOptimisedWhileAnotherDocumentWasChosenIsShownWithItsOwn) {
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.open({sourcePath("samples/wuzhishan.nc"), sourcePath("samples/transition-surface.nc")});
  inspector.waitUntilIdle();
  // The first time, the document's feedback is loaded first, and the optimisation waits for it.
  for (int time = 0; time < 2; ++time) {
    inspector.optimise(105, 400);  // lines of the transition surface
    inspector.showDocument(0);
    inspector.waitUntilIdle();
  }
  const nlohmann::json state = nlohmann::json::parse(inspector.describe());
  EXPECT_EQ(state["active"], 1) << inspector.statusText();
  ASSERT_FALSE(state["optimised"].is_null()) << inspector.statusText();
  EXPECT_NE(state["optimised"]["summary"].get<std::string>().find("passes re-fitted"), std::string::npos);
}

// A slow tool servo path written as a dump opens alone and is coloured by its error channels.
TEST(inspector, SlowToolServoPathColouredByItsError) {
  const std::string dump = (scratchDir() / "sts.biip").string();
  ASSERT_TRUE(stsToDump("sinusoid", "hermite", dump));
  panels::Inspector inspector(noContext(), app_model::Settings{});
  inspector.open(dump);
  inspector.waitUntilIdle();
  ASSERT_NE(inspector.statusText().find("samples"), std::string::npos) << inspector.statusText();
  inspector.colourBy("interpolation_error_um");
  inspector.waitUntilIdle();
  EXPECT_NE(inspector.statusText().find("coloured by interpolation_error_um"), std::string::npos)
      << inspector.statusText();
  EXPECT_THROW(inspector.colourBy("no_such_channel"), InputError);
}

// An idle window sleeps until input comes: nothing on screen changes without it.
TEST(window, AnIdleWindowTakesNoProcessorTime) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const std::string home = (scratchDir() / "idle-home").string();
  std::filesystem::create_directories(home);
  const std::string program = (scratchDir() / "idle-window-program.nc").string();
  std::filesystem::copy_file(sourcePath("samples/wuzhishan.nc"), program,
                             std::filesystem::copy_options::overwrite_existing);
  // Processor ticks (1/100 s) the window's process takes in 2 s windows, until two in a row are
  // quiet (the program has loaded and the window settled) or 90 s have passed.
  const std::string script =
      "HOME=" + home + " timeout 150 xvfb-run -a -s '-screen 0 1280x800x24' " + std::string(::isurface::test::guiProgram()) + " " + program +
      " > " + home + "/log 2>&1 &\n"
      "pid=; for i in $(seq 1 100); do pid=$(pgrep -f '^" + std::string(::isurface::test::guiProgram()) + " " + program + "' | head -1); "
      "[ -n \"$pid\" ] && break; sleep 0.2; done\n"
      "[ -z \"$pid\" ] && { echo 'no window process'; exit 2; }\n"
      "quiet=0; last=; for i in $(seq 1 45); do a=$(awk '{print $14+$15}' /proc/$pid/stat); sleep 2; "
      "b=$(awk '{print $14+$15}' /proc/$pid/stat); last=$((b-a)); echo $last >> " + home + "/ticks; "
      "if [ $last -le 4 ]; then quiet=$((quiet+1)); else quiet=0; fi; [ $quiet -ge 2 ] && break; done\n"
      "kill $pid; wait; [ $quiet -ge 2 ]\n";
  const std::string file = home + "/measure.sh";
  std::ofstream(file) << script;
  const int status = std::system(("bash " + file).c_str());
  EXPECT_EQ(WEXITSTATUS(status), 0) << "ticks per 2 s: " << readFile(home + "/ticks") << readFile(home + "/log");
}
