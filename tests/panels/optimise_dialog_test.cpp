// The Optimise dialog driven as a user does: where its lines start, what it says of lines that
// cannot run, and the region it holds between one opening and the next.
#include <gtest/gtest.h>
#include <imgui.h>

#include <nlohmann/json.hpp>

#include "isurface/panels/headless_ui.h"
#include "test_support.h"
#include "ui_driving.h"
#include "control_machines.h"

using namespace isurface;
using test::clickControl, test::tap, test::tapLetter, test::typeInto, test::described, test::waitForJobs;

namespace {

std::unique_ptr<panels::HeadlessUi> opened(const std::string& sample) {
  auto ui = std::make_unique<panels::HeadlessUi>(1280, 800, app_model::Settings{});
  ui->inspector().open(test::sourcePath("samples/" + sample));
  waitForJobs(*ui);
  return ui;
}

std::unique_ptr<panels::HeadlessUi> openedSample() { return opened("transition-surface.nc"); }

// The transition sample simulated on a control that brakes at its chords, where its transition
// is the worst region (control_machines.h).
std::unique_ptr<panels::HeadlessUi> openedOnABrakingControl() {
  auto ui = std::make_unique<panels::HeadlessUi>(1280, 800, app_model::Settings{});
  ui->inspector().useMachine(test::machineWithoutChordSmoothing(), test::kMachineWithoutChordSmoothing);
  ui->inspector().open(test::sourcePath("samples/transition-surface.nc"));
  waitForJobs(*ui);
  return ui;
}

}  // namespace

// Optimise opened with a line selected starts at that line's pass; a range chosen stays.
TEST(optimiseDialog, StartsAtTheSelectedLinesPass) {
  auto ui = openedSample();
  ASSERT_TRUE(ui->inspector().selectLine(2000));
  tapLetter(*ui, 'P');
  nlohmann::json state = described(*ui);
  ASSERT_TRUE(state["windows"]["optimise"].get<bool>());
  const auto lines = state["optimise_lines"].get<std::vector<int>>();
  EXPECT_LE(lines[0], 2000);
  EXPECT_GE(lines[1], 2000);
  EXPECT_GT(lines[1], lines[0]) << "a whole pass, not one line";
  tap(*ui, ImGuiKey_Escape);
  ASSERT_FALSE(described(*ui)["windows"]["optimise"].get<bool>());
  ASSERT_TRUE(ui->inspector().selectLine(20));
  tapLetter(*ui, 'P');
  ASSERT_TRUE(described(*ui)["windows"]["optimise"].get<bool>());
  EXPECT_EQ(described(*ui)["optimise_lines"].get<std::vector<int>>(), lines) << "the range chosen before stays";
}

// Lines typed the wrong way round are said to be so, and Optimise starts nothing: a click that
// did nothing would leave the user guessing.
TEST(optimiseDialog, SaysWhyLinesTypedBackwardsCannotRun) {
  auto ui = openedSample();
  tapLetter(*ui, 'P');
  ASSERT_TRUE(described(*ui)["windows"]["optimise"].get<bool>());
  EXPECT_EQ(described(*ui)["optimise_range_problem"].get<std::string>(), "");
  typeInto(*ui, "optimise.first", "400");
  typeInto(*ui, "optimise.last", "40");
  ASSERT_EQ(described(*ui)["optimise_lines"].get<std::vector<int>>(), (std::vector<int>{400, 40}));
  EXPECT_NE(described(*ui)["optimise_range_problem"].get<std::string>().find("before the first"), std::string::npos);
  clickControl(*ui, "optimise.run");
  waitForJobs(*ui);
  const nlohmann::json state = described(*ui);
  EXPECT_TRUE(state["windows"]["optimise"].get<bool>()) << "nothing started: the dialog stays open";
  EXPECT_TRUE(state["optimised"].is_null());
  typeInto(*ui, "optimise.first", "20");
  EXPECT_EQ(described(*ui)["optimise_range_problem"].get<std::string>(), "");
}

// A region chosen (here the whole program, its box the figures' box) is still the dialog's when
// it opens again: closed and reopened, the figures would otherwise silently be taken elsewhere.
// Another program's lines mean other moves: with another program active the dialog starts anew.
TEST(optimiseDialog, TheRegionChosenStaysForTheNextOpeningOfTheSameProgram) {
  auto ui = openedSample();
  tapLetter(*ui, 'P');
  ASSERT_TRUE(described(*ui)["windows"]["optimise"].get<bool>());
  EXPECT_TRUE(described(*ui)["optimise_box"].is_null()) << "no region chosen yet";
  clickControl(*ui, "optimise.whole");
  const nlohmann::json chosen = described(*ui);
  ASSERT_FALSE(chosen["optimise_box"].is_null()) << chosen["status"];
  EXPECT_GT(chosen["optimise_box"]["samples"].get<std::size_t>(), 1000u);
  EXPECT_EQ(chosen["optimise_box"]["lines"], chosen["optimise_lines"]);
  tap(*ui, ImGuiKey_Escape);
  ASSERT_FALSE(described(*ui)["windows"]["optimise"].get<bool>());
  ASSERT_TRUE(ui->inspector().selectLine(2000));  // a selection does not move a range already chosen
  tapLetter(*ui, 'P');
  const nlohmann::json reopened = described(*ui);
  ASSERT_TRUE(reopened["windows"]["optimise"].get<bool>());
  EXPECT_EQ(reopened["optimise_box"], chosen["optimise_box"]);
  EXPECT_EQ(reopened["optimise_lines"], chosen["optimise_lines"]);
  tap(*ui, ImGuiKey_Escape);

  ui->inspector().open(test::sourcePath("samples/wuzhishan.nc"));
  waitForJobs(*ui);
  tapLetter(*ui, 'P');
  const nlohmann::json other = described(*ui);
  ASSERT_TRUE(other["windows"]["optimise"].get<bool>());
  EXPECT_TRUE(other["optimise_box"].is_null()) << "the other program's box";
  EXPECT_EQ(other["optimise_lines"].get<std::vector<int>>(), (std::vector<int>{1, 1}));
}

// "Worst predicted region" holds what `optimize --auto` would take: whole passes, the figures'
// box around the defects, said in the status.
TEST(optimiseDialog, TheWorstPredictedRegionIsHeldWithItsBox) {
  auto ui = openedOnABrakingControl();
  tapLetter(*ui, 'P');
  clickControl(*ui, "optimise.worst");
  waitForJobs(*ui);  // the predicted deviation needs the feedback first
  const nlohmann::json state = described(*ui);
  ASSERT_TRUE(state["windows"]["optimise"].get<bool>());
  ASSERT_FALSE(state["optimise_box"].is_null()) << state["status"];
  EXPECT_EQ(state["optimise_box"]["lines"], state["optimise_lines"]);
  const auto lines = state["optimise_lines"].get<std::vector<int>>();
  EXPECT_GT(lines[1] - lines[0], 100) << "several whole passes";
  EXPECT_EQ(state["status"].get<std::string>().rfind("worst predicted region: lines ", 0), 0u) << state["status"];
  // Why it spans more than the box, and what it costs: the share of the run every plan simulates.
  EXPECT_NE(state["status"].get<std::string>().find("with every pass joined to it"), std::string::npos) << state["status"];
  // Why it is not the first of the worst regions list when that one lies where passes end.
  EXPECT_NE(state["status"].get<std::string>().find("regions at pass ends left out"), std::string::npos) << state["status"];
  EXPECT_GT(state["optimise_time_share"].get<double>(), 0.05);
  EXPECT_LE(state["optimise_time_share"].get<double>(), 1.0);
  EXPECT_LT(state["optimise_box"]["lower"][0].get<double>(), state["optimise_box"]["upper"][0].get<double>());
}

// The worst region widened to every pass joined to it can be most of a program; the passes it
// lies on alone are a click away, with their cost, and the box still stands for them (the figures
// are taken in it). A second click goes back to the widened lines.
TEST(optimiseDialog, TheWorstRegionCanBeOptimisedOnThePassesItLiesOnAlone) {
  auto ui = openedOnABrakingControl();
  tapLetter(*ui, 'P');
  clickControl(*ui, "optimise.worst");
  waitForJobs(*ui);
  nlohmann::json state = described(*ui);
  ASSERT_FALSE(state["optimise_box"].is_null()) << state["status"];
  const auto widened = state["optimise_lines"].get<std::vector<int>>();
  const auto own = state["optimise_box"]["own_passes"].get<std::vector<int>>();
  ASSERT_LT(own[1] - own[0], widened[1] - widened[0]) << "the transition's worst region is widened";
  EXPECT_GE(own[0], widened[0]);
  EXPECT_LE(own[1], widened[1]);
  const double widenedShare = state["optimise_time_share"].get<double>();

  clickControl(*ui, "optimise.width");
  state = described(*ui);
  EXPECT_EQ(state["optimise_lines"].get<std::vector<int>>(), own);
  EXPECT_LT(state["optimise_time_share"].get<double>(), widenedShare);
  EXPECT_FALSE(state["optimise_box"].is_null()) << "the box stands for the passes it lies on too";

  clickControl(*ui, "optimise.width");
  EXPECT_EQ(described(*ui)["optimise_lines"].get<std::vector<int>>(), widened);
}
