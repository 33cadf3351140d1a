// Passes further apart than the 2 mm a finishing map joins (a roughing raster, a finishing one
// with a wide step-over), in the window: the gap typed into the Colour panel joins them, and
// what is measured on the surface (an optimisation's figures, a report) joins them alike.
#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>

#include "isurface/panels/headless_ui.h"
#include "test_support.h"
#include "ui_driving.h"

using namespace isurface;
using test::clickControl, test::settle, test::tap, test::tapLetter, test::typeInto, test::described, test::waitForJobs;

namespace {

constexpr int kWidth = 1280, kHeight = 800;

// The figure after `name` in an optimisation's summary ("... p99 17.6 -> 108.9 ...").
double figureBefore(const std::string& summary, const std::string& name) {
  const std::size_t at = summary.find(name);
  return at == std::string::npos ? -1.0 : std::stod(summary.substr(at + name.size()));
}

}  // namespace

TEST(wideStepOver, PassesFurtherApartThanTheGapAreJoinedOnceItIsRaised) {
  // A roughing-like raster, its passes 4 mm apart: more than the 2 mm a finishing map joins.
  const std::filesystem::path program = test::scratchDir() / "wide-step-over.nc";
  {
    std::ofstream out(program);
    out << "G21 G90\nG0 X0 Y0 Z1\nG1 Z0 F1200\n";
    for (int pass = 0; pass < 8; ++pass) out << "G1 X" << (pass % 2 == 0 ? 40 : 0) << "\nG1 Y" << 4 * (pass + 1) << "\n";
    out << "G0 Z5\nM2\n";
  }
  panels::HeadlessUi ui(kWidth, kHeight, app_model::Settings{});
  ui.inspector().open(program.string());
  waitForJobs(ui);
  EXPECT_TRUE(described(ui)["map"].empty());
  EXPECT_NE(ui.inspector().statusText().find("too far apart"), std::string::npos) << ui.inspector().statusText();
  // The empty view says why too, not to open what is open.
  const std::string viewText = described(ui)["view_text"];
  EXPECT_EQ(viewText.rfind("no map: ", 0), 0u) << viewText;
  EXPECT_NE(viewText.find("Colour panel"), std::string::npos) << viewText;
  // A gap raised but not enough: the view says so at the gap typed.
  typeInto(ui, "surface.gap", "2.5");
  tap(ui, ImGuiKey_Enter);
  waitForJobs(ui);
  EXPECT_TRUE(described(ui)["map"].empty());
  EXPECT_NE(described(ui)["view_text"].get<std::string>().find("gap limit 2.5 mm"), std::string::npos)
      << described(ui)["view_text"];

  typeInto(ui, "surface.gap", "5");
  tap(ui, ImGuiKey_Enter);
  waitForJobs(ui);
  const nlohmann::json state = described(ui);
  EXPECT_DOUBLE_EQ(state["colour"]["gap_limit_mm"].get<double>(), 5.0);
  ASSERT_FALSE(state["map"].empty()) << ui.inspector().statusText();
  EXPECT_GT(state["map"]["vertices"].get<std::size_t>(), 100u);
  EXPECT_EQ(state["view_text"], "");

  // A report made from the window joins the passes as its map does.
  const std::filesystem::path report = test::scratchDir() / "wide-step-over report.html";
  tapLetter(ui, 'E', true);
  clickControl(ui, "export.report");
  typeInto(ui, "export.path", report.string());
  clickControl(ui, "export.write");
  waitForJobs(ui);
  ASSERT_EQ(described(ui)["last_saved"], report.string()) << ui.inspector().statusText();
  const std::string html = test::readFile(report.string());
  EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos);
  EXPECT_EQ(html.find("No quality map"), std::string::npos);

  // A gap too small for any surface: the map made again fails, and the one shown stays with its gap.
  typeInto(ui, "surface.gap", "0.01");
  tap(ui, ImGuiKey_Enter);
  waitForJobs(ui);
  EXPECT_NE(ui.inspector().statusText().find("too far apart"), std::string::npos) << ui.inspector().statusText();
  EXPECT_DOUBLE_EQ(described(ui)["colour"]["gap_limit_mm"].get<double>(), 5.0);
  EXPECT_FALSE(described(ui)["map"].empty());

  // Nothing is made of a gap of 0: it is refused, and the map stays.
  typeInto(ui, "surface.gap", "0");
  tap(ui, ImGuiKey_Enter);
  waitForJobs(ui);
  EXPECT_DOUBLE_EQ(described(ui)["colour"]["gap_limit_mm"].get<double>(), 5.0);
  EXPECT_NE(ui.inspector().statusText().find("more than 0"), std::string::npos) << ui.inspector().statusText();
  EXPECT_FALSE(described(ui)["map"].empty());
}

TEST(wideStepOver, AnOptimisationMeasuresThePassesAsTheMapJoinsThem) {
  // A finishing raster over a bump, its passes 3 mm apart, of 0.4 mm moves.
  const std::filesystem::path program = test::scratchDir() / "bump-3mm-step-over.nc";
  {
    std::ofstream out(program);
    out << std::fixed << std::setprecision(4) << "G21 G90\nG0 X0 Y0 Z5\nG1 Z0 F3000\n";
    for (int pass = 0; pass < 12; ++pass)
      for (int i = 0; i <= 100; ++i) {
        const double x = 0.4 * (pass % 2 == 0 ? i : 100 - i);
        out << "G1 X" << x << " Y" << 3 * pass << " Z" << 3.0 * std::exp(-std::pow((x - 20) / 6, 2)) << "\n";
      }
    out << "G0 Z5\nM2\n";
  }
  panels::HeadlessUi ui(kWidth, kHeight, app_model::Settings{});
  ui.inspector().open(program.string());
  waitForJobs(ui);
  typeInto(ui, "surface.gap", "4");
  tap(ui, ImGuiKey_Enter);
  waitForJobs(ui);
  ASSERT_FALSE(described(ui)["map"].empty()) << ui.inspector().statusText();

  // Another program opened, its gap typed back to 2 mm, and closed: the Colour panel shows the
  // gap of the map shown again, and the optimisation joins the passes by it.
  ui.inspector().open(test::sourcePath("samples/transition-surface.nc"));
  waitForJobs(ui);
  typeInto(ui, "surface.gap", "2");
  tap(ui, ImGuiKey_Enter);
  waitForJobs(ui);
  tapLetter(ui, 'W', true);
  waitForJobs(ui);
  ASSERT_EQ(ui.inspector().documentCount(), 1u);
  EXPECT_DOUBLE_EQ(described(ui)["colour"]["gap_limit_mm"].get<double>(), 4.0);

  ui.inspector().optimise(4, 1215);
  waitForJobs(ui);
  ASSERT_NE(ui.inspector().optimisedDifference(), nullptr) << ui.inspector().statusText();
  // Measured between passes 3 mm apart, as the map shows them: not the nothing of a surface
  // without triangles.
  const std::string summary = ui.inspector().statusText();
  EXPECT_GT(figureBefore(summary, "inconsistency between passes p99 "), 1.0) << summary;
  EXPECT_GT(figureBefore(summary, "predicted deviation p99 "), 0.1) << summary;
}
