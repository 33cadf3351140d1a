#include "isurface/core/simulator.h"

#include <cstddef>
#include <nlohmann/json.hpp>

namespace isurface {

namespace {

class BiipSink : public SampleSink {
 public:
  explicit BiipSink(BiipWriter& writer) : writer_(writer) {}
  void consume(const SimSample* samples, std::size_t count) override {
    for (std::size_t i = 0; i < count; ++i) writer_.append(&samples[i]);
  }

 private:
  BiipWriter& writer_;
};

nlohmann::json machineJson(const Machine& m) {
  nlohmann::json axes = nlohmann::json::object();
  const char* names[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    const AxisLimits& a = m.axes[i];
    axes[names[i]] = {{"max_velocity_mm_min", a.maxVelocity * 60},
                      {"max_acceleration_mm_s2", a.maxAcceleration},
                      {"max_jerk_mm_s3", a.maxJerk},
                      {"position_gain_1_s", a.positionGain},
                      {"velocity_feed_forward", a.velocityFeedForward},
                      {"velocity_loop_time_constant_s", a.velocityLoopTimeConstant}};
  }
  return {{"name", m.name},
          {"cycle_s", m.cycle},
          {"rapid_mm_min", m.rapidVelocity * 60},
          {"chord_tolerance_mm", m.chordTolerance},
          {"axes", axes}};
}

}  // namespace

std::vector<BiipChannel> simulationChannels() {
  std::vector<BiipChannel> channels = {
      {"line", BiipType::U32, offsetof(SimSample, line)}, {"block", BiipType::U32, offsetof(SimSample, block)},
      {"x", BiipType::F64, offsetof(SimSample, x)},       {"y", BiipType::F64, offsetof(SimSample, y)},
      {"z", BiipType::F64, offsetof(SimSample, z)},       {"fb_x", BiipType::F64, offsetof(SimSample, fbX)},
      {"fb_y", BiipType::F64, offsetof(SimSample, fbY)},  {"fb_z", BiipType::F64, offsetof(SimSample, fbZ)},
      {"feed", BiipType::F64, offsetof(SimSample, feed)}};
  return channels;
}

SimulationReport simulate(const Program& program, const Machine& machine, SampleSink& sink,
                          const ProgressCallback& progress) {
  const FeedPlan plan = planFeed(program, machine, LimitBudget{}, [&](double f) {
    if (progress) progress(0.1 * f);
  });
  const InterpolationSummary summary = interpolate(program, machine, plan, sink, [&](double f) {
    if (progress) progress(0.1 + 0.9 * f);
  });
  SimulationReport report;
  report.samples = summary.samples;
  report.machiningTime = summary.duration;
  report.segments = plan.segments.size();
  for (const PlannedSegment& s : plan.segments) report.pathLength += s.length;
  report.filterTime1 = plan.filterTime1;
  report.filterTime2 = plan.filterTime2;
  return report;
}

SimulationReport simulateToBiip(const Program& program, const Machine& machine, const std::string& path,
                                const ProgressCallback& progress) {
  nlohmann::json meta = {{"source", program.source},
                         {"units", "mm"},
                         {"writer", "isurface-cli 0.1.0 simulate"},
                         {"coordinates", "workpiece"},
                         {"machine", machineJson(machine)}};
  BiipWriter writer(path, simulationChannels(), machine.cycle, meta.dump());
  BiipSink sink(writer);
  const SimulationReport report = simulate(program, machine, sink, progress);
  writer.commit();
  return report;
}

}  // namespace isurface
