// Number options refuse what they cannot mean: NaN, infinities, values out of their range, a
// fraction where a count is asked; each names the option and the value as written, exits 2 and
// writes nothing.
#include <gtest/gtest.h>

#include "scratch_files.h"
#include "test_support.h"

using namespace isurface::test;

TEST(numberOptions, ValuesAnOptionCannotMeanAreRefusedNamingTheOption) {
  const std::string program = sourcePath("samples/transition-surface.nc");
  const std::string out = (scratchDir() / "never.out").string();
  const std::string trace = writeScratch("trace.hal", "0 0 0 0 1 0 0 1\n1 1 0 0 1 0 0 1\n");
  const struct {
    std::string args;
    const char* says;
  } cases[] = {
      {"import halsampler " + trace + " -o " + out + " --cycle 0", "--cycle: 0 must be from"},
      {"import halsampler " + trace + " -o " + out + " --cycle 1e308", "--cycle: 1e308 must be from"},
      {"import halsampler " + trace + " -o " + out + " --cycle 1e-300", "--cycle: 1e-300 must be from"},
      {"compare a.biip b.biip -o " + out + " --time-tolerance nan", "--time-tolerance: nan is not a finite number"},
      {"compare a.biip b.biip -o " + out + " --time-tolerance -1", "--time-tolerance: -1 must be from 0"},
      {"render " + program + " -o " + out + " --highlight-line -1", "--highlight-line: -1 must be from 1"},
      {"render " + program + " -o " + out + " --highlight-line 2.5", "--highlight-line: 2.5 is not a whole number"},
      {"optimize " + program + " --auto -o " + out + " --tolerance inf", "--tolerance: inf is not a finite number"},
      {"analyze " + program + " -o " + out + " --speed-threshold nan", "--speed-threshold: nan is not a finite number"},
      {"intervals " + program + " -o " + out + " --dist-ratio 1", "--dist-ratio: 1 must be above 1"},
      {"sts --surface toric -o " + out + " --spindle-rpm 1e308", "--spindle-rpm: 1e308 must be from"},
      {"analyze " + program + " -o " + out + " --gap-limit inf", "--gap-limit: inf is not a finite number"},
      {"analyze " + program + " -o " + out + " --gap-limit 1e400", "--gap-limit: 1e400"},
  };
  for (const auto& c : cases) {
    const CommandResult r = runCli(c.args);
    EXPECT_EQ(r.exitCode, 2) << c.args;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(fileExists(out)) << c.args;
  }
}
