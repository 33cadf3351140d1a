#include "isurface/nc/simulator.h"

#include <cstddef>

namespace isurface {

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

}  // namespace isurface
