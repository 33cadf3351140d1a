// Inputs that never end or are far larger than their kind are refused at a bound, at once:
// /dev/zero as a machine description or a tool table, a tool table of hundreds of megabytes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scratch_files.h"
#include "test_support.h"

using namespace isurface::test;

TEST(unboundedReads, ADeviceOrAHugeFileAsADescriptionIsRefusedAtOnce) {
  const std::string program = sourcePath("samples/transition-surface.nc");
  const std::string out = (scratchDir() / "never.biip").string();
  const std::string huge = (scratchDir() / "huge.tbl").string();
  {
    std::ofstream table(huge);
    table << "T1 P1 D6\nthis line is wrong\n";
  }
  std::filesystem::resize_file(huge, std::uintmax_t(300) << 20);  // sparse: 300 MB read back as zeros
  const struct {
    std::string args;
    const char* says;
  } cases[] = {{"--machine /dev/zero", "a machine description is not that large"},
               {"--tool-table /dev/zero", "a tool table is not that large"},
               {"--tool-table " + huge, "a tool table is at most"}};
  for (const auto& c : cases) {
    const CommandResult r = runCli("simulate " + program + " -o " + out + " " + c.args);
    EXPECT_EQ(r.exitCode, 2) << c.args;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(fileExists(out));
  }
}
