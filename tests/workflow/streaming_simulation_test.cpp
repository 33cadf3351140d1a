// Planning with a bounded look-ahead window and simulating as the program is read give what
// planning and simulating the whole program gives, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "isurface/nc/feed_plan.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/gcode/gcode_stream.h"
#include "isurface/nc/simulator.h"
#include "isurface/workflow/simulation_dump.h"
#include "program_corpus.h"
#include "test_support.h"

using namespace isurface;

namespace {

Program load(const std::string& path) {
  InterpretResult r = interpretGcodeFile(path);
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front().str());
  return std::move(r.program);
}

bool sameSegment(const PlannedSegment& a, const PlannedSegment& b) {
  return a.move == b.move && a.length == b.length && a.entrySpeed == b.entrySpeed && a.peakSpeed == b.peakSpeed &&
         a.exitSpeed == b.exitSpeed && a.accel == b.accel && a.holdAfter == b.holdAfter && a.cap == b.cap &&
         a.entryLimit == b.entryLimit;
}

struct WindowedPlan {
  std::vector<PlannedSegment> segments;
  double holdBefore = 0;
  std::size_t largestHeld = 0, forcedCommits = 0;
};

WindowedPlan planWindowed(const Program& p, const Machine& m, const StreamingFeedPlanner::Window& window) {
  StreamingFeedPlanner planner(m, LimitBudget{}, p.source, window);
  WindowedPlan out;
  for (std::size_t i = 0; i < p.moves.size(); ++i) {
    planner.add(static_cast<std::uint32_t>(i), p.moves[i], p.startOf(i));
    planner.take(out.segments);
  }
  planner.finish();
  planner.take(out.segments);
  out.holdBefore = planner.holdBefore();
  out.largestHeld = planner.largestHeld();
  out.forcedCommits = planner.forcedCommits();
  return out;
}

// FNV-1a over the samples' bytes (SimSample has no padding): equal hashes and counts stand for
// equal streams without keeping 11 M samples twice.
class HashingSink : public SampleSink {
 public:
  void consume(const SimSample* samples, std::size_t count) override {
    const auto* bytes = reinterpret_cast<const unsigned char*>(samples);
    for (std::size_t i = 0; i < count * sizeof(SimSample); ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
    this->count += count;
  }
  std::uint64_t hash = 1469598103934665603ull;
  std::uint64_t count = 0;
};

// Interprets in chunks of `chunkMoves` and simulates as the moves come.
SimulationReport simulateStreamed(const std::string& text, const std::string& source, const Machine& m,
                                  SampleSink& sink, std::size_t chunkMoves,
                                  const StreamingFeedPlanner::Window& window = {}) {
  StreamingSimulation simulation(m, Vec3::Zero(), source, sink, window);
  const StreamedInterpretation r = interpretGcodeStream(text, source, simulation, {}, chunkMoves);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(simulation.planner().forcedCommits(), 0u);
  return simulation.finish();
}

void expectSameReport(const SimulationReport& a, const SimulationReport& b) {
  EXPECT_EQ(a.samples, b.samples);
  EXPECT_EQ(a.machiningTime, b.machiningTime);
  EXPECT_EQ(a.pathLength, b.pathLength);
  EXPECT_EQ(a.segments, b.segments);
  EXPECT_EQ(a.filterTime1, b.filterTime1);
  EXPECT_EQ(a.filterTime2, b.filterTime2);
}

void expectSameSamples(const SampleBuffer& streamed, const SampleBuffer& whole) {
  ASSERT_EQ(streamed.data.size(), whole.data.size());
  EXPECT_EQ(std::memcmp(streamed.data.data(), whole.data.data(), whole.data.size() * sizeof(SimSample)), 0);
}

}  // namespace

TEST(StreamingFeedPlan, EverySegmentEqualsTheWholeProgramPlan) {
  for (const Machine& m : {defaultMachine(), loadMachine(test::sourcePath("resources/machines/linuxcnc-sim.json"))}) {
    for (const std::string& path : test::samplesAndRealPrograms()) {
      SCOPED_TRACE(path + " on " + m.name);
      const Program p = load(path);
      const FeedPlan whole = planFeed(p, m);
      // Committing after every segment, and the default window.
      for (const StreamingFeedPlanner::Window window : {StreamingFeedPlanner::Window{1, 1u << 17},
                                                        StreamingFeedPlanner::Window{}}) {
        const WindowedPlan windowed = planWindowed(p, m, window);
        EXPECT_EQ(windowed.forcedCommits, 0u);
        EXPECT_EQ(windowed.holdBefore, whole.holdBefore);
        ASSERT_EQ(windowed.segments.size(), whole.segments.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < whole.segments.size(); ++i)
          differing += sameSegment(windowed.segments[i], whole.segments[i]) ? 0 : 1;
        EXPECT_EQ(differing, 0u);
        // The window really is bounded: on the long programs it holds a small part of them.
        if (whole.segments.size() > 100000) {
          EXPECT_LT(windowed.largestHeld, whole.segments.size() / 10);
        }
      }
    }
  }
}

TEST(StreamingSimulationLong, SamplesEqualTheWholeProgramSimulation) {
  const Machine m = defaultMachine();
  for (const std::string& path : test::samplesAndRealPrograms()) {
    SCOPED_TRACE(path);
    const Program p = load(path);
    HashingSink whole;
    const SimulationReport wholeReport = simulate(p, m, whole);
    HashingSink streamed;
    const std::string text = test::readFile(path);
    // Odd chunks of moves, and a commit attempted after every segment.
    const SimulationReport streamedReport = simulateStreamed(text, path, m, streamed, 4093, {1, 1u << 17});
    expectSameReport(streamedReport, wholeReport);
    EXPECT_EQ(streamed.count, whole.count);
    EXPECT_EQ(streamed.hash, whole.hash);
  }
}

TEST(StreamingSimulation, ChunkOfOneMoveAndCommitAfterEverySegmentSampleForSample) {
  // Dwells before the first motion and between moves, stops, arcs, a canned cycle, rapids.
  const std::string text =
      "G21 G90 G64 F3000\nG4 P0.3\nG0 Z5\nG1 X10 Y0 Z0\nG2 X0 Y10 I-10 J0\nG3 X-10 Y0 R10\nG4 P0.2\n"
      "G1 X-10 Y-10 F1200\nG61 G1 X0 Y-10\nG64 G1 X1 Y-9.9\nX2 Y-9.6\nX3 Y-9.1\nX4 Y-8.4\nM0\n"
      "G99 G81 X20 Y20 Z-2 R1\nX25\nG80 G0 Z10\nG1 X0.001 Y0 Z10\nX0.002\nX50 Y50 F6000\nM30\n";
  const Program p = interpretGcode(text, "t.ngc").program;
  const Machine m = defaultMachine();
  SampleBuffer whole;
  const SimulationReport wholeReport = simulate(p, m, whole);
  for (std::size_t chunk : {1, 3, 1000}) {
    SCOPED_TRACE("chunk of " + std::to_string(chunk));
    SampleBuffer streamed;
    expectSameReport(simulateStreamed(text, "t.ngc", m, streamed, chunk, {1, 1u << 17}), wholeReport);
    expectSameSamples(streamed, whole);
  }
}

TEST(StreamingSimulation, DwellsAloneAndEmptyPrograms) {
  const Machine m = defaultMachine();
  for (const std::string text : {"G4 P0.5\nG4 P0.25\n", "", "G0 X0\n"}) {
    SCOPED_TRACE(text);
    SampleBuffer whole, streamed;
    const SimulationReport wholeReport = simulate(interpretGcode(text, "t.ngc").program, m, whole);
    expectSameReport(simulateStreamed(text, "t.ngc", m, streamed, 1), wholeReport);
    expectSameSamples(streamed, whole);
  }
}

// A braking distance over more segments than the window may hold: the window commits anyway,
// slower than the whole plan but within every limit.
TEST(StreamingFeedPlan, AFullWindowCommitsSlowerButFeasible) {
  std::string text = "G21 G90 G1 F24000\n";
  for (int i = 1; i <= 20000; ++i) text += "X" + std::to_string(i * 0.005) + "\n";
  const Program p = interpretGcode(text, "t.ngc").program;
  const Machine m = defaultMachine();
  const FeedPlan whole = planFeed(p, m);
  const WindowedPlan windowed = planWindowed(p, m, {16, 256});
  EXPECT_GT(windowed.forcedCommits, 0u);
  EXPECT_LE(windowed.largestHeld, 256u + 16u + 1u);
  ASSERT_EQ(windowed.segments.size(), whole.segments.size());
  double previousExit = 0;
  bool slower = false;
  for (std::size_t i = 0; i < whole.segments.size(); ++i) {
    const PlannedSegment& s = windowed.segments[i];
    SCOPED_TRACE("segment " + std::to_string(i));
    EXPECT_EQ(s.entrySpeed, previousExit);
    EXPECT_LE(s.entrySpeed, whole.segments[i].entrySpeed);
    EXPECT_LE(s.entrySpeed, s.entryLimit);
    EXPECT_LE(s.peakSpeed, std::max({s.cap, s.entrySpeed, s.exitSpeed}));
    // Each ramp within the segment's acceleration.
    const double reach = 2.0 * s.accel * s.length * (1 + 1e-12);
    EXPECT_LE(s.exitSpeed * s.exitSpeed, s.entrySpeed * s.entrySpeed + reach + 1e-12);
    EXPECT_LE(s.entrySpeed * s.entrySpeed, s.exitSpeed * s.exitSpeed + reach + 1e-12);
    slower = slower || s.entrySpeed < whole.segments[i].entrySpeed;
    previousExit = s.exitSpeed;
  }
  EXPECT_EQ(previousExit, 0.0);
  EXPECT_TRUE(slower);
}

TEST(StreamingSimulation, PlanningErrorsNameTheLineAndProgramErrorsComeFirst) {
  const Machine m = defaultMachine();
  {
    SampleBuffer samples;
    StreamingSimulation simulation(m, Vec3::Zero(), "t.ngc", samples);
    interpretGcodeStream("G1 X1 F100\nG4 P100000\nG1 X2\n", "t.ngc", simulation, {}, 1);
    try {
      simulation.finish();
      ADD_FAILURE() << "a dwell of 28 h was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("t.ngc:2"), std::string::npos) << e.what();
    }
  }
  // The day-long dwell on line 2 and a bad block on line 4: the program's error is reported, and
  // no dump is left.
  const auto dir = test::scratchDir();
  const std::string gcode = (dir / "two-errors.ngc").string(), biip = (dir / "two-errors.biip").string();
  {
    std::ofstream(gcode) << "G1 X1 F100\nG4 P100000\nG1 X2\nG1 X3 X4\n";
  }
  const StreamedSimulation r = simulateGcodeFileToBiip(gcode, m, biip);
  ASSERT_EQ(r.interpretation.errors.size(), 1u);
  EXPECT_EQ(r.interpretation.errors[0].line, 4u);
  EXPECT_FALSE(std::filesystem::exists(biip));
}

TEST(StreamingSimulation, TheDumpIsByteForByteTheWholeProgramDump) {
  const std::string path = test::sourcePath("samples/wuzhishan.nc");
  const Machine m = defaultMachine();
  const auto dir = test::scratchDir();
  const std::string wholeBiip = (dir / "whole.biip").string(), streamedBiip = (dir / "streamed.biip").string();
  const SimulationReport wholeReport = simulateToBiip(load(path), m, wholeBiip);
  const StreamedSimulation streamed = simulateGcodeFileToBiip(path, m, streamedBiip);
  ASSERT_TRUE(streamed.interpretation.ok());
  expectSameReport(streamed.report, wholeReport);
  EXPECT_EQ(streamed.forcedCommits, 0u);
  const std::string a = test::readFile(wholeBiip), b = test::readFile(streamedBiip);
  EXPECT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == b);
}
