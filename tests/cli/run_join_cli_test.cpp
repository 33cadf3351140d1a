// A dump given with a program on the command line must be that program's: render, analyze and
// export refuse another program's dump (exit 2, both files named, nothing written) unless
// --force; ui-snapshot joins a program and its dump named together.
#include <gtest/gtest.h>

#include "test_support.h"

using namespace isurface::test;

namespace {

const std::string& transitionDump() {
  static const std::string path = [] {
    const std::string made = (scratchDir() / "transition.biip").string();
    const CommandResult r = runCli("simulate " + sourcePath("samples/transition-surface.nc") + " -o " + made);
    if (r.exitCode != 0) throw std::runtime_error("simulate failed: " + r.err);
    return made;
  }();
  return path;
}

}  // namespace

TEST(runJoinCli, AnotherProgramsDumpIsRefusedNamingBothFiles) {
  const std::string wuzhishan = sourcePath("samples/wuzhishan.nc");
  const std::string png = (scratchDir() / "refused.png").string();
  const std::string json = (scratchDir() / "refused.json").string();
  const std::string vtp = (scratchDir() / "refused.vtp").string();
  for (const std::string& args : {"render " + wuzhishan + " " + transitionDump() + " -o " + png,
                                  "analyze " + wuzhishan + " " + transitionDump() + " -o " + json,
                                  "export " + transitionDump() + " --gcode " + wuzhishan + " --vtp " + vtp}) {
    const CommandResult r = runCli(args);
    EXPECT_EQ(r.exitCode, 2) << args;
    EXPECT_NE(r.err.find(transitionDump()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(wuzhishan), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fileExists(png));
  EXPECT_FALSE(fileExists(json));
  EXPECT_FALSE(fileExists(vtp));
  const CommandResult forced = runCli("analyze " + wuzhishan + " " + transitionDump() + " -o " + json + " --force");
  EXPECT_EQ(forced.exitCode, 0) << forced.err;
}

TEST(runJoinCli, TheProgramsOwnDumpIsAccepted) {
  const std::string json = (scratchDir() / "own.json").string();
  const CommandResult r = runCli("analyze " + sourcePath("samples/transition-surface.nc") + " " + transitionDump() +
                                 " -o " + json);
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST(runJoinCli, UiSnapshotJoinsAProgramAndItsDumpAndRefusesAnothers) {
  const std::string png = (scratchDir() / "joined.png").string();
  const CommandResult joined = runCli("ui-snapshot " + sourcePath("samples/transition-surface.nc") + " " +
                                      transitionDump() + " --pick-line 150 --size 800x600 -o " + png);
  EXPECT_EQ(joined.exitCode, 0) << joined.err;
  EXPECT_TRUE(fileExists(png));
  const CommandResult refused = runCli("ui-snapshot " + sourcePath("samples/wuzhishan.nc") + " " + transitionDump() +
                                       " --size 800x600 -o " + (scratchDir() / "refused-ui.png").string());
  EXPECT_EQ(refused.exitCode, 2);
  EXPECT_NE(refused.err.find("is not a dump of"), std::string::npos) << refused.err;
}
