// The simulator on real programs written by others (../shared/realdata).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "motion_checks.h"
#include "isurface/nc/feed_plan.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/nc/simulator.h"
#include "test_support.h"

using namespace isurface;
using isurface::test::MotionChecker;
using isurface::test::MotionExtremes;
using isurface::test::expectWithinLimits;
using isurface::test::realdataPath;

namespace {

Program load(const std::string& name) {
  InterpretResult r = interpretGcodeFile(realdataPath(name));
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front().str());
  return std::move(r.program);
}

MotionExtremes check(const Program& p, const Machine& m, bool geometry) {
  const FeedPlan plan = planFeed(p, m);
  MotionChecker checker(p, m, static_cast<int>((plan.filterTime1 + plan.filterTime2) / m.cycle) + 2, geometry);
  simulate(p, m, checker);
  return checker.finish();
}

#define REQUIRE_REALDATA(name) ISURFACE_SKIP_WITHOUT_REALDATA(realdataPath(name))

}  // namespace

TEST(SimulatorRealData, LinuxcncTestProgramWithinLimitsAndTolerance) {
  REQUIRE_REALDATA("linuxcnc_test.ngc");
  const Machine m = defaultMachine();
  const MotionExtremes r = check(load("linuxcnc_test.ngc"), m, true);
  expectWithinLimits(r, m);
}

TEST(SimulatorRealData, CommunicatorWaterlineArcsWithinLimitsAndTolerance) {
  REQUIRE_REALDATA("communicator.nc");
  const Machine m = defaultMachine();
  const MotionExtremes r = check(load("communicator.nc"), m, true);
  expectWithinLimits(r, m);
}

// LinuxCNC 2.9 ran linuxcnc_test.ngc at 100 mm/s and 1000 mm/s^2 on every axis with no jerk
// limit; with the same machine (its linuxcnc-2.9 control) our machining time is within 2 % of the recording's.
TEST(SimulatorRealData, MachiningTimeMatchesTheLinuxcncRecording) {
  REQUIRE_REALDATA("linuxcnc_test.halsampler.txt");
  std::ifstream in(realdataPath("linuxcnc_test.halsampler.txt"));
  std::string text;
  std::size_t inProgram = 0;
  while (std::getline(in, text)) {
    std::istringstream fields(text);
    double index, x, y, z, line;
    if (fields >> index >> x >> y >> z >> line && line != 0) ++inProgram;
  }
  const double recorded = inProgram * 0.001;
  ASSERT_GT(recorded, 10.0);
  const Machine m = loadMachine(isurface::test::sourcePath("resources/machines/linuxcnc-sim.json"));
  SampleBuffer buffer;
  const SimulationReport r = simulate(load("linuxcnc_test.ngc"), m, buffer);
  EXPECT_NEAR(r.machiningTime, recorded, 0.02 * recorded)
      << "simulated " << r.machiningTime << " s, recorded " << recorded << " s";
}

// Reliefs with sharp turns between short moves: the first few thousand moves of each.
TEST(SimulatorRealData, ReliefProgramsWithinLimitsAndTolerance) {
  for (const char* name : {"stellabee1.ngc", "cameo.nc"}) {
    if (!isurface::test::fileExists(realdataPath(name))) continue;
    SCOPED_TRACE(name);
    Program p = load(name);
    p.moves.resize(std::min<std::size_t>(p.moves.size(), 4000));
    const Machine m = defaultMachine();
    const MotionExtremes r = check(p, m, true);
    expectWithinLimits(r, m);
  }
}
