// Cutter radius compensation in the interpreter: turning it on and off, the tool's radius, the
// codes it forbids, and its offset moves written into the program.
#include <fmt/format.h>

#include <cmath>

#include "interpreter_state.h"
#include "isurface/base/tolerances.h"

namespace isurface::gcode {

bool InterpreterState::setCutterComp(const Block& block, int code, std::uint32_t column) {
  if (code == kG40) {
    if (comp_.on()) {
      const std::string error = comp_.stop(state_.position);  // the next move leaves from where the tool is
      if (!error.empty()) return fail(column, error);
    }
    compOpenMoves_.clear();
    state_.cutterComp = kG40;
    return true;
  }
  if (state_.cutterComp != kG40) return fail(column, "Cannot turn cutter radius comp on when already on");
  if (state_.plane == Plane::YZ)
    return fail(column, "Cutter radius compensation is only possible in the XY (G17) and XZ (G18) planes");
  const bool dynamic = code == kG41_1 || code == kG42_1;
  double radius = 0;  // mm
  if (dynamic) {
    // G41.1 / G42.1 D<diameter>: the diameter in program units, no tool table.
    if (!block.has('D')) return fail(column, "G41.1 and G42.1 need a D word: the tool diameter");
    radius = length(block.get('D')) / 2;  // negative: the other side, as LinuxCNC takes it
  } else {
    int tool = spindleTool_;
    if (block.has('D')) {
      const double d = block.get('D');
      if (d < 0 || std::fabs(d - std::nearbyint(d)) > kWholeNumberTolerance)
        return fail(block.col('D'), "D word with G41 / G42 must be a tool number (a whole number, 0 or more)");
      tool = static_cast<int>(std::nearbyint(d));
    }
    if (!options_.toolDiameters.empty() && tool != 0) {
      const auto found = options_.toolDiameters.find(tool);
      if (found == options_.toolDiameters.end())
        return fail(block.has('D') ? block.col('D') : column,
                    fmt::format("Tool {} is not in the tool table: its radius for cutter compensation is unknown", tool));
      radius = found->second / 2;
    }
  }
  state_.cutterComp = code;
  compOpenMoves_.clear();
  // A zero radius leaves the path as programmed (as LinuxCNC does).
  if (radius != 0) {
    const bool left = (code == kG41 || code == kG41_1) == (radius > 0);
    radius = std::fabs(radius);
    comp_.start(left ? CutterCompensation::kLeft : CutterCompensation::kRight, radius, state_.plane, state_.position,
                state_.inch);
  }
  return true;
}

bool InterpreterState::compensationAllows(const GroupedCodes& groups, int motion) {
  if (!comp_.on()) return true;
  if (groups.has(kGroupPlane)) {
    const int code = groups.code[kGroupPlane];
    const Plane plane = code == kG17 ? Plane::XY : code == kG18 ? Plane::ZX : Plane::YZ;
    if (plane != state_.plane) return fail(groups.column[kGroupPlane], "Cannot change plane with cutter radius comp on");
  }
  const int nonModal = groups.code[kGroupNonModal];
  if (nonModal == kG28 || nonModal == kG30)
    return fail(groups.column[kGroupNonModal], "Cannot use G28 or G30 with cutter radius comp");
  if (nonModal == kG53) return fail(groups.column[kGroupNonModal], "Cannot use G53 with cutter radius comp");
  const bool inverseTime = groups.has(kGroupFeedMode) ? groups.code[kGroupFeedMode] == kG93 : state_.inverseTime;
  if (inverseTime && motion != kG0 && motion != kG80)
    return fail(groups.has(kGroupFeedMode) ? groups.column[kGroupFeedMode] : 1,
                "Inverse time feed (G93) with cutter radius compensation is not supported");
  return true;
}

bool InterpreterState::emitPath(MoveKind kind, const Vec3& end, const Vec3& centre, unsigned turns, float feed,
                                std::uint32_t column) {
  const bool arcMove = kind == MoveKind::ArcCW || kind == MoveKind::ArcCCW;
  if (!comp_.on()) {
    if (arcMove) emitArc(kind, end, centre, turns, feed);
    else emit(kind, end, feed);
    return true;
  }
  CompensationStep step;
  const std::string error = arcMove ? comp_.arc(state_.position, end, centre, kind == MoveKind::ArcCCW, turns, step)
                                    : comp_.line(state_.position, end, kind == MoveKind::Rapid, step);
  if (!error.empty()) return fail(column, error);
  if (step.openMoveEnd) {
    const PlaneAxes ax = planeAxes(state_.plane);
    for (const std::uint64_t index : compOpenMoves_) {
      if (index < delivered_) continue;  // never: firstHeldMove() keeps them
      Move& m = moves_[static_cast<std::size_t>(index - delivered_)];
      m.end[ax.u] = step.openMoveEnd->x();
      m.end[ax.v] = step.openMoveEnd->y();
    }
  }
  for (int i = 0; i < step.count; ++i) {
    const CompensatedMove& m = step.moves[i];
    if (m.kind == MoveKind::ArcCW || m.kind == MoveKind::ArcCCW) emitArc(m.kind, m.end, m.centre, m.turns, feed);
    else emit(m.kind, m.end, m.kind == MoveKind::Rapid ? 0.0f : feed);
  }
  if (!step.extendsOpenMove) compOpenMoves_.clear();
  compOpenMoves_.push_back(delivered_ + moves_.size() - 1);
  state_.position = end;  // the programmed point: the next move's words are relative to it
  return true;
}

InterpreterState::CompensationSnapshot InterpreterState::compensationSnapshot() const {
  CompensationSnapshot snapshot{comp_, {}};
  for (const std::uint64_t index : compOpenMoves_)
    if (index >= delivered_) snapshot.openMoves.emplace_back(index, moves_[static_cast<std::size_t>(index - delivered_)].end);
  return snapshot;
}

void InterpreterState::restoreCompensation(const CompensationSnapshot& snapshot) {
  // The bad block's own moves are gone already; an open move it moved the end of moves back.
  comp_ = snapshot.comp;
  compOpenMoves_.clear();
  for (const auto& [index, end] : snapshot.openMoves) {
    moves_[static_cast<std::size_t>(index - delivered_)].end = end;
    compOpenMoves_.push_back(index);
  }
}

std::size_t InterpreterState::firstHeldMove() const {
  std::size_t held = moves_.empty() ? 0 : moves_.size() - 1;
  if (comp_.on() && !compOpenMoves_.empty() && compOpenMoves_.front() >= delivered_)
    held = std::min<std::size_t>(held, static_cast<std::size_t>(compOpenMoves_.front() - delivered_));
  return held;
}

}  // namespace isurface::gcode
