// The linuxcnc-2.9 control against LinuxCNC 2.9's own planner: the programs of
// tools/linuxcnc-reference, recorded on it (tests/data/linuxcnc-2.9, tools/linuxcnc-reference/
// record.sh), simulated with the machine of those recordings and compared line by line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <unistd.h>

#include "isurface/analysis/run_comparison.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/machine/machine.h"
#include "isurface/nc/sample_trajectory.h"
#include "isurface/nc/simulator.h"
#include "motion_checks.h"
#include "isurface/workflow/file_kinds.h"
#include "test_locations.h"
#include "test_support.h"

namespace isurface {
namespace {

namespace fs = std::filesystem;

fs::path dataDir() { return fs::path(test::sourceDir()) / "tests/data/linuxcnc-2.9"; }
// Recordings of programs in ../shared/realdata (read from there, not copied).
fs::path realdataRecordingsDir() { return fs::path(test::sourceDir()) / "tests/data/linuxcnc-2.9-realdata"; }
std::string linuxcncSim() { return std::string(test::sourceDir()) + "/resources/machines/linuxcnc-sim.json"; }

Trajectory recording(const std::string& name, const fs::path& folder = dataDir()) {
  const fs::path text = fs::temp_directory_path() / ("isurface-" + name + "-" + std::to_string(::getpid()) + ".txt");
  const std::string command =
      "gzip -dc '" + (folder / (name + ".halsampler.txt.gz")).string() + "' > '" + text.string() + "'";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  Trajectory t = readTrace(text.string(), FileKind::HalsamplerTrace);
  fs::remove(text);
  return t;
}

struct Agreement {
  double totalDifference = 0;  // share of the recording's time
  double lineP90 = 0;          // share of a line's time, lines of 20 ms and more
  double speedWithin = 0;      // share of samples whose speed is within 5 % of the feed
};

// `program`: the G-code the recording `name` in `folder` ran.
Agreement agreement(const fs::path& program, const std::string& name, const fs::path& folder,
                    const Machine& machine = loadMachine(linuxcncSim())) {
  const InterpretResult read = interpretGcodeFile(program.string());
  EXPECT_TRUE(read.ok());
  TrajectorySink sink(machine.cycle, name, false);
  simulate(read.program, machine, sink);
  const Trajectory simulated = sink.take();
  const Trajectory recorded = recording(name, folder);
  const RunComparison c = compareRuns(recorded, simulated);

  Agreement a;
  a.totalDifference = (c.total.timeB - c.total.timeA) / c.total.timeA;
  std::vector<double> lineShares;
  for (const LineDifference& line : c.lines)
    if (line.figures.timeA >= 0.020) lineShares.push_back(std::abs(line.figures.timeDifference) / line.figures.timeA);
  std::sort(lineShares.begin(), lineShares.end());
  a.lineP90 = lineShares.empty() ? 0 : lineShares[static_cast<std::size_t>(0.9 * double(lineShares.size() - 1))];

  // The programmed feed of each line (a rapid's: the machine's rapid rate), mm/min.
  std::map<std::uint32_t, double> feed;
  for (const Move& m : read.program.moves)
    if (m.isMotion()) feed[m.line] = std::max(feed[m.line], m.kind == MoveKind::Rapid ? machine.rapidVelocity * 60 : double(m.feed));
  std::size_t compared = 0, within = 0;
  for (std::size_t i = 0; i < c.speedDifference.size(); ++i) {
    const auto f = feed.find(recorded.line[i]);
    if (!std::isfinite(c.speedDifference[i]) || f == feed.end()) continue;
    ++compared;
    if (std::abs(c.speedDifference[i]) <= 0.05 * f->second) ++within;
  }
  a.speedWithin = compared ? double(within) / double(compared) : 0;
  return a;
}

std::vector<std::string> recordedPrograms(const fs::path& folder) {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(folder)) {
    const std::string file = e.path().filename().string();
    const std::string suffix = ".halsampler.txt.gz";
    if (file.size() > suffix.size() && file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0)
      names.push_back(file.substr(0, file.size() - suffix.size()));
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The agreement asked of the linuxcnc-2.9 control (issue figures), of every recording: total
// motion time within 2 %, per line of 20 ms or more |difference| p90 within 5 %, speed at the
// same arc length within 5 % of the feed at 95 % of the samples.
struct Bounds {
  double total = 0.02, lineP90 = 0.05, speedWithin = 0.95;
};

void expectEveryRecordingAgrees(const fs::path& folder, std::size_t atLeast) {
  const std::vector<std::string> names = recordedPrograms(folder);
  ASSERT_GE(names.size(), atLeast) << "the reference recordings are missing from " << folder;
  for (const std::string& name : names) {
    const Agreement a = agreement(folder / (name + ".ngc"), name, folder);
    std::printf("%-40s total %+6.2f %%  line p90 %5.2f %%  speed within 5 %% of feed %6.2f %%\n", name.c_str(),
                100 * a.totalDifference, 100 * a.lineP90, 100 * a.speedWithin);
    const Bounds b;
    EXPECT_LT(std::abs(a.totalDifference), b.total) << name;
    EXPECT_LT(a.lineP90, b.lineP90) << name;
    EXPECT_GT(a.speedWithin, b.speedWithin) << name;
  }
}

TEST(linuxcncReference, everyRecordingAgreesWithTheLinuxcnc29Control) { expectEveryRecordingAgrees(dataDir(), 20); }

// Finishing programs of a generator written apart from the project (its own surface family,
// chord tolerances of 2-10 um, F1500-3500, G64 P0.01 or G64), recorded after the control was
// final: tests/data/linuxcnc-2.9-independent/README.md.
TEST(linuxcncReference, programsOfAnotherGeneratorAgreeWithTheLinuxcnc29Control) {
  expectEveryRecordingAgrees(fs::path(test::sourceDir()) / "tests/data/linuxcnc-2.9-independent", 8);
}

// s from the first sample that moves to the last: a recording holds no standstill before the first
// motion, a simulation holds the dwells before it.
double motionSpan(const Trajectory& t) {
  std::size_t first = 0, last = 0;
  for (std::size_t i = 1; i < t.size(); ++i)
    if (t.commanded(i) != t.commanded(i - 1)) {
      if (first == 0) first = i;
      last = i;
    }
  return first == 0 ? 0 : t.timeAt(last) - t.timeAt(first - 1);
}

// LinuxCNC's daisy without its A words (the recording machine has X, Y and Z only).
std::string daisyWithoutA() {
  std::string text = test::readFile(test::realdataPath("linuxcnc_daisy.ngc"));
  for (const std::string word : {"A0", " A#44"})
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at)) text.erase(at, word.size());
  return text;
}

double simulatedSpan(const std::string& text, const Machine& machine) {
  const InterpretResult read = interpretGcode(text, "daisy_xyz.ngc");
  EXPECT_TRUE(read.ok());
  TrajectorySink sink(machine.cycle, "daisy_xyz.ngc", false);
  simulate(read.program, machine, sink);
  return motionSpan(sink.take());
}

// LinuxCNC 2.9's planner is not monotonic in acceleration: halving every axis's acceleration
// runs LinuxCNC's daisy (its A words left out) about 0.5 s faster, as its blends grow with the
// time they have. The control follows it; this is why the limit-lowering properties of
// control_properties_test.cpp leave acceleration out for this control.
TEST(linuxcncReference, aLowerAccelerationRunsAsLinuxCncRunsIt) {
  ISURFACE_SKIP_WITHOUT_REALDATA(test::realdataPath("linuxcnc_daisy.ngc"));
  Machine machine = loadMachine(linuxcncSim());
  const double recordedFull = motionSpan(recording("daisy_xyz.accel1000", realdataRecordingsDir()));
  const double recordedHalf = motionSpan(recording("daisy_xyz.accel500", realdataRecordingsDir()));
  const std::string daisy = daisyWithoutA();
  ASSERT_EQ(daisy.find("A0"), std::string::npos);
  const double simulatedFull = simulatedSpan(daisy, machine);
  for (AxisLimits& axis : machine.axes) axis.maxAcceleration *= 0.5;
  const double simulatedHalf = simulatedSpan(daisy, machine);
  std::printf("daisy_xyz: LinuxCNC %.3f -> %.3f s, the control %.3f -> %.3f s\n", recordedFull, recordedHalf,
              simulatedFull, simulatedHalf);
  EXPECT_NEAR(simulatedFull, recordedFull, 0.02 * recordedFull);
  EXPECT_NEAR(simulatedHalf, recordedHalf, 0.02 * recordedHalf);
  ASSERT_LT(recordedHalf, recordedFull - 0.2);
  EXPECT_NEAR(simulatedHalf - simulatedFull, recordedHalf - recordedFull, 0.1);
}

// LinuxCNC's flowsnake (recursive O-word subroutines drawing a space-filling curve, 3,076 moves),
// recorded on its planner after the control was final.
TEST(linuxcncReferenceLong, linuxcncsFlowsnakeAgreesWithTheLinuxcnc29Control) {
  ISURFACE_SKIP_WITHOUT_REALDATA(test::realdataPath("linuxcnc_flowsnake.ngc"));
  const Agreement a = agreement(test::realdataPath("linuxcnc_flowsnake.ngc"), "linuxcnc_flowsnake", realdataRecordingsDir());
  std::printf("linuxcnc_flowsnake: total %+.3f %%, line p90 %.2f %%, speed within 5 %% of feed %.2f %%\n",
              100 * a.totalDifference, 100 * a.lineP90, 100 * a.speedWithin);
  const Bounds b;
  EXPECT_LT(std::abs(a.totalDifference), b.total);
  EXPECT_LT(a.lineP90, b.lineP90);
  EXPECT_GT(a.speedWithin, b.speedWithin);
}

// The generic control (no jerk limit, the limits of the recordings' machine) on CAM chords whose
// program asks no looser a tolerance than the machine's (G64 P0.01): it blends the chords within
// its tolerance as LinuxCNC does, and runs each within 6 % of LinuxCNC's time (before blends:
// 2-50 % slower, braking at every chord junction). Its path stays within the machine's tolerance.
TEST(genericControl, holdsTheFeedOnCamChordsAsLinuxCncDoes) {
  Machine machine = loadMachine(linuxcncSim());
  machine.control.planner = TrajectoryPlanner::Generic;
  const fs::path independent = fs::path(test::sourceDir()) / "tests/data/linuxcnc-2.9-independent";
  const std::vector<std::pair<fs::path, std::string>> programs = {
      {dataDir(), "chords_tol001_f3000_p001"}, {dataDir(), "bump_raster_chords_p001_f3000"},
      {independent, "T0"}, {independent, "T1"}, {independent, "T2"},
      {independent, "T3"}, {independent, "T6"}, {independent, "T7"}};
  for (const auto& [folder, name] : programs) {
    const InterpretResult read = interpretGcodeFile((folder / (name + ".ngc")).string());
    ASSERT_TRUE(read.ok()) << name;
    test::MotionChecker checker(read.program, machine, 20);
    TrajectorySink sink(machine.cycle, name, false);
    simulate(read.program, machine, sink);
    const double simulated = motionSpan(sink.take());
    const double recorded = motionSpan(recording(name, folder));
    simulate(read.program, machine, checker);
    const test::MotionExtremes extremes = checker.finish();
    std::printf("%-32s LinuxCNC %.3f s, the generic control %.3f s (%+.2f %%), deviation %.4f mm\n", name.c_str(),
                recorded, simulated, 100 * (simulated / recorded - 1), extremes.maxDeviation);
    EXPECT_LT(std::abs(simulated / recorded - 1), 0.06) << name;
    EXPECT_LE(extremes.maxDeviation, machine.chordTolerance * test::kLimitTolerance) << name;
    EXPECT_LE(extremes.velocityRatio, test::kLimitTolerance) << name;
    EXPECT_LE(extremes.accelerationRatio, test::kLimitTolerance) << name;
  }
}

}  // namespace
}  // namespace isurface
