// Five-axis programs on the command line: canon lists A, B and C with every move as LinuxCNC's
// rs274 reads them; simulating one is refused with the first line that turns a rotary axis
// (never simulated as if A, B and C stood still), and writes no dump.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "scratch_files.h"
#include "test_support.h"

namespace isurface {
namespace {

using test::runCli;
using test::scratchDir;

std::string program(const std::string& name) {
  return std::string(test::sourceDir()) + "/tests/data/linuxcnc-2.9-xyzbc-trt/" + name + ".ngc";
}

TEST(fiveAxisCli, CanonListsTheRotaryAxesOfEveryMove) {
  const auto r = runCli("canon " + program("rotary_only"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // G1 C90 at F2000 (line 8 of the file): the tip stays, C turns.
  EXPECT_NE(r.out.find("G1 10.0000 5.0000 10.0000 2000.0000 A0.0000 B20.0000 C90.0000\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" A0.0000 B-40.0000 C270.0000\n"), std::string::npos) << r.out;
  // Before the first rotary word, lines are as for a three-axis program.
  std::istringstream lines(r.out);
  std::string first;
  std::getline(lines, first);
  EXPECT_EQ(first.find(" A"), std::string::npos) << first;
  // A three-axis program lists no rotary axes at all.
  const auto plain = runCli("canon " + std::string(test::sourceDir()) + "/samples/transition-surface.nc");
  EXPECT_EQ(plain.out.find(" A0.0000"), std::string::npos);
}

TEST(fiveAxisCli, SimulatingRotaryMotionIsRefusedWithItsLine) {
  const std::string dump = (scratchDir() / "swarf.biip").string();
  for (const std::string machine : {std::string(), " --machine " + std::string(test::sourceDir()) + "/resources/machines/linuxcnc-xyzbc-trt.json"}) {
    const auto r = runCli("simulate " + program("swarf_bc") + machine + " -o " + dump);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("swarf_bc.ngc:8:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the rotary axes move here"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dump));
  }
}

}  // namespace
}  // namespace isurface
