// What the window offers beyond the paper's: the G-code pane's search and times, the pass
// pattern, the worst regions, playing the run, documents that keep their own view, machines
// remembered per program, a run saved as a dump and a second run's speed on one time axis, and
// Export going back to its dialog when a file is kept. Drawn headless, driven with the mouse and
// the keys.
#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "isurface/io/biip.h"
#include "isurface/machine/machine.h"
#include "isurface/panels/headless_ui.h"
#include "test_support.h"
#include "ui_driving.h"

using namespace isurface;
using test::clickControl, test::settle, test::tap, test::tapLetter, test::typeInto, test::described, test::waitForJobs;

namespace {

constexpr int kWidth = 1280, kHeight = 800;

std::unique_ptr<panels::HeadlessUi> openedSample() { return test::openedSample(kWidth, kHeight); }

}  // namespace

// Keeping the file the export would replace goes back to the Export dialog, its path to be
// changed, not out of it.
TEST(windowFeatures, KeepingTheFileAnExportWouldReplaceReturnsToTheDialog) {
  auto ui = openedSample();
  const std::filesystem::path png = test::scratchDir() / "kept-view.png";
  std::ofstream(png) << "kept";
  tapLetter(*ui, 'E', true);
  typeInto(*ui, "export.path", png.string());
  clickControl(*ui, "export.write");
  ASSERT_TRUE(described(*ui)["windows"]["replace_question"].get<bool>());
  EXPECT_FALSE(described(*ui)["windows"]["export"].get<bool>());
  clickControl(*ui, "replace.no");
  settle(*ui);
  EXPECT_TRUE(described(*ui)["windows"]["export"].get<bool>());
  EXPECT_EQ(described(*ui)["export_path"], png.string());
  EXPECT_EQ(test::readFile(png.string()), "kept");
}

// A simulation is saved from the window as a dump with its machine: opened again, it is the same
// run, made with the same machine, and needs no simulating.
TEST(windowFeatures, ASimulationIsSavedAsADumpWithItsMachine) {
  auto ui = openedSample();
  const std::filesystem::path dump = test::scratchDir() / "window-run.biip";
  std::filesystem::remove(dump);
  tapLetter(*ui, 'E', true);
  clickControl(*ui, "export.dump");
  typeInto(*ui, "export.path", dump.string());
  clickControl(*ui, "export.write");
  waitForJobs(*ui);  // the feedback positions are loaded first
  ASSERT_EQ(described(*ui)["last_saved"], dump.string()) << ui->inspector().statusText();
  const BiipReader reader(dump.string());
  EXPECT_EQ(reader.recordCount(), described(*ui)["documents"][0]["samples"].get<std::size_t>());
  const nlohmann::json meta = nlohmann::json::parse(reader.header().metadataJson);
  EXPECT_EQ(meta["machine"]["name"], defaultMachine().name);
  ui->inspector().open(dump.string());
  waitForJobs(*ui);
  const nlohmann::json reopened = described(*ui)["documents"].back();
  EXPECT_EQ(reopened["machine"], defaultMachine().name) << reopened.dump();
}

// A second run compared (a machine's recording, a simulation saved before) has its path speed
// drawn over this run's, in orange, on one time axis.
TEST(windowFeatures, TheSecondRunsSpeedIsDrawnOverThisRunsOnOneTimeAxis) {
  auto ui = openedSample();
  const auto orangeInSpeedPlot = [&ui] {
    settle(*ui);
    const auto plot = ui->inspector().controlRect("curves.speed");
    EXPECT_TRUE(plot.has_value());
    if (!plot) return std::size_t{0};
    const std::vector<unsigned char> rgba = ui->pixels();
    std::size_t orange = 0;
    for (int y = int((*plot)[1]); y < int((*plot)[3]); ++y)
      for (int x = int((*plot)[0]); x < int((*plot)[2]); ++x) {
        const unsigned char* p = &rgba[(std::size_t(y) * kWidth + std::size_t(x)) * 4];
        orange += p[0] > 150 && p[1] > 60 && p[1] < 175 && p[0] - p[2] > 60;
      }
    return orange;
  };
  const std::size_t before = orangeInSpeedPlot();
  const std::filesystem::path dump = test::scratchDir() / "second-run.biip";
  std::filesystem::remove(dump);
  tapLetter(*ui, 'E', true);
  clickControl(*ui, "export.dump");
  typeInto(*ui, "export.path", dump.string());
  clickControl(*ui, "export.write");
  waitForJobs(*ui);
  ui->inspector().compareWith(dump.string());
  waitForJobs(*ui);
  ASSERT_NE(ui->inspector().runComparison(), nullptr) << ui->inspector().statusText();
  const std::size_t after = orangeInSpeedPlot();
  EXPECT_GT(after, before + 300) << before << " orange pixels before, " << after << " after";
}

// Ctrl+F in the G-code: Enter goes to the next line holding the text, Shift+Enter back, round
// past the ends; text no line holds is said, and the selection stays.
TEST(windowFeatures, CtrlFFindsTextInTheGcode) {
  auto ui = openedSample();
  ASSERT_TRUE(ui->inspector().selectLine(2000));
  settle(*ui);
  // The lines holding "X23.35", as a reader of the file finds them.
  std::vector<std::uint32_t> holding;
  std::ifstream program(test::sourcePath("samples/transition-surface.nc"));
  std::string text;
  for (std::uint32_t line = 1; std::getline(program, text); ++line)
    if (text.find("X23.35") != std::string::npos) holding.push_back(line);
  ASSERT_GE(holding.size(), 2u);
  const auto after2000 = std::upper_bound(holding.begin(), holding.end(), 2000u);
  const std::uint32_t next = after2000 == holding.end() ? holding.front() : *after2000;
  tapLetter(*ui, 'F', true);
  ui->type("x23.35");
  tap(*ui, ImGuiKey_Enter);
  EXPECT_EQ(ui->inspector().selection().line, next);
  ui->shift(true);
  tap(*ui, ImGuiKey_Enter);
  ui->shift(false);
  const auto before = std::lower_bound(holding.begin(), holding.end(), next);
  EXPECT_EQ(ui->inspector().selection().line, before == holding.begin() ? holding.back() : *(before - 1));
  typeInto(*ui, "gcode.find", "s12000 m3");
  tap(*ui, ImGuiKey_Enter);
  EXPECT_EQ(ui->inspector().selection().line, 6u);
  typeInto(*ui, "gcode.find", "G65 P9999");
  tap(*ui, ImGuiKey_Enter);
  EXPECT_EQ(ui->inspector().selection().line, 6u);
  EXPECT_EQ(described(*ui)["gcode_search"], "no line holds \"G65 P9999\"");
}

// The pass pattern is chosen in the window, as `compare --pattern` takes it: the map is made
// again with it, and another program's passes are found anew.
TEST(windowFeatures, ThePassPatternIsChosenInTheWindow) {
  auto ui = openedSample();
  nlohmann::json map = described(*ui)["map"];
  EXPECT_EQ(map["pattern_asked"], "auto");
  EXPECT_EQ(map["pattern"], "direction-parallel");
  const std::size_t found = map["passes"].get<std::size_t>();
  clickControl(*ui, "surface.pattern");
  clickControl(*ui, "surface.pattern:no-boundary");
  waitForJobs(*ui);
  map = described(*ui)["map"];
  EXPECT_EQ(map["pattern_asked"], "no-boundary");
  EXPECT_EQ(map["pattern"], "no-boundary");
  EXPECT_NE(map["passes"].get<std::size_t>(), found);
  ui->inspector().open(test::sourcePath("samples/wuzhishan.nc"));
  waitForJobs(*ui);
  EXPECT_EQ(described(*ui)["map"]["pattern_asked"], "auto");
}

// The worst regions as the report ranks them: listed in the window (Ctrl+R), a click goes to
// a region's worst sample, its Optimise button holds its lines and box in the dialog.
TEST(windowFeatures, TheWorstRegionsAreListedAndAClickGoesThere) {
  auto ui = openedSample();
  tapLetter(*ui, 'R', true);
  waitForJobs(*ui);
  settle(*ui);
  const nlohmann::json map = described(*ui)["map"];
  ASSERT_TRUE(map["regions_found"].is_number()) << map.dump();
  ASSERT_GT(map["regions_found"].get<std::size_t>(), 0u);
  clickControl(*ui, "regions.item:1");
  ASSERT_TRUE(ui->inspector().selection().sample);
  const std::uint32_t line = *ui->inspector().selection().line;
  // The status names the region's box (its corners), not its width as a distance.
  const std::string status = described(*ui)["status"];
  EXPECT_EQ(status.rfind("region 1: lines ", 0), 0u) << status;
  EXPECT_NE(status.find(", box X "), std::string::npos) << status;
  EXPECT_EQ(status.find(" from X "), std::string::npos) << status;
  clickControl(*ui, "regions.optimise:1");
  settle(*ui);
  const nlohmann::json lines = described(*ui)["optimise_lines"];
  EXPECT_LE(lines[0].get<std::uint32_t>(), line);
  EXPECT_GE(lines[1].get<std::uint32_t>(), line);
  EXPECT_TRUE(described(*ui)["optimise_box"].is_object());
}

// Play moves the selection along the run with the clock and Pause holds it; a click on the
// time slider goes to that time of the run.
TEST(windowFeatures, TheRunIsPlayedAndScrubbed) {
  auto ui = openedSample();
  ASSERT_TRUE(ui->inspector().selectSample(100));
  settle(*ui);
  clickControl(*ui, "curves.play");
  settle(*ui, 10);
  const std::size_t played = *ui->inspector().selection().sample;
  EXPECT_GT(played, 100u);
  clickControl(*ui, "curves.play");  // Pause
  const std::size_t paused = *ui->inspector().selection().sample;
  settle(*ui, 10);
  EXPECT_EQ(*ui->inspector().selection().sample, paused);
  clickControl(*ui, "curves.time");  // the middle of the slider: about half the run
  const std::size_t middle = *ui->inspector().selection().sample;
  const std::size_t samples = described(*ui)["documents"][0]["samples"].get<std::size_t>();
  EXPECT_NEAR(double(middle) / double(samples), 0.5, 0.05);
}

// The tool stands on the selected sample, its tip on the commanded point, and moves with the
// selection as the run plays; with nothing selected it is not drawn.
TEST(windowFeatures, TheToolStandsOnTheSelectedSampleAndPlaysAlong) {
  auto ui = openedSample();
  EXPECT_FALSE(described(*ui)["selection"].contains("tool_tip"));
  ASSERT_TRUE(ui->inspector().selectSample(5000));
  settle(*ui, 3);
  const nlohmann::json picked = described(*ui)["selection"];
  ASSERT_TRUE(picked.contains("tool_tip")) << picked;
  EXPECT_EQ(picked["tool_tip"], picked["position"]);
  clickControl(*ui, "curves.play");
  settle(*ui, 10);
  const nlohmann::json playing = described(*ui)["selection"];  // while it plays
  ASSERT_GT(playing["sample"].get<std::size_t>(), 5000u);
  EXPECT_EQ(playing["tool_tip"], playing["position"]);
  clickControl(*ui, "curves.play");  // Pause
  settle(*ui, 3);
  const nlohmann::json played = described(*ui)["selection"];
  ASSERT_GT(played["sample"].get<std::size_t>(), 5000u);
  EXPECT_EQ(played["tool_tip"], played["position"]);
  EXPECT_NE(played["tool_tip"], picked["tool_tip"]);
}

// Playing with the curves around the selection, the curves turn the page when the tool leaves
// the stretch they show: it stays in view, and the stretch keeps its width.
TEST(windowFeatures, TheCurvesAroundTheSelectionFollowPlay) {
  auto ui = openedSample();
  ASSERT_TRUE(ui->inspector().selectSample(5000));
  settle(*ui, 2);
  clickControl(*ui, "curves.around");
  const auto before = described(*ui)["curves_span"].get<std::vector<std::size_t>>();
  ASSERT_EQ(before, (std::vector<std::size_t>{3000, 7000}));
  clickControl(*ui, "curves.play");
  settle(*ui, 120);  // 4 s at x1, 1 ms a sample: well past the stretch
  clickControl(*ui, "curves.play");
  const nlohmann::json state = described(*ui);
  const auto span = state["curves_span"].get<std::vector<std::size_t>>();
  const std::size_t sample = state["selection"]["sample"];
  ASSERT_GT(sample, 7000u);
  EXPECT_GE(sample, span[0]);
  EXPECT_LT(sample, span[1]);
  EXPECT_EQ(span[1] - span[0], 4000u);
}

// A re-optimisation shown beside its document stays with it: another document shown meanwhile
// has none beside it, and going back finds it again.
TEST(windowFeatures, AnOptimisationStaysWithItsDocument) {
  auto ui = openedSample();
  ui->inspector().optimise(105, 400);
  waitForJobs(*ui);
  ASSERT_FALSE(described(*ui)["optimised"].is_null()) << ui->inspector().statusText();
  ui->inspector().open(test::sourcePath("samples/wuzhishan.nc"));
  waitForJobs(*ui);
  EXPECT_TRUE(described(*ui)["optimised"].is_null());
  ui->inspector().showDocument(0);
  settle(*ui);
  EXPECT_FALSE(described(*ui)["optimised"].is_null());
}

// A new document starts at its own top and from the default view, not where the one before it
// was scrolled and turned; going back to the first finds it as it was left.
TEST(windowFeatures, ANewDocumentStartsAtItsTopAndFromTheDefaultView) {
  auto ui = openedSample();
  ASSERT_TRUE(ui->inspector().selectLine(2000));
  settle(*ui);
  tapLetter(*ui, 'T');  // top view
  settle(*ui);
  EXPECT_GT(described(*ui)["gcode_top_line"].get<std::size_t>(), 1000u);
  ui->inspector().open(test::sourcePath("samples/wuzhishan.nc"));
  waitForJobs(*ui);
  settle(*ui);
  EXPECT_EQ(described(*ui)["gcode_top_line"], 1u);
  EXPECT_EQ(described(*ui)["colour"]["view"], "iso");
  ui->inspector().showDocument(0);
  settle(*ui);
  EXPECT_GT(described(*ui)["gcode_top_line"].get<std::size_t>(), 1000u);
  EXPECT_EQ(described(*ui)["colour"]["view"], "top");
}

// The machine a program was simulated with is remembered for it: opened again, it is simulated
// with that machine, whatever another program was simulated with meanwhile; a program with no
// machine of its own then opens with the default, not another program's.
TEST(windowFeatures, TheMachineIsRememberedForItsProgram) {
  auto ui = openedSample();
  tapLetter(*ui, 'M');
  typeInto(*ui, "machine.velocity.x", "1500");
  clickControl(*ui, "machine.simulate");
  waitForJobs(*ui);
  const std::string edited = described(*ui)["machine"]["name"];
  ASSERT_NE(edited, defaultMachine().name);
  EXPECT_FALSE(ui->inspector().settings().machineOf(test::sourcePath("samples/transition-surface.nc")).empty());
  // Another program does not take the machine applied to this one: it opens with the default.
  ui->inspector().open(test::sourcePath("samples/wuzhishan.nc"));
  waitForJobs(*ui);
  EXPECT_EQ(described(*ui)["documents"].back()["machine"], defaultMachine().name);
  clickControl(*ui, "machine.default");
  clickControl(*ui, "machine.simulate");
  waitForJobs(*ui);
  EXPECT_EQ(described(*ui)["documents"].back()["machine"], defaultMachine().name);
  ui->inspector().open(test::sourcePath("samples/transition-surface.nc"));
  waitForJobs(*ui);
  nlohmann::json state = described(*ui);
  EXPECT_EQ(state["documents"].back()["machine"], edited);
  EXPECT_EQ(state["machine_source"], "remembered for transition-surface.nc");
  ui->inspector().open(test::sourcePath("samples/cola-bottle-bottom.nc"));
  waitForJobs(*ui);
  state = described(*ui);
  EXPECT_EQ(state["documents"].back()["machine"], defaultMachine().name);
  EXPECT_EQ(state["machine_source"], "built-in default");
}

