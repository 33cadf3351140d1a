#include "isurface/nc/simulator.h"

#include "isurface/nc/feed_cap_notes.h"
#include "isurface/nc/linuxcnc_motion.h"
#include "isurface/nc/run_bound.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace isurface {

namespace {

// Samples after the plan's last one besides the filters' window, and the most a sink is told
// to expect (a hint: more than a run could hold in memory is not worth making room for).
constexpr std::size_t kExpectedTail = 16;
constexpr std::size_t kLargestExpectation = std::size_t(1) << 32;

// Five-axis motion is planned on a machine with rotary axes under the linuxcnc-2.9 control;
// elsewhere a program that turns them is refused: its tool tip simulated as if A, B and C stood
// still would show feeds no machine runs.
InputError rotaryMotionRefused(const Machine& machine, const std::string& source, std::uint32_t line,
                               std::uint32_t column, const std::array<double, 3>& abc) {
  const std::string why =
      machine.kinematics
          ? "five-axis motion is simulated under the linuxcnc-2.9 control only (\"control\": {\"planner\": "
            "\"linuxcnc-2.9\"})"
          : "the machine has no rotary axes: simulate on a machine whose description has \"kinematics\" "
            "(docs/five-axis.md; resources/machines/linuxcnc-xyzbc-trt.json is one)";
  return InputError(Diagnostic{source, line, column,
                               fmt::format("the rotary axes move here (A {:g} B {:g} C {:g} deg): {}, and the tool tip "
                                           "alone would show feeds the machine does not run",
                                           abc[0], abc[1], abc[2], why)});
}

void requireJointsKept(const SampleSink& sink) {
  if (!sink.keepsJoints()) throw std::logic_error("a five-axis run was given a sink that drops its joints");
}

Vec3 asVec3(const std::array<double, 3>& abc) { return Vec3(abc[0], abc[1], abc[2]); }

// The interpolator does not know the program's name; its errors get it here.
InputError naming(const InputError& e, const std::string& source) {
  if (!e.diagnostic().file.empty()) return e;
  Diagnostic d = e.diagnostic();
  d.file = source;
  return InputError(d);
}

// Refuses a run whose planned time passes the machine's longest run, before its samples are
// made: `move` is where the plan passes it (null: at the end).
void checkRunLength(double seconds, const Machine& machine, const Move* move, const std::string& source) {
  if (seconds <= machine.longestRun) return;
  throw runTooLongError(machine, source, move ? move->line : 0, move ? move->column : 0u);
}

// The program through LinuxCNC 2.9's planner, cycle by cycle.
SimulationReport simulateOnLinuxCnc(const Program& program, const Machine& machine, SampleSink& sink,
                                    const ProgressCallback& progress) {
  LinuxCncMotion motion(machine, program.start, sink);
  std::size_t nextBlending = 0;
  for (std::size_t i = 0; i < program.moves.size(); ++i) {
    while (nextBlending < program.blending.size() && program.blending[nextBlending].firstMove <= i)
      motion.blendingChanged(program.blending[nextBlending++]);
    try {
      motion.add(i, program.moves[i], program.startOf(i), asVec3(program.rotaryAt(i)));
    } catch (const InputError& e) {
      throw naming(e, program.source);
    }
    if ((i & 4095) == 0) {
      checkRunLength(motion.plannedSeconds(), machine, &program.moves[i], program.source);
      if (progress) progress(double(i) / double(program.moves.size()));
    }
  }
  const InterpolationSummary summary = motion.finish();
  checkRunLength(summary.duration, machine, nullptr, program.source);
  SimulationReport report;
  report.samples = summary.samples;
  report.machiningTime = summary.duration;
  report.segments = motion.segments();
  report.pathLength = motion.pathLength();
  report.warnings = motion.jointLimitWarnings(program.source);
  return report;
}

}  // namespace

namespace {

SimulationReport simulateWithoutNotes(const Program& program, const Machine& machine, SampleSink& sink,
                                      const ProgressCallback& progress) {
  if (!program.rotary.empty()) {
    const std::size_t first = static_cast<std::size_t>(program.rotary.front().move);
    const Move& m = program.moves.at(first);
    if (!simulatesFiveAxis(machine))
      throw rotaryMotionRefused(machine, program.source, m.line, m.column, program.rotary.front().abc);
    requireJointsKept(sink);
  }
  if (machine.control.planner == TrajectoryPlanner::LinuxCnc29) return simulateOnLinuxCnc(program, machine, sink, progress);
  const FeedPlan plan = planFeed(program, machine, LimitBudget{}, [&](double f) {
    if (progress) progress(0.1 * f);
  });
  // Dwells and motion in program order, so that the move named is the one that passes the
  // bound; then the plan's own total, with the holds of its stops.
  double known = 0;
  std::size_t next = 0;
  auto dwellsUpTo = [&](std::size_t end) {
    for (; next < end; ++next)
      if (program.moves[next].kind == MoveKind::Dwell) {
        known += std::max(0.0, program.moves[next].dwellSeconds());
        checkRunLength(known, machine, &program.moves[next], program.source);
      }
  };
  double planned = plan.holdBefore;
  for (std::size_t k = 0; k < plan.segments.size(); ++k) {
    const PlannedSegment& segment = plan.segments[k];
    const Move* move = &program.moves[segment.move];
    dwellsUpTo(segment.move);
    known += segment.motionTime();
    planned += segment.motionTime();
    checkRunLength(known, machine, move, program.source);
    checkRunLength(planned, machine, move, program.source);
    dwellsUpTo(k + 1 < plan.segments.size() ? plan.segments[k + 1].move : program.moves.size());
    planned += segment.holdAfter;
    checkRunLength(planned, machine, move, program.source);
  }
  dwellsUpTo(program.moves.size());
  checkRunLength(planned, machine, nullptr, program.source);
  // The filters' window settles after the plan's last sample.
  const double expected = (planned + plan.filterTime1 + plan.filterTime2) / machine.cycle + kExpectedTail;
  if (std::isfinite(expected) && expected < double(kLargestExpectation)) sink.expect(static_cast<std::size_t>(expected));
  InterpolationSummary summary;
  try {
    summary = interpolate(program, machine, plan, sink, [&](double f) {
      if (progress) progress(0.1 + 0.9 * f);
    });
  } catch (const InputError& e) {
    throw naming(e, program.source);
  }
  SimulationReport report;
  report.samples = summary.samples;
  report.machiningTime = summary.duration;
  report.segments = plan.segments.size();
  for (const PlannedSegment& s : plan.segments) report.pathLength += s.length;
  report.filterTime1 = plan.filterTime1;
  report.filterTime2 = plan.filterTime2;
  return report;
}

}  // namespace

bool simulatesFiveAxis(const Machine& machine) {
  return machine.kinematics && machine.control.planner == TrajectoryPlanner::LinuxCnc29;
}

SimulationReport simulate(const Program& program, const Machine& machine, SampleSink& sink,
                          const ProgressCallback& progress) {
  SimulationReport report = simulateWithoutNotes(program, machine, sink, progress);
  FeedCapNotes feeds(machine);
  for (std::size_t i = 0; i < program.moves.size(); ++i) feeds.note(program.moves[i], program.startOf(i));
  if (auto w = feeds.warning(program.source)) report.warnings.push_back(*w);
  return report;
}

StreamingSimulation::StreamingSimulation(const Machine& machine, const Vec3& start, const std::string& source,
                                         SampleSink& sink, const StreamingFeedPlanner::Window& window)
    : machine_(machine),
      sink_(sink),
      planner_(machine, LimitBudget{}, source, window),
      source_(source),
      start_(start),
      moveStart_(start) {
  report_.filterTime1 = planner_.filterTime1();
  report_.filterTime2 = planner_.filterTime2();
  // LinuxCNC 2.9 has no corner or jerk filters: its samples are the planner's own.
  if (machine.control.planner == TrajectoryPlanner::LinuxCnc29) {
    linuxcnc_ = std::make_unique<LinuxCncMotion>(machine, start, sink);
    report_.filterTime1 = report_.filterTime2 = 0;
  }
}

void StreamingSimulation::blendingChanged(const PathBlending& blending) {
  if (linuxcnc_) linuxcnc_->blendingChanged(blending);
}

void StreamingSimulation::rotaryChanged(const RotaryPosition& rotary) {
  if (simulatesFiveAxis(machine_)) {
    requireJointsKept(sink_);
    rotaryChanges_.push_back(rotary);
  } else if (!firstRotary_) {
    firstRotary_ = rotary;
  }
}

StreamingSimulation::~StreamingSimulation() = default;

void StreamingSimulation::consume(const Move* moves, std::size_t count, std::uint64_t firstIndex) {
  if (simulationError_) return;
  try {
    if (firstRotary_ && firstRotary_->move >= firstIndex && firstRotary_->move < firstIndex + count) {
      const Move& m = moves[firstRotary_->move - firstIndex];
      throw rotaryMotionRefused(machine_, source_, m.line, m.column, firstRotary_->abc);
    }
    if (linuxcnc_) {
      for (std::size_t i = 0; i < count; ++i) {
        feeds_.note(moves[i], moveStart_);
        while (!rotaryChanges_.empty() && rotaryChanges_.front().move <= firstIndex + i) {
          rotary_ = asVec3(rotaryChanges_.front().abc);
          rotaryChanges_.pop_front();
        }
        linuxcnc_->add(firstIndex + i, moves[i], moveStart_, rotary_);
        moveStart_ = moves[i].end;
      }
      checkRunLength(linuxcnc_->plannedSeconds(), machine_, count ? &moves[count - 1] : nullptr, source_);
      return;
    }
    for (std::size_t i = 0; i < count; ++i) {
      if (firstIndex + i > 0xffffffffu)
        throw InputError(
            Diagnostic{source_, moves[i].line, moves[i].column, "more than 4,294,967,295 moves: too many for a Biip block channel"});
      if (moves[i].kind == MoveKind::Dwell && moves[i].dwellSeconds() > 0) {
        if (pendingDwells_.size() < kMostPendingDwells)
          pendingDwells_.push_back({firstIndex + i, moves[i].dwellSeconds(), moves[i]});
        else
          pendingDwells_.back().seconds += moves[i].dwellSeconds();
      }
      feeds_.note(moves[i], moveStart_);
      planner_.add(static_cast<std::uint32_t>(firstIndex + i), moves[i], moveStart_);
      // Only moves that may become segments wait for the interpolator: a program of millions
      // of dwells or zero-length moves must not pile them up.
      const bool standing = moves[i].kind == MoveKind::Dwell ||
                            ((moves[i].kind == MoveKind::Linear || moves[i].kind == MoveKind::Rapid) &&
                             moves[i].end == moveStart_);
      if (!standing) moves_.push_back({firstIndex + i, moves[i], moveStart_});
      moveStart_ = moves[i].end;
      planner_.take(final_);
      if (!final_.empty()) interpolateFinalSegments();
    }
  } catch (const InputError& e) {
    simulationError_ = naming(e, source_);
  }
}

void StreamingSimulation::interpolateFinalSegments() {
  if (!interpolator_)
    interpolator_ = std::make_unique<StreamingInterpolator>(machine_, start_, planner_.holdBefore(),
                                                            planner_.filterTime1(), planner_.filterTime2(), sink_);
  for (const PlannedSegment& segment : final_) {
    // The moves before this segment's (segments walked) are done.
    while (!moves_.empty() && moves_.front().index < segment.move) moves_.pop_front();
    if (moves_.empty() || moves_.front().index != segment.move)
      throw std::logic_error("a planned segment's move was not kept for the interpolator");
    if (plannedTime_ == 0) plannedTime_ = planner_.holdBefore();
    countDwellsBefore(segment.move);
    countedTime_ += segment.motionTime();
    plannedTime_ += segment.motionTime();
    checkRunLength(countedTime_, machine_, &moves_.front().move, source_);
    checkRunLength(plannedTime_, machine_, &moves_.front().move, source_);
    // Its hold: the dwells up to the next move with motion, then the plan's total with it.
    countDwellsBefore(moves_.size() > 1 ? moves_[1].index : std::numeric_limits<std::uint64_t>::max());
    plannedTime_ += segment.holdAfter;
    checkRunLength(plannedTime_, machine_, &moves_.front().move, source_);
    interpolator_->add(segment, moves_.front().move, moves_.front().start);
    report_.pathLength += segment.length;
    ++report_.segments;
  }
  final_.clear();
}

void StreamingSimulation::countDwellsBefore(std::uint64_t index) {
  while (!pendingDwells_.empty() && pendingDwells_.front().index < index) {
    countedTime_ += pendingDwells_.front().seconds;
    checkRunLength(countedTime_, machine_, &pendingDwells_.front().move, source_);
    pendingDwells_.pop_front();
  }
}

SimulationReport StreamingSimulation::finish() {
  if (simulationError_) throw *simulationError_;
  InterpolationSummary summary;
  if (linuxcnc_) {
    try {
      summary = linuxcnc_->finish();
      checkRunLength(summary.duration, machine_, nullptr, source_);
    } catch (const InputError& e) {
      throw naming(e, source_);
    }
    report_.samples = summary.samples;
    report_.machiningTime = summary.duration;
    report_.segments = linuxcnc_->segments();
    report_.pathLength = linuxcnc_->pathLength();
    report_.warnings = linuxcnc_->jointLimitWarnings(source_);
    if (auto w = feeds_.warning(source_)) report_.warnings.push_back(*w);
    return report_;
  }
  try {
    planner_.finish();
    planner_.take(final_);
    interpolateFinalSegments();
    countDwellsBefore(std::numeric_limits<std::uint64_t>::max());  // a program of dwells alone
    checkRunLength(std::max(plannedTime_, planner_.holdBefore()), machine_, nullptr, source_);
    summary = interpolator_->finish();
  } catch (const InputError& e) {
    throw naming(e, source_);
  }
  report_.samples = summary.samples;
  report_.machiningTime = summary.duration;
  if (auto w = feeds_.warning(source_)) report_.warnings.push_back(*w);
  return report_;
}

}  // namespace isurface
