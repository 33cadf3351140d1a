// A program run beside the window (the report's isurface-cli): its progress lines read as they
// come, its messages kept, its exit code; a cancelled job stops it.
#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <fstream>

#include <chrono>
#include <thread>
#include <utility>
#include <vector>

#include "isurface/app_model/background_job.h"
#include "isurface/app_model/child_process.h"

using namespace isurface::app_model;

TEST(childProcess, ProgressMessagesAndExitCode) {
  BackgroundJob job;
  std::vector<std::pair<std::string, double>> seen;
  ChildOutcome outcome;
  job.start("child", [&](JobControl& control) {
    outcome = runChildProcess(
        {"/bin/sh", "-c",
         "printf '\\rsimulating  10%%' >&2; printf '\\rsimulating 100%%\\n' >&2; echo 'on stdout, not kept';"
         "echo 'error: x.nc:3:1: bad word' >&2; printf 'reporting on x.nc  50%%' >&2; exit 2"},
        control, [&](const std::string& label, double f) { seen.emplace_back(label, f); });
  });
  while (job.running()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(job.error(), "");
  EXPECT_EQ(outcome.exitCode, 2);
  EXPECT_EQ(outcome.messages, "error: x.nc:3:1: bad word\n");
  const std::vector<std::pair<std::string, double>> expected = {
      {"simulating", 0.1}, {"simulating", 1.0}, {"reporting on x.nc", 0.5}};
  EXPECT_EQ(seen, expected);
}

namespace {

// The process id the child wrote to `file` (its first line), or 0.
pid_t pidIn(const std::string& file) {
  std::ifstream in(file);
  long pid = 0;
  in >> pid;
  return static_cast<pid_t>(pid);
}

bool gone(pid_t pid) { return kill(pid, 0) == -1 && errno == ESRCH; }

// Cancels a job running `script` (which writes its pid to `pidFile`) and checks that the child
// is stopped and reaped.
void expectCancelStops(const std::string& script, const std::string& pidFile) {
  std::remove(pidFile.c_str());
  BackgroundJob job;
  const auto start = std::chrono::steady_clock::now();
  job.start("child", [&](JobControl& control) {
    runChildProcess({"/bin/sh", "-c", script}, control, [](const std::string&, double) {});
  });
  pid_t pid = 0;
  for (int i = 0; i < 200 && (pid = pidIn(pidFile)) == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_GT(pid, 0);
  job.cancel();
  while (job.running()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_TRUE(job.wasCancelled());
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  EXPECT_TRUE(gone(pid)) << "the child " << pid << " still runs or was not reaped";
  std::remove(pidFile.c_str());
}

}  // namespace

TEST(childProcess, ACancelledJobStopsTheChild) {
  const std::string pidFile = "/tmp/isurface-child-test-" + std::to_string(getpid());
  expectCancelStops("echo $$ > " + pidFile + "; exec sleep 60", pidFile);
}

// A child that closes its standard error and goes on: Cancel still stops it.
TEST(childProcess, AChildThatClosedItsErrorsIsStillCancelled) {
  const std::string pidFile = "/tmp/isurface-child-test-closed-" + std::to_string(getpid());
  expectCancelStops("echo $$ > " + pidFile + "; exec 2>&-; exec sleep 60", pidFile);
}

TEST(childProcess, AProgramThatCannotBeRunIsAnError) {
  BackgroundJob job;
  job.start("child", [&](JobControl& control) {
    runChildProcess({"/nonexistent/isurface-cli", "report"}, control, [](const std::string&, double) {});
  });
  while (job.running()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_NE(job.error().find("/nonexistent/isurface-cli"), std::string::npos) << job.error();
}
