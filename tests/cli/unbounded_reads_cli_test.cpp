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

// A named pipe nobody writes to, given as a program, a dump or a machine description, is read at
// once as what it holds, nothing (an empty program: `canon` lists no move, as of an empty file;
// the others, trace import and the window's snapshot too, refuse it, naming it), instead of the command waiting for a writer for ever.
TEST(unboundedReads, ANamedPipeWithoutAWriterIsNotWaitedFor) {
  const std::filesystem::path fifo = scratchDir() / "nobody-writes";
  std::filesystem::remove(fifo);
  ASSERT_EQ(runShell("mkfifo '" + fifo.string() + "'").exitCode, 0);
  const std::string out = (scratchDir() / "fifo-out.biip").string();
  const CommandResult listed = runShell("timeout 20 " + std::string(cliProgram()) + " canon " + fifo.string());
  EXPECT_EQ(listed.exitCode, 0) << listed.err;  // 124: it waited
  EXPECT_EQ(listed.out, "");
  const std::string png = (scratchDir() / "fifo-out.png").string();
  for (const std::string& args : {"simulate " + fifo.string() + " -o " + out, "info " + fifo.string(),
                                  "simulate " + sourcePath("samples/transition-surface.nc") + " --machine " +
                                      fifo.string() + " -o " + out,
                                  "import csv " + fifo.string() + " --map t=t,x=x,y=y,z=z -o " + out,
                                  "import halsampler " + fifo.string() + " -o " + out,
                                  "ui-snapshot " + fifo.string() + " -o " + png}) {
    const CommandResult r = runShell("timeout 20 " + std::string(cliProgram()) + " " + args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("nobody-writes"), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(png));
}
