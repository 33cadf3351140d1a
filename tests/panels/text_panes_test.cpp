// The G-code pane and the data bar driven with the mouse and the keys, drawn headless: a row
// clicked stays selected and under the pointer, and the keys step through the rows.
#include <gtest/gtest.h>
#include <imgui.h>

#include "isurface/panels/headless_ui.h"
#include "test_support.h"
#include "ui_driving.h"

using namespace isurface;
using test::click, test::tap;

namespace {

constexpr int kWidth = 1280, kHeight = 800;
// Inside the G-code pane (right of 70 % of the width, the upper 45 % below the toolbar) and the
// data bar under it.
constexpr float kGcodeX = 960, kGcodeY = 220, kDataX = 960, kDataY = 600;

std::uint32_t selectedLine(panels::HeadlessUi& ui) { return ui.inspector().selection().line.value_or(0); }

std::unique_ptr<panels::HeadlessUi> openedSample() {
  auto ui = std::make_unique<panels::HeadlessUi>(kWidth, kHeight, app_model::Settings{});
  ui->inspector().open(test::sourcePath("samples/wuzhishan.nc"));
  ui->inspector().waitUntilIdle();
  for (int i = 0; i < 3; ++i) ui->frame();
  return ui;
}

}  // namespace

TEST(textPanes, AGcodeRowClickedAgainStaysSelected) {
  auto ui = openedSample();
  ASSERT_TRUE(ui->inspector().selectLine(1725));
  for (int i = 0; i < 3; ++i) ui->frame();
  click(*ui, kGcodeX, kGcodeY);
  const std::uint32_t first = selectedLine(*ui);
  ASSERT_GT(first, 0u);
  EXPECT_NEAR(static_cast<double>(first), 1725.0, 40.0);  // a row of the page the selection scrolled to
  click(*ui, kGcodeX, kGcodeY);
  EXPECT_EQ(selectedLine(*ui), first);
  click(*ui, kGcodeX, kGcodeY);
  EXPECT_EQ(selectedLine(*ui), first);
}

TEST(textPanes, TheKeysStepThroughTheGcodeLines) {
  auto ui = openedSample();
  ASSERT_TRUE(ui->inspector().selectLine(1725));
  for (int i = 0; i < 3; ++i) ui->frame();
  click(*ui, kGcodeX, kGcodeY);
  const std::uint32_t first = selectedLine(*ui);
  tap(*ui, ImGuiKey_DownArrow);
  EXPECT_EQ(selectedLine(*ui), first + 1);
  tap(*ui, ImGuiKey_UpArrow);
  tap(*ui, ImGuiKey_UpArrow);
  EXPECT_EQ(selectedLine(*ui), first - 1);
  tap(*ui, ImGuiKey_PageDown);
  const std::uint32_t paged = selectedLine(*ui);
  EXPECT_GT(paged, first + 5);
  tap(*ui, ImGuiKey_PageUp);
  EXPECT_EQ(selectedLine(*ui), first - 1);
  tap(*ui, ImGuiKey_Home);
  EXPECT_EQ(selectedLine(*ui), 1u);
  tap(*ui, ImGuiKey_End);
  EXPECT_GT(selectedLine(*ui), 2316u);  // the last line of the program
  // Stepping down from a line near the bottom of the view scrolls by rows, not to the middle:
  // the row under the pointer after one more step down is the next line.
  ASSERT_TRUE(ui->inspector().selectLine(1725));
  for (int i = 0; i < 3; ++i) ui->frame();
  click(*ui, kGcodeX, kGcodeY);
  for (int i = 0; i < 30; ++i) tap(*ui, ImGuiKey_DownArrow);
  EXPECT_EQ(selectedLine(*ui), first + 30);
}

TEST(textPanes, TheKeysStepThroughTheSamplesInTheDataBar) {
  auto ui = openedSample();
  ASSERT_TRUE(ui->inspector().selectLine(1725));
  for (int i = 0; i < 3; ++i) ui->frame();
  click(*ui, kDataX, kDataY);
  ASSERT_TRUE(ui->inspector().selection().sample.has_value());
  const std::size_t sample = *ui->inspector().selection().sample;
  click(*ui, kDataX, kDataY);
  EXPECT_EQ(*ui->inspector().selection().sample, sample);  // the clicked row stays
  tap(*ui, ImGuiKey_DownArrow);
  EXPECT_EQ(*ui->inspector().selection().sample, sample + 1);
  tap(*ui, ImGuiKey_Home);
  EXPECT_EQ(*ui->inspector().selection().sample, 0u);
}
