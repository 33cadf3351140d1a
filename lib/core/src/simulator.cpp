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

namespace {

std::string simulationMetadata(const std::string& source, const Machine& machine) {
  const nlohmann::json meta = {{"source", source},
                               {"units", "mm"},
                               {"writer", "isurface-cli 0.1.0 simulate"},
                               {"coordinates", "workpiece"},
                               {"machine", machineJson(machine)}};
  return meta.dump();
}

}  // namespace

SimulationReport simulateToBiip(const Program& program, const Machine& machine, const std::string& path,
                                const ProgressCallback& progress) {
  BiipWriter writer(path, simulationChannels(), machine.cycle, simulationMetadata(program.source, machine));
  BiipSink sink(writer);
  const SimulationReport report = simulate(program, machine, sink, progress);
  writer.commit();
  return report;
}

StreamingSimulation::StreamingSimulation(const Machine& machine, const Vec3& start, const std::string& source,
                                         SampleSink& sink, const StreamingFeedPlanner::Window& window)
    : machine_(machine),
      sink_(sink),
      planner_(machine, LimitBudget{}, source, window),
      source_(source),
      start_(start),
      moveStart_(start),
      firstMoveStart_(start) {
  report_.filterTime1 = planner_.filterTime1();
  report_.filterTime2 = planner_.filterTime2();
}

StreamingSimulation::~StreamingSimulation() = default;

void StreamingSimulation::consume(const Move* moves, std::size_t count, std::uint64_t firstIndex) {
  if (simulationError_) return;
  try {
    for (std::size_t i = 0; i < count; ++i) {
      if (firstIndex + i > 0xffffffffu)
        throw InputError(
            Diagnostic{source_, moves[i].line, 0, "more than 4,294,967,295 moves: too many for a Biip block channel"});
      planner_.add(static_cast<std::uint32_t>(firstIndex + i), moves[i], moveStart_);
      moves_.push_back(moves[i]);
      moveStart_ = moves[i].end;
      planner_.take(final_);
      if (!final_.empty()) interpolateFinalSegments();
    }
  } catch (const InputError& e) {
    simulationError_ = e;
  }
}

void StreamingSimulation::interpolateFinalSegments() {
  if (!interpolator_)
    interpolator_ = std::make_unique<StreamingInterpolator>(machine_, start_, planner_.holdBefore(),
                                                            planner_.filterTime1(), planner_.filterTime2(), sink_);
  for (const PlannedSegment& segment : final_) {
    // The moves before this segment's (dwells, zero-length moves, segments walked) are done.
    while (firstMove_ < segment.move) {
      firstMoveStart_ = moves_.front().end;
      moves_.pop_front();
      ++firstMove_;
    }
    interpolator_->add(segment, moves_.front(), firstMoveStart_);
    report_.pathLength += segment.length;
    ++report_.segments;
  }
  final_.clear();
}

SimulationReport StreamingSimulation::finish() {
  if (simulationError_) throw *simulationError_;
  planner_.finish();
  planner_.take(final_);
  interpolateFinalSegments();
  const InterpolationSummary summary = interpolator_->finish();
  report_.samples = summary.samples;
  report_.machiningTime = summary.duration;
  return report_;
}

StreamedSimulation simulateGcodeFileToBiip(const std::string& gcodePath, const Machine& machine,
                                           const std::string& biipPath, const InterpreterOptions& options) {
  BiipWriter writer(biipPath, simulationChannels(), machine.cycle, simulationMetadata(gcodePath, machine));
  BiipSink sink(writer);
  StreamingSimulation simulation(machine, options.startPosition, gcodePath, sink);
  StreamedSimulation result;
  result.interpretation = interpretGcodeFileStream(gcodePath, simulation, options);
  if (!result.interpretation.ok()) return result;  // the writer removes its temporary file
  result.report = simulation.finish();
  result.largestWindow = simulation.planner().largestHeld();
  result.forcedCommits = simulation.planner().forcedCommits();
  writer.commit();
  return result;
}

}  // namespace isurface
