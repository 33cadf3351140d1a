// The linuxcnc-2.9 control on a five-axis machine against LinuxCNC 2.9's own planner with its
// xyzbc-trt kinematics: programs recorded on it (tests/data/linuxcnc-2.9-xyzbc-trt and
// -independent), simulated with resources/machines/linuxcnc-xyzbc-trt.json and compared in
// motion time, time per line and the joints along the path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "five_axis_recording.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/machine/machine.h"
#include "isurface/nc/sample_trajectory.h"
#include "isurface/nc/simulator.h"
#include "test_locations.h"

namespace isurface {
namespace {

namespace fs = std::filesystem;

// One cycle of either run: the axes (tip mm, then the rotary axes deg), the joints, the line.
struct Pose {
  std::array<double, 5> axes{}, joints{};
  unsigned line = 0;
};

Machine trtMachine() { return loadMachine(std::string(test::sourceDir()) + "/resources/machines/linuxcnc-xyzbc-trt.json"); }

std::vector<Pose> simulated(const fs::path& program, const Machine& machine) {
  const InterpretResult read = interpretGcodeFile(program.string());
  EXPECT_TRUE(read.ok()) << program;
  TrajectorySink sink(machine.cycle, program.string(), false);
  sink.keepJointsOf(*machine.kinematics);
  simulate(read.program, machine, sink);
  const Trajectory t = sink.take();
  const char* names[] = {"b", "c", "joint_x", "joint_y", "joint_z", "joint_b", "joint_c"};
  std::vector<const std::vector<double>*> channels;
  for (const char* name : names) {
    channels.push_back(t.extraChannel(name));
    EXPECT_NE(channels.back(), nullptr) << name;
    if (!channels.back()) return {};
  }
  std::vector<Pose> poses(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    poses[i].axes = {t.x[i], t.y[i], t.z[i], (*channels[0])[i], (*channels[1])[i]};
    for (std::size_t j = 0; j < 5; ++j) poses[i].joints[j] = (*channels[2 + j])[i];
    poses[i].line = t.line[i];
  }
  return poses;
}

// The recording with each row's joints taken from two cycles later: LinuxCNC commands a joint
// as the kinematics of the axes two servo cycles before.
std::vector<Pose> recorded(const fs::path& gz) {
  const std::vector<test::FiveAxisRow> rows = test::readFiveAxisRecording(gz);
  std::vector<Pose> poses;
  for (std::size_t i = 0; i + 2 < rows.size(); ++i) poses.push_back({rows[i].axes, rows[i + 2].joints, rows[i].line});
  return poses;
}

// [first, last]: from the cycle before the first that moves to the last that moves.
std::pair<std::size_t, std::size_t> motionSpan(const std::vector<Pose>& p) {
  std::size_t first = 0, last = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    if (p[i].axes != p[i - 1].axes) {
      if (first == 0) first = i;
      last = i;
    }
  return {first == 0 ? 0 : first - 1, last};
}

struct Agreement {
  double totalDifference = 0;  // share of the recording's motion time
  double lineP90 = 0;          // share of a line's time, lines of 20 ms and more
  std::size_t lines = 0;
  double worstLinearJoint = 0;  // mm
  double worstRotaryJoint = 0;  // deg
};

double distanceSquared(const std::array<double, 5>& a, const std::array<double, 5>& b) {
  double d = 0;
  for (std::size_t k = 0; k < 5; ++k) d += (a[k] - b[k]) * (a[k] - b[k]);
  return d;
}

// The joints of each recorded cycle against ours at the same point of the path: the nearest
// point (axes, mm and deg alike) of our run's polyline at or after where the last cycle matched
// (a path that turns back passes its own poses again: never matched backwards).
void compareJoints(const std::vector<Pose>& rec, std::pair<std::size_t, std::size_t> recSpan,
                   const std::vector<Pose>& sim, std::pair<std::size_t, std::size_t> simSpan, Agreement& a) {
  constexpr std::size_t kWindow = 300;
  std::size_t at = simSpan.first + 1;
  for (std::size_t i = recSpan.first; i <= recSpan.second; ++i) {
    const Pose& p = rec[i];
    double best = INFINITY, bestShare = 0;
    std::size_t bestK = at;
    for (std::size_t k = at; k <= std::min(simSpan.second, at + kWindow); ++k) {
      const Pose &s0 = sim[k - 1], &s1 = sim[k];
      double along = 0, length = 0;
      for (std::size_t c = 0; c < 5; ++c) {
        const double d = s1.axes[c] - s0.axes[c];
        along += (p.axes[c] - s0.axes[c]) * d;
        length += d * d;
      }
      const double share = length > 0 ? std::clamp(along / length, 0.0, 1.0) : 0.0;
      std::array<double, 5> q;
      for (std::size_t c = 0; c < 5; ++c) q[c] = s0.axes[c] + (s1.axes[c] - s0.axes[c]) * share;
      const double d = distanceSquared(p.axes, q);
      if (d < best) best = d, bestK = k, bestShare = share;
    }
    at = bestK;
    for (std::size_t j = 0; j < 5; ++j) {
      const double ours = sim[bestK - 1].joints[j] + (sim[bestK].joints[j] - sim[bestK - 1].joints[j]) * bestShare;
      double& worst = j < 3 ? a.worstLinearJoint : a.worstRotaryJoint;
      worst = std::max(worst, std::abs(ours - p.joints[j]));
    }
  }
}

Agreement agreement(const fs::path& folder, const std::string& name) {
  const Machine machine = trtMachine();
  const std::vector<Pose> sim = simulated(folder / (name + ".ngc"), machine);
  const std::vector<Pose> rec = recorded(folder / (name + ".halsampler.txt.gz"));
  Agreement a;
  if (sim.size() < 2 || rec.size() < 2) {
    ADD_FAILURE() << name << ": no run to compare";
    return a;
  }
  const auto simSpan = motionSpan(sim), recSpan = motionSpan(rec);
  const double simTime = double(simSpan.second - simSpan.first), recTime = double(recSpan.second - recSpan.first);
  a.totalDifference = (simTime - recTime) / recTime;
  std::map<unsigned, double> simLine, recLine;  // cycles per line
  for (std::size_t i = simSpan.first + 1; i <= simSpan.second; ++i) simLine[sim[i].line] += 1;
  for (std::size_t i = recSpan.first + 1; i <= recSpan.second; ++i) recLine[rec[i].line] += 1;
  std::vector<double> shares;
  for (const auto& [line, cycles] : recLine)
    if (cycles * machine.cycle >= 0.020) shares.push_back(std::abs(simLine[line] - cycles) / cycles);
  std::sort(shares.begin(), shares.end());
  a.lines = shares.size();
  a.lineP90 = shares.empty() ? 0 : shares[static_cast<std::size_t>(0.9 * double(shares.size() - 1))];
  compareJoints(rec, recSpan, sim, simSpan, a);
  return a;
}

// The figures the five-axis simulation is held to: total motion time within 3 %, per line of
// 20 ms or more |difference| p90 within 5 %, joints within 0.01 mm / 0.01 deg of LinuxCNC's at
// the same point of the path.
void expectEveryRecordingAgrees(const fs::path& folder, std::size_t atLeast) {
  const std::vector<std::string> names = test::recordingNames(folder);
  ASSERT_GE(names.size(), atLeast) << "the reference recordings are missing from " << folder;
  for (const std::string& name : names) {
    const Agreement a = agreement(folder, name);
    std::printf("%-18s total %+6.2f %%  line p90 %5.2f %% of %3zu lines  joints within %.4f mm %.4f deg\n",
                name.c_str(), 100 * a.totalDifference, 100 * a.lineP90, a.lines, a.worstLinearJoint,
                a.worstRotaryJoint);
    EXPECT_LT(std::abs(a.totalDifference), 0.03) << name;
    EXPECT_LT(a.lineP90, 0.05) << name;
    EXPECT_LT(a.worstLinearJoint, 0.01) << name;
    EXPECT_LT(a.worstRotaryJoint, 0.01) << name;
  }
}

TEST(fiveAxisReference, EveryRecordingAgreesWithLinuxCncsFiveAxisPlanner) {
  expectEveryRecordingAgrees(fs::path(test::sourceDir()) / "tests/data/linuxcnc-2.9-xyzbc-trt", 11);
}

// Programs written apart from the planner by other methods and recorded after it was done
// (tests/data/linuxcnc-2.9-xyzbc-trt-independent/README.md).
TEST(fiveAxisReference, ProgramsRecordedAfterThePlannerWasWrittenAgree) {
  expectEveryRecordingAgrees(fs::path(test::sourceDir()) / "tests/data/linuxcnc-2.9-xyzbc-trt-independent", 6);
}

}  // namespace
}  // namespace isurface
