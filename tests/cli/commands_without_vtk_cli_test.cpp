// The commands that draw nothing run in isurface-cli alone, which loads no VTK or OpenGL:
// analyze (without --png) and export among them. A copy of isurface-cli with no isurface-cli-all
// beside it runs them; a command that draws says what it is missing.
#include <gtest/gtest.h>

#include <filesystem>

#include "scratch_files.h"
#include "test_support.h"
#include "workflow_fixtures.h"

namespace isurface {
namespace {

using test::runShell;
using test::scratchDir;

TEST(commandsWithoutVtk, AnalyzeAndExportRunWithoutTheDrawingProgram) {
  const std::filesystem::path alone = scratchDir() / "cli-alone";
  std::filesystem::create_directories(alone);
  const std::filesystem::path cli = alone / "isurface-cli";
  std::filesystem::copy_file(test::cliProgram(), cli, std::filesystem::copy_options::overwrite_existing);
  const std::string program = test::sourcePath("samples/transition-surface.nc");
  const std::string dump = test::transitionDump();

  const auto analysed = runShell(cli.string() + " analyze " + program + " " + dump + " -o " + (alone / "a.json").string());
  EXPECT_EQ(analysed.exitCode, 0) << analysed.err;
  EXPECT_TRUE(std::filesystem::exists(alone / "a.json"));
  const auto exported = runShell(cli.string() + " export " + dump + " --gcode " + program + " --vtp " + (alone / "s.vtp").string());
  EXPECT_EQ(exported.exitCode, 0) << exported.err;
  EXPECT_GT(std::filesystem::file_size(alone / "s.vtp"), 100000u);

  const auto drawn = runShell(cli.string() + " analyze " + program + " " + dump + " -o " + (alone / "b.json").string() +
                              " --png " + (alone / "b.png").string());
  EXPECT_NE(drawn.exitCode, 0);
  EXPECT_NE(drawn.err.find("isurface-cli-all"), std::string::npos) << drawn.err;
  EXPECT_FALSE(std::filesystem::exists(alone / "b.png"));
}

}  // namespace
}  // namespace isurface
