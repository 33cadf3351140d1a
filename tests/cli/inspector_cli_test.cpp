// The whole UI drawn headless by isurface-cli ui-snapshot against a reference picture, and its
// bad inputs refused.
//
// ISURFACE_UPDATE_REFERENCES=1 rewrites the reference from the current snapshot (look at it).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "test_support.h"
#include "image_compare.h"

using namespace isurface::test;

TEST(uiSnapshot, WholeWindowWithAPickedLineMatchesItsReference) {
  const std::string out = (scratchDir() / "ui.png").string();
  const CommandResult r = runCli("ui-snapshot " + sourcePath("samples/transition-surface.nc") +
                                 " --pick-line 2000 --size 1280x800 -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string reference = sourcePath("tests/data/reference/ui-transition-surface-line2000.png");
  if (std::getenv("ISURFACE_UPDATE_REFERENCES")) {
    std::filesystem::copy_file(out, reference, std::filesystem::copy_options::overwrite_existing);
    GTEST_SKIP() << "reference rewritten: " << reference;
  }
  const ImageDifference d = compareImages(readPng(reference), readPng(out));
  EXPECT_TRUE(matches(d)) << "worst block " << d.worstBlock << ", mean " << d.meanDifference << " (" << out << ")";
}

TEST(uiSnapshot, BadInputsExitWithTwoAndWriteNothing) {
  const std::string out = (scratchDir() / "never-ui.png").string();
  EXPECT_EQ(runCli("ui-snapshot /nonexistent.nc -o " + out).exitCode, 2);
  EXPECT_EQ(runCli("ui-snapshot " + sourcePath("samples/wuzhishan.nc") + " --pick-line 3 -o " + out).exitCode, 2);
  EXPECT_EQ(runCli("ui-snapshot --size 10x10 -o " + out).exitCode, 2);
  EXPECT_FALSE(fileExists(out));
}

TEST(uiSnapshot, TheMachineGivenSimulatesAndItsWindowIsDrawn) {
  const std::string plain = (scratchDir() / "ui-default-machine.png").string();
  const std::string machine = (scratchDir() / "ui-sim-machine.png").string();
  const std::string program = sourcePath("samples/transition-surface.nc");
  const CommandResult a = runCli("ui-snapshot " + program + " --size 1280x800 -o " + plain);
  ASSERT_EQ(a.exitCode, 0) << a.err;
  const CommandResult b = runCli("ui-snapshot " + program + " --machine " + sourcePath("resources/machines/linuxcnc-sim.json") +
                                 " --show-machine --size 1280x800 -o " + machine);
  ASSERT_EQ(b.exitCode, 0) << b.err;
  // Another machine, another simulation: the status names another number of samples.
  EXPECT_NE(a.out, b.out);
  // The machine window stands in the middle of the picture, over the map.
  const ImageDifference d = compareImages(readPng(plain), readPng(machine));
  EXPECT_FALSE(matches(d));
  EXPECT_NE(runCli("ui-snapshot " + program + " --machine /nonexistent.json -o " + machine).exitCode, 0);
}
