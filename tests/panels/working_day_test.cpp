// A process engineer's working day in the window, drawn headless and driven with the mouse and
// the keys: the machine window (edit, simulate with it, save), a file that exists is replaced
// only when the user says so, measuring a distance, the value under a resting pointer, export,
// close, help.
#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cam_style_transition.h"
#include "image_compare.h"
#include "workflow_fixtures.h"
#include "isurface/io/biip.h"
#include "isurface/machine/machine.h"
#include "control_machines.h"
#include "isurface/panels/headless_ui.h"
#include "scratch_files.h"
#include "test_support.h"
#include "ui_driving.h"

using namespace isurface;
using test::click, test::clickControl, test::settle, test::tap, test::tapLetter, test::typeInto, test::described, test::waitForJobs;

namespace {

constexpr int kWidth = 1280, kHeight = 800;

std::size_t distinctColours(const test::Image& image) {
  std::vector<unsigned> colours;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
    colours.push_back(unsigned(image.rgb[i]) << 16 | unsigned(image.rgb[i + 1]) << 8 | image.rgb[i + 2]);
  std::sort(colours.begin(), colours.end());
  return static_cast<std::size_t>(std::unique(colours.begin(), colours.end()) - colours.begin());
}

std::unique_ptr<panels::HeadlessUi> openedSample() { return test::openedSample(kWidth, kHeight); }

}  // namespace

TEST(workingDay, TheMachineIsEditedSimulatedWithAndSaved) {
  auto ui = openedSample();
  const double before = described(*ui)["documents"][0]["duration_s"];
  tapLetter(*ui, 'M');
  ASSERT_TRUE(described(*ui)["windows"]["machine"].get<bool>());
  // Every axis at 1500 mm/min: the program's F3000 passes take twice as long.
  for (const char* axis : {"x", "y", "z"}) typeInto(*ui, std::string("machine.velocity.") + axis, "1500");
  clickControl(*ui, "machine.simulate");
  waitForJobs(*ui);
  const nlohmann::json state = described(*ui);
  EXPECT_DOUBLE_EQ(state["machine"]["axes"][0]["max_velocity_mm_s"].get<double>(), 25.0);
  EXPECT_EQ(state["machine_source"], "edited");
  // Named as a machine of its own, wherever the map and its exports name it.
  const std::string edited = defaultMachine().name + " (edited: X velocity, Y velocity, "
                             "Z velocity)";
  EXPECT_EQ(state["machine"]["name"], edited);
  EXPECT_EQ(state["documents"][0]["machine"], edited);
  const double after = state["documents"][0]["duration_s"];
  EXPECT_GT(after, before * 1.3) << "a slower machine takes longer";
  ASSERT_NE(ui->inspector().activeMachine(), nullptr);
  EXPECT_DOUBLE_EQ(ui->inspector().activeMachine()->axes[2].maxVelocity, 25.0);

  // Saved, it reads back as the same machine; a file that exists is asked about first.
  const std::filesystem::path path = test::scratchDir() / "edited-machine.json";
  std::ofstream(path) << "{}";
  typeInto(*ui, "machine.savePath", path.string());
  clickControl(*ui, "machine.save");
  ASSERT_TRUE(described(*ui)["windows"]["replace_question"].get<bool>());
  EXPECT_EQ(test::readFile(path.string()), "{}");  // not yet
  clickControl(*ui, "replace.yes");
  EXPECT_FALSE(described(*ui)["windows"]["replace_question"].get<bool>());
  EXPECT_EQ(described(*ui)["last_saved"], path.string());
  const Machine saved = loadMachine(path.string());
  EXPECT_DOUBLE_EQ(saved.axes[1].maxVelocity, 25.0);
  EXPECT_EQ(saved.name, edited);
  EXPECT_EQ(machineDescriptionJson(saved), machineDescriptionJson(ui->inspector().machine()));
}

TEST(workingDay, ReplacingAFileCanBeRefused) {
  auto ui = openedSample();
  tapLetter(*ui, 'M');
  const std::filesystem::path path = test::scratchDir() / "kept-machine.json";
  std::ofstream(path) << "{\"name\": \"kept\"}";
  typeInto(*ui, "machine.savePath", path.string());
  clickControl(*ui, "machine.save");
  ASSERT_TRUE(described(*ui)["windows"]["replace_question"].get<bool>());
  clickControl(*ui, "replace.no");
  EXPECT_EQ(test::readFile(path.string()), "{\"name\": \"kept\"}");
  EXPECT_EQ(described(*ui)["last_saved"], "");
}

TEST(workingDay, TwoClicksOnTheSurfaceMeasureTheirDistance) {
  auto ui = openedSample();
  const auto view = ui->inspector().controlRect("view");
  ASSERT_TRUE(view.has_value());
  const float cx = ((*view)[0] + (*view)[2]) * 0.5f, cy = ((*view)[1] + (*view)[3]) * 0.5f;
  tapLetter(*ui, 'D');
  ASSERT_TRUE(described(*ui)["measure"]["active"].get<bool>());
  click(*ui, cx - 60, cy);
  click(*ui, cx + 60, cy + 20);
  const nlohmann::json m = described(*ui)["measure"];
  ASSERT_TRUE(m.contains("distance_mm")) << m.dump();
  const Vec3 a(m["a"][0], m["a"][1], m["a"][2]), b(m["b"][0], m["b"][1], m["b"][2]);
  EXPECT_GT(m["distance_mm"].get<double>(), 1.0);
  EXPECT_NEAR(m["distance_mm"].get<double>(), (b - a).norm(), 1e-9);
  EXPECT_NE(ui->inspector().statusText().find("distance"), std::string::npos);
  // Measuring does not pick: the selection is as it was.
  EXPECT_FALSE(ui->inspector().selection().sample.has_value());
  tap(*ui, ImGuiKey_Escape);
  EXPECT_FALSE(described(*ui)["measure"]["active"].get<bool>());
}

TEST(workingDay, ThePointerRestingOnTheSurfaceShowsTheValueThere) {
  auto ui = openedSample();
  const auto view = ui->inspector().controlRect("view");
  ASSERT_TRUE(view.has_value());
  const float cx = ((*view)[0] + (*view)[2]) * 0.5f, cy = ((*view)[1] + (*view)[3]) * 0.5f;
  ui->mouse(cx - 5, cy, false);
  ui->frame();
  EXPECT_FALSE(described(*ui)["selection"].contains("hover_sample"));
  ui->mouse(cx, cy, false);
  settle(*ui, 8);
  const nlohmann::json sel = described(*ui)["selection"];
  ASSERT_TRUE(sel.contains("hover_sample"));
  EXPECT_FALSE(sel.contains("sample"));  // hovering does not select
  ui->mouse(cx + 40, cy, false);
  ui->frame();
  EXPECT_FALSE(described(*ui)["selection"].contains("hover_sample"));  // gone as the pointer moves
}

TEST(workingDay, ExportWritesTheViewFiguresAndSamples) {
  auto ui = openedSample();
  ASSERT_TRUE(ui->inspector().selectLine(2000));
  settle(*ui);
  const std::filesystem::path png = test::scratchDir() / "view-export.png";
  std::filesystem::remove(png);
  tapLetter(*ui, 'E', true);
  typeInto(*ui, "export.path", png.string());
  clickControl(*ui, "export.write");
  ASSERT_EQ(described(*ui)["last_saved"], png.string()) << ui->inspector().statusText();
  const test::Image image = test::readPng(png.string());
  EXPECT_EQ(image.width, 1920);
  EXPECT_EQ(image.height, 1080);
  EXPECT_GT(distinctColours(image), 50u) << "a map, not a blank image";

  const std::filesystem::path csv = test::scratchDir() / "line-2000.csv";
  std::filesystem::remove(csv);
  tapLetter(*ui, 'E', true);
  clickControl(*ui, "export.csv");
  // Another kind, its own extension: the CSV is not offered the view's name.
  EXPECT_EQ(described(*ui)["export_path"], (test::scratchDir() / "view-export.csv").string());
  typeInto(*ui, "export.path", csv.string());
  clickControl(*ui, "export.write");
  // The samples are written with their feedback, loaded first in the background (slower than a
  // few frames under the sanitizers): the user waits for it, as here.
  waitForJobs(*ui);
  ASSERT_EQ(described(*ui)["last_saved"], csv.string()) << ui->inspector().statusText();
  std::ifstream in(csv);
  std::string header, row;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("sample,t_s,line,x_mm,y_mm,z_mm,", 0), 0u) << header;
  std::size_t rows = 0;
  while (std::getline(in, row)) {
    ++rows;
    EXPECT_NE(row.find(",2000,"), std::string::npos) << row;  // only the selected line's samples
  }
  EXPECT_GT(rows, 0u);
}

TEST(workingDay, CloseAndHelp) {
  auto ui = openedSample();
  tapLetter(*ui, 'H');
  EXPECT_TRUE(described(*ui)["windows"]["help"].get<bool>());
  tapLetter(*ui, 'H');
  EXPECT_FALSE(described(*ui)["windows"]["help"].get<bool>());
  ASSERT_EQ(ui->inspector().documentCount(), 1u);
  tapLetter(*ui, 'W', true);
  EXPECT_EQ(ui->inspector().documentCount(), 0u);
  EXPECT_EQ(ui->inspector().activeMachine(), nullptr);
}

TEST(workingDay, OptimiseWithOnlyADumpSaysWhyInTheDialog) {
  panels::HeadlessUi ui(kWidth, kHeight, app_model::Settings{});
  ui.inspector().open(test::transitionDump());
  waitForJobs(ui);
  ASSERT_EQ(ui.inspector().documentCount(), 1u);
  tapLetter(ui, 'P');
  const nlohmann::json state = described(ui);
  EXPECT_TRUE(state["windows"]["optimise"].get<bool>()) << "the dialog stays open to say why";
  EXPECT_NE(state["optimise_problem"].get<std::string>().find("needs the G-code program"), std::string::npos)
      << state["optimise_problem"];
}

TEST(workingDay, ADumpCutShortWithNoSurfaceOpensAndSaysBoth) {
  const std::filesystem::path program = test::scratchDir() / "one-line.nc";
  std::ofstream(program) << "G21 G90\nG1 X20 F600\nM2\n";
  const std::string dump = (test::scratchDir() / "one-line-cut.biip").string();
  simulateToBiip(readProgram(program.string()), defaultMachine(), dump);
  std::filesystem::resize_file(dump, std::filesystem::file_size(dump) - 5);
  panels::HeadlessUi ui(kWidth, kHeight, app_model::Settings{});
  ui.inspector().open(dump);
  waitForJobs(ui);
  ASSERT_EQ(ui.inspector().documentCount(), 1u) << ui.inspector().statusText();
  const std::string status = ui.inspector().statusText();
  EXPECT_NE(status.find("cut short"), std::string::npos) << status;
  EXPECT_NE(status.find("no map: "), std::string::npos) << status;
  EXPECT_GT(described(ui)["documents"][0]["samples"].get<std::size_t>(), 100u);  // its rows and curves are there
}

TEST(workingDay, TheMainViewIsFittedAgainWhenAMapStandsBesideIt) {
  auto ui = openedSample();
  ui->inspector().optimise(105, 400);
  waitForJobs(*ui);
  settle(*ui);
  ASSERT_NE(ui->inspector().optimisedDifference(), nullptr) << ui->inspector().statusText();
  const nlohmann::json controls = described(*ui)["controls"];
  ASSERT_TRUE(controls.contains("surface") && controls.contains("view"));
  const auto view = controls["view"].get<std::array<float, 4>>();
  const auto surface = controls["surface"].get<std::array<float, 4>>();
  // Inside the narrower view, and filling it across or top to bottom.
  EXPECT_GE(surface[0], view[0] - 1);
  EXPECT_LE(surface[2], view[2] + 1);
  EXPECT_GE(surface[1], view[1] - 1);
  EXPECT_LE(surface[3], view[3] + 1);
  const float across = (surface[2] - surface[0]) / (view[2] - view[0]);
  const float down = (surface[3] - surface[1]) / (view[3] - view[1]);
  EXPECT_GT(std::max(across, down), 0.7f) << across << " " << down;
}

TEST(workingDay, TheFeedbackSurfaceInTurnWithTheCommandedOne) {
  panels::HeadlessUi ui(kWidth, kHeight, app_model::Settings{});
  ui.inspector().open({test::sourcePath("samples/transition-surface.nc"), test::transitionDump()});
  waitForJobs(ui);
  EXPECT_EQ(described(ui)["map"]["surface"], "commanded");
  clickControl(ui, "surface.feedback");
  waitForJobs(ui);
  const nlohmann::json map = described(ui)["map"];
  EXPECT_EQ(map["surface"], "feedback");
  EXPECT_NE(map["caption"].get<std::string>().find("feedback surface"), std::string::npos) << map["caption"];
}

TEST(workingDay, AnInchProgramIsShownInInches) {
  const std::filesystem::path inch = test::scratchDir() / "inch-raster.nc";
  {
    std::ofstream out(inch);
    out << "G20 G90 G17\nG0 X0 Y0 Z0.1\nG1 Z0 F40\n";
    for (int row = 0; row < 12; ++row)
      out << "G1 X" << (row % 2 ? 0 : 2) << " Y" << row * 0.02 << "\nG1 Y" << (row + 1) * 0.02 << "\n";
    out << "M2\n";
  }
  panels::HeadlessUi ui(kWidth, kHeight, app_model::Settings{});
  ui.inspector().open(inch.string());
  waitForJobs(ui);
  EXPECT_EQ(described(ui)["length_unit"], "in");
  EXPECT_EQ(described(ui)["map"]["unit"], "in/min");  // the legend too
  EXPECT_EQ(described(ui)["colour"]["unit"], "in/min");  // and the Colour panel
  ui.inspector().settings().units = "mm";  // the user's choice stands over the program's
  settle(ui);
  EXPECT_EQ(described(ui)["length_unit"], "mm");
  EXPECT_EQ(described(ui)["colour"]["unit"], "mm/min");
  ui.inspector().settings().units = "auto";
  ui.inspector().open(test::sourcePath("samples/transition-surface.nc"));
  waitForJobs(ui);
  EXPECT_EQ(described(ui)["length_unit"], "mm");
}

TEST(workingDay, ThemeAndSizeAreChosenAndRemembered) {
  app_model::Settings settings;
  settings.theme = "light";
  settings.uiScale = 1.5f;
  panels::HeadlessUi ui(kWidth, kHeight, settings);
  settle(ui);
  EXPECT_FLOAT_EQ(ImGui::GetIO().FontGlobalScale, 1.5f);
  EXPECT_GT(ImGui::GetStyle().Colors[ImGuiCol_WindowBg].x, 0.8f) << "a light window background";
  EXPECT_EQ(described(ui)["theme"], "light");
}

TEST(workingDay, TheOpenDialogBrowsesFoldersAndOpensAFile) {
  panels::HeadlessUi ui(kWidth, kHeight, app_model::Settings{});
  settle(ui);
  tapLetter(ui, 'O', true);  // Ctrl+O, as File > Open and the window's help say; O alone too
  // A folder typed and entered lists it; a file typed and entered opens.
  typeInto(ui, "open.path", test::sourcePath("samples"));
  tap(ui, ImGuiKey_Enter);
  EXPECT_EQ(ui.inspector().documentCount(), 0u);
  typeInto(ui, "open.path", test::sourcePath("samples/transition-surface.nc"));
  clickControl(ui, "open.open");
  waitForJobs(ui);
  ASSERT_EQ(ui.inspector().documentCount(), 1u) << ui.inspector().statusText();
  EXPECT_EQ(described(ui)["documents"][0]["name"], "transition-surface.nc");
}

TEST(workingDay, TheScaleBarAgreesWithAMeasuredDistance) {
  auto ui = openedSample();
  tapLetter(*ui, 'T');  // from the top: screen distances are workpiece distances
  settle(*ui);
  const nlohmann::json bar = described(*ui)["scale_bar"];
  ASSERT_GT(bar["pixels"].get<double>(), 20.0);
  EXPECT_EQ(bar["unit"], "mm");
  const double mmPerPixel = bar["length"].get<double>() / bar["pixels"].get<double>();
  const auto surface = described(*ui)["controls"]["surface"].get<std::array<float, 4>>();
  const float cy = (surface[1] + surface[3]) / 2, cx = (surface[0] + surface[2]) / 2;
  tapLetter(*ui, 'D');
  click(*ui, cx - 100, cy);
  click(*ui, cx + 100, cy);
  const nlohmann::json m = described(*ui)["measure"];
  ASSERT_TRUE(m.contains("distance_mm")) << m.dump();
  const double across = std::hypot(m["b"][0].get<double>() - m["a"][0].get<double>(),
                                   m["b"][1].get<double>() - m["a"][1].get<double>());
  EXPECT_NEAR(across, 200 * mmPerPixel, 0.15 * across);
}

TEST(workingDay, TheMapsFiguresExportAsJson) {
  auto ui = openedSample();
  const std::filesystem::path json = test::scratchDir() / "map-figures.json";
  std::filesystem::remove(json);
  tapLetter(*ui, 'E', true);
  clickControl(*ui, "export.json");
  typeInto(*ui, "export.path", json.string());
  clickControl(*ui, "export.write");
  // The figures include the predicted deviation: the dump's feedback is loaded first, in the
  // background, and the file is written when it is in.
  waitForJobs(*ui);
  ASSERT_EQ(described(*ui)["last_saved"], json.string()) << ui->inspector().statusText();
  const nlohmann::json figures = nlohmann::json::parse(test::readFile(json.string()));
  EXPECT_EQ(figures["quantity"], "Path speed");
  EXPECT_EQ(figures["unit"], "mm/min");
  EXPECT_GT(figures["samples"].get<std::size_t>(), 100000u);
  EXPECT_GT(figures["machining_time_s"].get<double>(), 100.0);
  EXPECT_LE(figures["values"]["p1"].get<double>(), figures["values"]["median"].get<double>());
  EXPECT_LE(figures["values"]["median"].get<double>(), figures["values"]["p99"].get<double>());
  // The map's 1-99 % range is its values' 1st and 99th percentiles, to the digit.
  EXPECT_EQ(figures["values"]["p1"].get<double>(), figures["colour_range"][0].get<double>());
  EXPECT_EQ(figures["values"]["p99"].get<double>(), figures["colour_range"][1].get<double>());
  EXPECT_GT(figures["figures"]["speed_fluctuation_mm_min"].get<double>(), 0.0);
}

TEST(workingDay, EscClosesWhatItIsPressedInAndCancelsNothingElse) {
  auto ui = openedSample();
  tapLetter(*ui, 'M');
  typeInto(*ui, "machine.velocity.x", "1500");
  tap(*ui, ImGuiKey_Enter);
  // M again, with the window open: the edit stays.
  tapLetter(*ui, 'M');
  EXPECT_DOUBLE_EQ(described(*ui)["machine_edited"]["axes"][0]["max_velocity_mm_s"].get<double>(), 25.0);
  clickControl(*ui, "machine.simulate");
  tap(*ui, ImGuiKey_Escape);  // closes the machine window; the simulation goes on
  waitForJobs(*ui);
  EXPECT_EQ(ui->inspector().statusText().find("cancelled"), std::string::npos) << ui->inspector().statusText();
  EXPECT_FALSE(described(*ui)["windows"]["machine"].get<bool>());
  EXPECT_DOUBLE_EQ(described(*ui)["machine"]["axes"][0]["max_velocity_mm_s"].get<double>(), 25.0);
}

TEST(workingDay, AFixedRangeStartsAsTheRangeShown) {
  auto ui = openedSample();
  ui->inspector().colourBy("accel");
  waitForJobs(*ui);
  const nlohmann::json shown = described(*ui)["map"];
  clickControl(*ui, "range.fixed");
  waitForJobs(*ui);
  const nlohmann::json colour = described(*ui)["colour"];
  EXPECT_EQ(colour["range_mode"], 2);
  // Not 0 .. 3000 whatever the quantity: the acceleration range the map showed (symmetric here).
  EXPECT_LT(colour["fixed"][0].get<double>(), -100.0);
  EXPECT_GT(colour["fixed"][1].get<double>(), 100.0);
  EXPECT_NEAR(colour["fixed"][0].get<double>(), -colour["fixed"][1].get<double>(), 1e-3);
  EXPECT_EQ(shown["quantity"], "Tangential acceleration");
}

TEST(workingDay, LocateStartsAtTheSelectionAndSaysWhenARequestIsOutOfRange) {
  auto ui = openedSample();
  ASSERT_TRUE(ui->inspector().selectLine(2000));
  settle(*ui);
  const std::size_t sample = *ui->inspector().selection().sample;
  tapLetter(*ui, 'L', true);
  nlohmann::json locate = described(*ui)["locate"];
  EXPECT_EQ(locate["sample"].get<std::size_t>(), sample);
  EXPECT_EQ(locate["line"], 2000);
  typeInto(*ui, "locate.sample", "999999999");
  clickControl(*ui, "locate.goSample");
  locate = described(*ui)["locate"];
  EXPECT_NE(locate["message"].get<std::string>().find("out of range"), std::string::npos) << locate.dump();
  EXPECT_EQ(*ui->inspector().selection().sample, sample);  // nothing else moved
  typeInto(*ui, "locate.sample", "1234");
  tap(*ui, ImGuiKey_Enter);
  EXPECT_EQ(*ui->inspector().selection().sample, 1234u);
}

TEST(workingDay, ARecentFileClickedOpensThatFile) {
  app_model::Settings settings;
  settings.addRecent(test::sourcePath("samples/transition-surface.nc"));
  panels::HeadlessUi ui(kWidth, kHeight, settings);
  settle(ui);
  clickControl(ui, "menu.file");
  const auto recent = ui.inspector().controlRect("menu.recent");
  ASSERT_TRUE(recent.has_value());
  ui.mouse(((*recent)[0] + (*recent)[2]) / 2, ((*recent)[1] + (*recent)[3]) / 2, false);  // the submenu opens on hover
  settle(ui, 4);
  clickControl(ui, "recent.0");
  waitForJobs(ui);
  ASSERT_EQ(ui.inspector().documentCount(), 1u) << ui.inspector().statusText();
  EXPECT_EQ(described(ui)["documents"][0]["program"], test::sourcePath("samples/transition-surface.nc"));
}

// Letters typed while a dialog is open and no field of it has the keyboard are not shortcuts:
// a window opened behind an open dialog (H: help, M: machine) stopped the program (Dear ImGui
// 1.86 asserts that a window appearing under a modal has one to go behind).
TEST(workingDay, ShortcutsWaitWhileADialogIsOpen) {
  auto ui = openedSample();
  tapLetter(*ui, 'E', true);
  ASSERT_TRUE(described(*ui)["controls"].contains("export.write"));
  for (char letter : {'H', 'M', 'P', 'D', 'O'}) tapLetter(*ui, letter);
  const nlohmann::json windows = described(*ui)["windows"];
  EXPECT_FALSE(windows["help"].get<bool>());
  EXPECT_FALSE(windows["machine"].get<bool>());
  EXPECT_FALSE(windows["optimise"].get<bool>());
  EXPECT_TRUE(described(*ui)["controls"].contains("export.write")) << "the export dialog closed";
}

// A drag turns the camera as VTK's trackball does at the view's full size (200 degrees over
// the view's width), though the view is drawn smaller while it is dragged.
TEST(workingDay, DraggingTurnsTheCameraByTheTrackballsAngle) {
  auto ui = openedSample();
  tapLetter(*ui, 'T');
  settle(*ui);
  const auto view = described(*ui)["controls"]["view"].get<std::array<float, 4>>();
  const float width = view[2] - view[0], cx = (view[0] + view[2]) / 2, cy = (view[1] + view[3]) / 2;
  auto direction = [&] {
    const nlohmann::json c = described(*ui)["camera"];
    auto point = [](const nlohmann::json& p) { return Vec3(p[0].get<double>(), p[1].get<double>(), p[2].get<double>()); };
    const Vec3 position = point(c["position"]), focal = point(c["focal_point"]);
    return Vec3((focal - position).normalized());
  };
  const Vec3 before = direction();
  const float dx = 0.2f * width;  // 40 degrees
  ui->mouse(cx, cy, false);
  ui->frame();
  ui->mouse(cx, cy, true);
  ui->frame();
  for (int step = 1; step <= 8; ++step) {
    ui->mouse(cx + dx * step / 8, cy, true);
    ui->frame();
  }
  ui->mouse(cx + dx, cy, false);
  settle(*ui);
  const double turned = std::acos(std::clamp(before.dot(direction()), -1.0, 1.0)) * 180.0 / M_PI;
  EXPECT_NEAR(turned, 200.0 * dx / width, 4.0);
}

// Esc closes the Help window, as its own list of keys says.
TEST(workingDay, EscapeClosesHelp) {
  auto ui = openedSample();
  tapLetter(*ui, 'H');
  ASSERT_TRUE(described(*ui)["windows"]["help"].get<bool>());
  tap(*ui, ImGuiKey_Escape);
  EXPECT_FALSE(described(*ui)["windows"]["help"].get<bool>());
}

// Esc closes Locate too, also after it has gone somewhere.
TEST(workingDay, EscapeClosesLocate) {
  auto ui = openedSample();
  tapLetter(*ui, 'L', true);
  ASSERT_TRUE(described(*ui)["windows"]["locate"].get<bool>());
  clickControl(*ui, "locate.goSample");
  tap(*ui, ImGuiKey_Escape);
  EXPECT_FALSE(described(*ui)["windows"]["locate"].get<bool>());
}

// Simulated again with another machine, the program keeps the line the user had picked.
TEST(workingDay, SimulatingAgainKeepsThePickedLine) {
  auto ui = openedSample();
  ASSERT_TRUE(ui->inspector().selectLine(2000));
  settle(*ui, 2);
  tapLetter(*ui, 'M');
  clickControl(*ui, "machine.chordSmoothing");
  clickControl(*ui, "machine.simulate");
  waitForJobs(*ui);
  EXPECT_EQ(described(*ui)["selection"]["line"], 2000);
}

// A control without a compressor, chosen in the machine window: the transition's chords are
// braked for, so the same program takes longer and is named as run on an edited machine.
TEST(workingDay, TheMachinesChordSmoothingIsSwitchedOffInTheWindow) {
  auto ui = openedSample();
  const double smoothed = described(*ui)["documents"][0]["duration_s"];
  tapLetter(*ui, 'M');
  clickControl(*ui, "machine.chordSmoothing");
  clickControl(*ui, "machine.simulate");
  waitForJobs(*ui);
  ASSERT_NE(ui->inspector().activeMachine(), nullptr);
  EXPECT_FALSE(ui->inspector().activeMachine()->control.chordSmoothing);
  const nlohmann::json state = described(*ui);
  EXPECT_EQ(state["documents"][0]["machine"], defaultMachine().name + " (edited: chord smoothing)");
  EXPECT_GT(state["documents"][0]["duration_s"].get<double>(), smoothed);
}

// A kept program that was not saved lives only in the window: Close asks before letting it go,
// and once it is saved Close closes.
TEST(workingDay, AKeptProgramIsNotClosedUnsavedWithoutAsking) {
  // The CAM-style program's fillet (its worst region's lines), which the closed loop keeps on a
  // control that brakes at its chords.
  auto ui = std::make_unique<panels::HeadlessUi>(kWidth, kHeight, app_model::Settings{});
  ui->inspector().useMachine(test::machineWithoutChordSmoothing(), test::kMachineWithoutChordSmoothing);
  ui->inspector().open(test::writeScratch("cam-style-kept.nc", isurface::testing::camStyleTransitionProgram()));
  waitForJobs(*ui);
  ui->inspector().optimise(10, 617);
  waitForJobs(*ui);
  ASSERT_TRUE(described(*ui)["optimised"]["kept"].get<bool>()) << ui->inspector().statusText();
  clickControl(*ui, "optimised.close");
  ASSERT_FALSE(described(*ui)["optimised"].is_null()) << "closed without asking";
  EXPECT_TRUE(described(*ui)["optimised"]["discard_question"].get<bool>());
  clickControl(*ui, "discard.no");
  ASSERT_FALSE(described(*ui)["optimised"].is_null());
  EXPECT_FALSE(described(*ui)["optimised"]["discard_question"].get<bool>());
  clickControl(*ui, "optimised.close");
  clickControl(*ui, "discard.yes");
  EXPECT_TRUE(described(*ui)["optimised"].is_null());

  ui->inspector().optimise(10, 617);
  waitForJobs(*ui);
  // Optimising again would replace it: the dialog says so before Optimise is pressed.
  tapLetter(*ui, 'P');
  ASSERT_TRUE(described(*ui)["windows"]["optimise"].get<bool>());
  EXPECT_NE(described(*ui)["optimise_replaces"].get<std::string>().find("lines 10-617 is kept but not saved"),
            std::string::npos);
  tap(*ui, ImGuiKey_Escape);
  ASSERT_FALSE(described(*ui)["windows"]["optimise"].get<bool>());
  const std::filesystem::path path = test::scratchDir() / "kept-before-closing.nc";
  std::filesystem::remove(path);
  typeInto(*ui, "optimised.path", path.string());
  clickControl(*ui, "optimised.save");
  ASSERT_TRUE(std::filesystem::exists(path)) << ui->inspector().statusText();
  EXPECT_TRUE(described(*ui)["optimised"]["saved"].get<bool>());
  tapLetter(*ui, 'P');
  EXPECT_EQ(described(*ui)["optimise_replaces"].get<std::string>(), "") << "saved: nothing is lost";
  tap(*ui, ImGuiKey_Escape);
  clickControl(*ui, "optimised.close");
  EXPECT_TRUE(described(*ui)["optimised"].is_null()) << "saved: nothing to ask";
}

// The Open dialog takes what is typed at once: a path typed right after O is not lost to a
// field that has not been clicked.
TEST(workingDay, APathTypedRightAfterOpeningGoesIntoTheOpenDialog) {
  auto ui = openedSample();
  // As the window sees a quick typist: the O key's press, then (a frame later, as the window
  // holds characters that come after a shortcut) its own "o" with the first typed character,
  // then one character a frame while the dialog opens and its field takes the keyboard.
  const auto typeQuickly = [&](const std::string& path) {
    ui->letter('O', true);
    ui->frame();
    ui->letter('O', false);
    ui->type("o" + path.substr(0, 1));
    ui->frame();
    for (std::size_t i = 1; i < path.size(); ++i) {
      ui->type(path.substr(i, 1));
      ui->frame();
    }
    settle(*ui, 2);
  };
  typeQuickly("/tmp/program.nc");
  nlohmann::json state = described(*ui);
  EXPECT_EQ(state["open_path"].get<std::string>(), "/tmp/program.nc");
  EXPECT_EQ(state["colour"]["view"], "iso") << "the t of tmp ran the Top shortcut";
  // Opened again, what is typed replaces the path left from before (the first Esc leaves the
  // field, the second closes the dialog).
  tap(*ui, ImGuiKey_Escape);
  tap(*ui, ImGuiKey_Escape);
  typeQuickly("/tmp/other.nc");
  EXPECT_EQ(described(*ui)["open_path"].get<std::string>(), "/tmp/other.nc");
}

// Ctrl+F and the text typed right after it: all of it is looked for.
TEST(workingDay, TextTypedRightAfterCtrlFIsLookedFor) {
  auto ui = openedSample();
  ui->ctrl(true);
  ui->letter('F', true);
  ui->frame();
  ui->letter('F', false);
  ui->ctrl(false);
  for (const char c : std::string("Y22.9")) {
    ui->type(std::string(1, c));
    ui->frame();
  }
  settle(*ui, 2);
  EXPECT_EQ(described(*ui)["gcode_search_text"], "Y22.9");
}

// A program whose surface covers little of its path (a test of moves, not a finish) keeps a
// warning that says so and what may fill it, and the Colour panel says it too.
TEST(workingDay, ASurfaceOnLittleOfThePathIsSaid) {
  auto ui = std::make_unique<panels::HeadlessUi>(kWidth, kHeight, app_model::Settings{});
  ui->inspector().open(test::realdataPath("linuxcnc_test.ngc"));
  waitForJobs(*ui);
  const nlohmann::json warnings = described(*ui)["documents"][0]["warnings"];
  bool said = false;
  for (const auto& w : warnings)
    said |= w.get<std::string>().find("of the cutting path lies on the surface") != std::string::npos &&
            w.get<std::string>().find("Colour panel") != std::string::npos;
  EXPECT_TRUE(said) << warnings;
}
