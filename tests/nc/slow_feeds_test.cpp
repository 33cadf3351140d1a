// Feeds are honoured however slow: a program at F1 takes the minutes it says, not a tenth.
#include <gtest/gtest.h>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/gcode/gcode_stream.h"
#include "isurface/machine/machine.h"
#include "isurface/nc/simulator.h"

#include <fmt/format.h>

using namespace isurface;

namespace {

SimulationReport simulateText(const std::string& text, const Machine& machine = defaultMachine()) {
  InterpretResult r = interpretGcode(text, "slow.nc");
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front().str());
  SampleBuffer buffer;
  return simulate(r.program, machine, buffer);
}

}  // namespace

TEST(SlowFeeds, OneMillimetreAtF1TakesAMinute) {
  const SimulationReport r = simulateText("G21 G90\nG1 X1 F1\n");
  EXPECT_NEAR(r.machiningTime, 60.0, 0.5);
}

TEST(SlowFeeds, HalfAMillimetrePerMinuteIsNotRaised) {
  const SimulationReport r = simulateText("G21 G90\nG1 X0.1 F0.5\n");
  EXPECT_NEAR(r.machiningTime, 12.0, 0.5);
}

TEST(SlowFeeds, TinyInverseTimeFeedTakesItsTime) {
  // G93 F0.1: the move takes 1 / 0.1 = 10 minutes.
  const SimulationReport r = simulateText("G21 G90\nG93 G1 X1 F0.1\n");
  EXPECT_NEAR(r.machiningTime, 600.0, 1.0);
}

TEST(SlowFeeds, ASlowAxisOfTheMachineIsHonoured) {
  Machine m = parseMachine(R"({"axes": {"x": {"max_velocity_mm_min": 2}}})", "slow-axis.json");
  const SimulationReport r = simulateText("G21 G90\nG1 X1 F1000\n", m);
  EXPECT_NEAR(r.machiningTime, 30.0, 0.5);
}

TEST(SlowFeeds, ARapidThatWouldTakeDaysNamesTheRapidSpeedNotF0) {
  Machine m = parseMachine(R"({"rapid_mm_min": 0.0001})", "slow-rapid.json");
  InterpretResult r = interpretGcode("G21 G90\nG0 X100\n", "rapid.nc");
  ASSERT_TRUE(r.ok());
  SampleBuffer buffer;
  try {
    simulate(r.program, m, buffer);
    FAIL() << "a rapid of 1.7e4 hours was simulated";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("rapid speed"), std::string::npos) << message;
    EXPECT_EQ(message.find("F0"), std::string::npos) << message;
    EXPECT_LT(message.size(), 200u) << message;
  }
}

TEST(SlowFeeds, AbsurdDurationsAreRefusedInFewWords) {
  for (const std::string block : {"G4 P[10**150]", "G1 X[10**150] F1", "G1 X1000000 F0.000001"}) {
    InterpretResult r = interpretGcode("G21 G90\n" + block + "\n", "absurd.nc");
    if (!r.ok()) {
      EXPECT_LT(r.errors.front().message.size(), 200u) << r.errors.front().message;
      continue;
    }
    SampleBuffer buffer;
    try {
      simulate(r.program, defaultMachine(), buffer);
      ADD_FAILURE() << block << " was simulated";
    } catch (const InputError& e) {
      EXPECT_LT(std::string(e.what()).size(), 200u) << e.what();
    }
  }
}

// A planner's refusal names the word that made the move, as the interpreter's errors do.
TEST(SlowFeeds, ARefusedMoveIsNamedByLineAndColumn) {
  struct Case {
    std::string program;
    unsigned line, column;
  };
  const Case cases[] = {
      {"G21 G90\nG1 X1 F100\n  N20 G4 P400000\n", 3, 7},      // the dwell's G4
      {"G21 G90\nG1 F0.000001\n   X1000000\n", 3, 4},         // modal G1: its first axis word
      {"G21 G90\nG1 X1 F100\nG0 Z5 (up)\n  G1 X1000000 F0.000001\n", 4, 3},
  };
  for (const Case& c : cases) {
    InterpretResult r = interpretGcode(c.program, "columns.nc");
    ASSERT_TRUE(r.ok()) << c.program;
    SampleBuffer buffer;
    try {
      simulate(r.program, defaultMachine(), buffer);
      ADD_FAILURE() << c.program << " was simulated";
    } catch (const InputError& e) {
      EXPECT_EQ(e.diagnostic().line, c.line) << e.what();
      EXPECT_EQ(e.diagnostic().column, c.column) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(fmt::format("columns.nc:{}:{}: ", c.line, c.column), 0), 0u) << e.what();
    }
  }
}

namespace {

struct CountingSink : SampleSink {
  void consume(const SimSample*, std::size_t count) override { samples += count; }
  std::size_t samples = 0;
};

// `program` passes the machine's longest run: simulated whole and as it is read (a move at a
// time), the refusal names line:column, and no sample of the run is made as it is read.
void expectRefusedAt(const std::string& program, const Machine& machine, unsigned line, unsigned column) {
  InterpretResult r = interpretGcode(program, "bound.nc");
  ASSERT_TRUE(r.ok());
  CountingSink whole, streamed;
  try {
    simulate(r.program, machine, whole);
    ADD_FAILURE() << "simulated whole past the bound";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostic().line, line) << "whole: " << e.what();
    EXPECT_EQ(e.diagnostic().column, column) << "whole: " << e.what();
  }
  StreamingSimulation simulation(machine, Vec3::Zero(), "bound.nc", streamed);
  EXPECT_TRUE(interpretGcodeStream(program, "bound.nc", simulation, {}, 1).ok());
  try {
    simulation.finish();
    ADD_FAILURE() << "simulated as it was read past the bound";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostic().line, line) << "streamed: " << e.what();
    EXPECT_EQ(e.diagnostic().column, column) << "streamed: " << e.what();
  }
}

}  // namespace

// Dwells that together pass the longest run are named where the bound is passed, not at the
// move before them, whether the program is simulated whole or as it is read.
TEST(SlowFeeds, TheDwellThatPassesTheLongestRunIsNamed) {
  expectRefusedAt("G21 G90\nG1 X1 F100\n G4 P80000\nG4 P80000\nG4 P80000\n  G4 P80000\nG4 P80000\n",
                  defaultMachine(), 7, 1);
}

// A dwell right after motion, that together pass the bound, is named, not the motion before it.
TEST(SlowFeeds, ADwellAfterMotionThatPassesTheLongestRunIsNamed) {
  Machine machine = defaultMachine();
  machine.longestRun = 600;  // s
  // Five moves of 100 s (1 mm at 0.6 mm/min), then 150 s of dwell on line 7.
  expectRefusedAt("G21 G90\nG1 X1 F0.6\nX2\nX3\nX4\nX5\n  G4 P150\nG1 X6\n", machine, 7, 3);
}

// Dwells alone (no motion at all) that pass the bound: the one passing it is named.
TEST(SlowFeeds, DwellsAloneThatPassTheLongestRunAreNamed) {
  Machine machine = defaultMachine();
  machine.longestRun = 600;  // s
  expectRefusedAt("G21 G90\nG4 P250\nG4 P250\n G4 P250\nG4 P250\n", machine, 4, 2);
}
