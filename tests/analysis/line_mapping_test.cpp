// Mapping trace samples back to G-code lines along the programmed path.
#include <gtest/gtest.h>

#include <cstdio>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/analysis/line_mapping.h"
#include "isurface/gcode/path_segment.h"
#include "isurface/io/trace_import.h"
#include "test_support.h"

namespace isurface {
namespace {

Program interpret(const std::string& text) {
  InterpretResult r = interpretGcode(text, "test.ngc");
  EXPECT_TRUE(r.ok());
  return std::move(r.program);
}

// Samples the program's exact path every `step` mm, keeping each sample's true line.
Trajectory samplePath(const Program& program, double step, std::vector<std::uint32_t>& truth) {
  Trajectory t;
  for (std::size_t m = 0; m < program.moves.size(); ++m) {
    if (!program.moves[m].isMotion()) continue;
    const PathSegment seg = PathSegment::from(program, m);
    // Points strictly inside the move: at its ends two lines are equally right.
    for (double s = step * 0.5; s < seg.length; s += step) {
      const Vec3 p = seg.at(s);
      t.x.push_back(p.x()), t.y.push_back(p.y()), t.z.push_back(p.z());
      truth.push_back(program.moves[m].line);
    }
  }
  t.line.assign(t.x.size(), 0);
  return t;
}

double agreement(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
  std::size_t same = 0;
  for (std::size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
  return a.empty() ? 0.0 : double(same) / double(a.size());
}

const char* kSmallProgram =
    "G21 G90 G17\n"
    "G0 X0 Y0 Z5\n"
    "G1 Z0 F600\n"         // straight back down the way the rapid went up
    "G1 X10 F1200\n"
    "G2 X20 Y0 I5 J0\n"    // half circle
    "G3 X30 Y0 R5\n"
    "G1 Y10\n"
    "G1 X0\n"               // crosses over nothing, returns along y = 10
    "G17 G2 X0 Y10 I0 J-5 Z-1\n"  // full helical turn
    "G0 Z5\n"
    "M2\n";

TEST(lineMapping, syntheticTraceMapsBackToItsLines) {
  const Program program = interpret(kSmallProgram);
  std::vector<std::uint32_t> truth;
  const Trajectory t = samplePath(program, 0.05, truth);
  ASSERT_GT(t.size(), 1000u);
  const LineMapping mapping = mapSamplesToLines(t, program);
  EXPECT_GE(agreement(mapping.line, truth), 0.99);
  EXPECT_EQ(mapping.report.samples, t.size());
  EXPECT_LT(mapping.report.maxDistance, 1e-6);
  EXPECT_DOUBLE_EQ(mapping.report.fractionWithin, 1.0);
}

TEST(lineMapping, retracedMoveFollowsTheDirectionOfTravel) {
  const Program program = interpret("G0 X0 Y0 Z5\nG1 Z0 F600\nG1 X5\nM2\n");
  std::vector<std::uint32_t> truth;
  const Trajectory t = samplePath(program, 0.1, truth);
  const LineMapping mapping = mapSamplesToLines(t, program);
  EXPECT_EQ(mapping.line, truth);
}

TEST(lineMapping, offsetSamplesReportTheirDistance) {
  const Program program = interpret("G1 X10 F600\nM2\n");
  Trajectory t;
  for (int i = 0; i <= 10; ++i) t.x.push_back(i), t.y.push_back(i % 2 ? 0.2 : 0.0), t.z.push_back(0);
  const LineMapping mapping = mapSamplesToLines(t, program);
  EXPECT_NEAR(mapping.report.maxDistance, 0.2, 1e-12);
  EXPECT_NEAR(mapping.report.meanDistance, 0.2 * 5 / 11, 1e-12);
  EXPECT_NEAR(mapping.report.fractionWithin, 6.0 / 11, 1e-12);
  EXPECT_NEAR(distanceToMove(program, 0, Vec3(12, 0, 0)), 2.0, 1e-12);
}

TEST(lineMapping, blendHandoverGivesCornerSamplesTheNextLine) {
  // Two 1 mm moves meeting at 90 degrees, then a reversal (never blended).
  const Program program = interpret("G1 X1 F600\nG1 Y1\nG1 Y0\nM2\n");
  Trajectory t;
  for (double x : {0.1, 0.4, 0.6, 0.9}) t.x.push_back(x), t.y.push_back(0), t.z.push_back(0);
  for (double y : {0.3, 0.95}) t.x.push_back(1), t.y.push_back(y), t.z.push_back(0);
  LineMappingOptions o;
  o.nextLineInBlends = true;
  o.blendFraction = 0.3;  // 0.3 mm before the corner
  const LineMapping mapping = mapSamplesToLines(t, program, o);
  EXPECT_EQ(mapping.line, (std::vector<std::uint32_t>{1, 1, 1, 2, 2, 2}));
  o.maxBlendLead = 0.05;
  EXPECT_EQ(mapSamplesToLines(t, program, o).line, (std::vector<std::uint32_t>{1, 1, 1, 1, 2, 2}));
}

struct RecordingAgreement {
  LineMappingReport report;
  double fraction = 0;      // of the samples the recording gives a line
  std::size_t compared = 0;
};

RecordingAgreement mapRecording(const Trajectory& recording, const Program& program, const LineMappingOptions& o) {
  Trajectory trace = recording;
  trace.line.assign(trace.size(), 0);
  trace.hasLine = false;
  const LineMapping mapping = mapSamplesToLines(trace, program, o);
  RecordingAgreement a{mapping.report};
  std::size_t agree = 0;
  for (std::size_t i = 0; i < recording.size(); ++i)
    if (recording.line[i] != 0) ++a.compared, agree += recording.line[i] == mapping.line[i];
  a.fraction = a.compared ? double(agree) / double(a.compared) : 0.0;
  const LineMappingReport& r = a.report;
  std::printf("%s: %zu samples, distance mean %.4f mm max %.4f mm, %.2f%% within %.1f mm; "
              "lines agree on %.2f%% of %zu samples\n",
              o.nextLineInBlends ? "linuxcnc handover" : "nearest move", r.samples, r.meanDistance, r.maxDistance,
              100 * r.fractionWithin, r.tolerance, 100 * a.fraction, a.compared);
  return a;
}

TEST(lineMapping, recordingMatchesLinuxcncProgramLines) {
  const std::string tracePath = test::realdataPath("linuxcnc_test.halsampler.txt");
  const std::string programPath = test::realdataPath("linuxcnc_test.ngc");
  ISURFACE_SKIP_WITHOUT_REALDATA(tracePath, programPath);
  const Trajectory recording = importHalsampler(tracePath);
  const InterpretResult interpreted = interpretGcodeFile(programPath);
  ASSERT_TRUE(interpreted.ok());

  // Nearest move only: LinuxCNC names the next line while blending into it, so the recorded
  // line leads the geometry before every blended corner.
  const RecordingAgreement nearest = mapRecording(recording, interpreted.program, {});
  EXPECT_GT(nearest.fraction, 0.80);
  EXPECT_GT(nearest.report.fractionWithin, 0.95);
  EXPECT_LT(nearest.report.meanDistance, 0.05);

  const RecordingAgreement handover = mapRecording(recording, interpreted.program, linuxcncLineMappingOptions());
  EXPECT_GT(handover.fraction, 0.90);
  EXPECT_GT(handover.fraction, nearest.fraction);
}

}  // namespace
}  // namespace isurface
