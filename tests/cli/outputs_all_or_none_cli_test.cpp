// A command's outputs: all of them or none, never over one of its inputs, never a temporary
// file left behind (a signal included), standard output checked like a file.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "scratch_files.h"
#include "test_support.h"

namespace fs = std::filesystem;
using isurface::test::runCli;
using isurface::test::scratchDir;
using isurface::test::freshScratchFolder;
using isurface::test::writeScratch;

namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Names in `folder` that look like a temporary output.
std::vector<std::string> temporaries(const fs::path& folder) {
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(folder)) {
    const std::string name = e.path().filename().string();
    if (name.find(".tmp") != std::string::npos || name.rfind(".isurface-tmp", 0) == 0) found.push_back(name);
  }
  return found;
}

const char* kProgram = "G21 G90\nG1 X10 Y5 F600\nG1 X0\nM2\n";

}  // namespace

TEST(Outputs, AnOutputThatIsTheInputIsRefusedAndTheInputKept) {
  const fs::path folder = freshScratchFolder("output-is-input");
  const std::string program = writeScratch("output-is-input/p.nc", kProgram);
  for (const std::string command : {"simulate", "canon"}) {
    const auto r = runCli(command + " " + program + " -o " + program);
    EXPECT_EQ(r.exitCode, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("is an input of this command"), std::string::npos) << r.err;
    EXPECT_EQ(readAll(program), kProgram) << command << " replaced its input";
  }
  // Under another name: a link to the input.
  fs::create_symlink(program, folder / "link.nc");
  const auto linked = runCli("canon " + program + " -o " + (folder / "link.nc").string());
  EXPECT_EQ(linked.exitCode, 2) << linked.err;
  EXPECT_EQ(readAll(program), kProgram);
  EXPECT_TRUE(temporaries(folder).empty());
}

TEST(Outputs, ATraceImportedOverItselfIsRefused) {
  const fs::path folder = freshScratchFolder("import-over-itself");
  const std::string trace = writeScratch("import-over-itself/t.csv", "x,y,z\n0,0,0\n1,0,0\n2,0,0\n");
  const auto r = runCli("import csv " + trace + " --map x=x,y=y,z=z -o " + trace);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(readAll(trace), "x,y,z\n0,0,0\n1,0,0\n2,0,0\n");
}

TEST(Outputs, WhenALaterFileCannotBeWrittenNoneIsLeft) {
  const fs::path folder = freshScratchFolder("all-or-none");
  const std::string program = (folder / "path.nc").string();
  const auto r = runCli("sts --surface toric -o " + program + " --report " + (folder / "no_dir" / "report.json").string());
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("report.json"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(program)) << "the program was left without its report";
  EXPECT_TRUE(temporaries(folder).empty());
}

TEST(Outputs, ALegalLongNameIsWritten) {
  const fs::path folder = freshScratchFolder("long-name");
  const std::string program = writeScratch("long-name/p.nc", kProgram);
  const std::string name = std::string(250, 'n') + ".txt";  // 254 bytes: legal, but not with ".tmpXXXXXX"
  const auto r = runCli("canon " + program + " -o " + (folder / name).string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(folder / name));
  EXPECT_TRUE(temporaries(folder).empty());
}

TEST(Outputs, StandardOutputOnAFullDiskIsAFailure) {
  for (const std::string args : {"sample --list", "sts --paper-tables"}) {
    const std::string command = std::string(::isurface::test::cliProgram()) + " " + args + " >/dev/full 2>/dev/null </dev/null";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_NE(WEXITSTATUS(status), 0) << args << " wrote to a full disk and said it succeeded";
  }
}

TEST(Outputs, ASignalLeavesNoTemporaryFileBehind) {
  const fs::path folder = freshScratchFolder("signalled");
  // Ten thousand seconds at F6: ten million samples, written for several seconds.
  const std::string program = writeScratch("signalled/slow.nc", "G21 G90\nG1 X1000 F6\nM2\n");
  const std::string dump = (folder / "slow.biip").string();
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::execl(::isurface::test::cliProgram(), ::isurface::test::cliProgram(), "simulate", program.c_str(), "-o", dump.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    bool writing = false;
    for (int i = 0; i < 400 && !writing; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      writing = !temporaries(folder).empty();
    }
    EXPECT_TRUE(writing) << "no temporary output appeared";
    ::kill(child, signal);
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "signal " << signal;
    EXPECT_TRUE(temporaries(folder).empty()) << "signal " << signal << " left " << temporaries(folder).front();
    EXPECT_FALSE(fs::exists(dump));
  }
}
