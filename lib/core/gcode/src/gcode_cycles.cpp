// Canned cycles in the XY, XZ and YZ planes (drilling along Z, Y and X), expanded into rapid and
// feed moves the way RS274/NGC (LinuxCNC's rs274) runs them: drilling G81 G82, pecking G73 G83,
// tapping G84 (right hand) and G74 (left hand), boring G85 G86 G88 G89.
#include <fmt/format.h>

#include <cmath>

#include "interpreter_state.h"
#include "isurface/base/tolerances.h"

namespace isurface::gcode {

namespace {

// How far above the previous peck the tool comes back down before feeding again (G73 backs off
// by as much): 0.010 inch, in mm.
constexpr double kPeckClearance = 0.254;
// Guards against programs that would expand into absurd numbers of moves.
constexpr long kMaxRepeats = 100000;
constexpr double kMaxPecks = 100000;
constexpr double kMaxCycleMoves = 2e6;
constexpr char kAxisLetter[3] = {'X', 'Y', 'Z'};

// The cycle's axes as LinuxCNC names them: the two of the plane (a, b) and the drilling one (c).
struct CycleAxes {
  int a, b, c;
  const char* plane;
};
CycleAxes cycleAxes(Plane plane) {
  switch (plane) {
    case Plane::ZX: return {2, 0, 1, "XZ"};
    case Plane::YZ: return {1, 2, 0, "YZ"};
    default: return {0, 1, 2, "XY"};
  }
}

// Where LinuxCNC 2.9 sends a G84 / G74 feed move to `p` (program coordinates) in G18 or G19: its
// tapping cycle hands the coordinates to the move in the wrong order, so the tap does not run
// along the drilling axis (every other cycle there does).
Vec3 linuxcncTapEnd(Plane plane, const Vec3& p) {
  return plane == Plane::ZX ? Vec3(p.y(), p.z(), p.x()) : Vec3(p.z(), p.x(), p.y());
}

std::string linuxcncTapWarning(const std::string& name, const CycleAxes& ax) {
  const char* axes = ax.c == 1 ? "X goes to the Y level, Y to the hole's Z and Z to the hole's X"
                               : "X goes to the hole's Z, Y to the X level and Z to the hole's Y";
  return fmt::format("{} in the {} plane is expanded as LinuxCNC 2.9 runs it, not along {}: in its feed "
                     "moves {}; a Fanuc control (\"control\": {{\"dialect\": \"fanuc\"}}) taps along {}",
                     name, ax.plane, kAxisLetter[ax.c], axes, kAxisLetter[ax.c]);
}

}  // namespace

// The canned cycles G73 G76.. G89 as rs274 runs them: the checks, then the shared approach, then
// one case per cycle. Kept whole so that the cycles read side by side (longer than most).
bool InterpreterState::cycle(const Block& block, int motion, std::uint32_t column) {
  const std::string name = fmt::format("G{}", motion / 10);
  const CycleAxes ax = cycleAxes(state_.plane);
  const char cLetter = kAxisLetter[ax.c];
  if (state_.cutterComp != kG40)
    return fail(column, "Cannot use canned cycles with cutter radius compensation");
  if (state_.inverseTime)
    return fail(column, "Cannot use canned cycles in inverse time feed mode (G93)");
  if (state_.rotation != 0) return fail(column, "Canned cycles under G68 coordinate rotation are not supported");
  if (state_.feed <= 0) return fail(column, fmt::format("Cannot do {} with zero feed rate", name));

  // A cycle's first block names its levels; later blocks may reuse them.
  const bool first = state_.motion != motion || state_.cyclePlane != state_.plane;
  if (first && !block.has(cLetter))
    return fail(column, fmt::format("{} value unspecified in {} plane canned cycle", cLetter, ax.plane));
  if (first && !block.has('R'))
    return fail(column, "R clearance plane unspecified in canned cycle");
  const double zWord = block.has(cLetter) ? length(block.get(cLetter)) : state_.cycleZ;
  const double rWord = block.has('R') ? length(block.get('R')) : state_.cycleR;

  long repeats = 1;
  if (block.has('L')) {
    const double l = block.get('L');
    if (l < 0 || std::fabs(l - std::nearbyint(l)) > kWholeNumberTolerance)
      return fail(block.col('L'), "L word must be a whole number, zero or more");
    if (l > kMaxRepeats)
      return fail(block.col('L'), fmt::format("L word too large (over {} repeats)", kMaxRepeats));
    repeats = static_cast<long>(std::nearbyint(l));
  }

  double peck = state_.cycleQ;
  if (motion == kG73 || motion == kG83) {
    if (first && !block.has('Q')) return fail(column, fmt::format("Q word missing with {}", name));
    if (block.has('Q')) peck = length(block.get('Q'));
    if (peck <= 0)
      return fail(block.has('Q') ? block.col('Q') : column, "Negative or zero Q value used");
  }
  double dwellSeconds = state_.cycleP;
  const bool dwellNeeded = motion == kG82 || motion == kG86 || motion == kG88 || motion == kG89;
  if (dwellNeeded || motion == kG84 || motion == kG74) {
    if (dwellNeeded && first && !block.has('P'))
      return fail(column, fmt::format("Dwell time P word missing with {}", name));
    if (block.has('P')) dwellSeconds = block.get('P');
    else if (first) dwellSeconds = 0;  // tapping: no dwell unless given
    if (dwellSeconds < 0) return fail(block.col('P'), fmt::format("Negative dwell time P word used with {}", name));
  }

  if ((motion == kG84 || motion == kG74) && block.has('Q'))
    warnOnce(warnedPeckTapping_, block.col('Q'),
             fmt::format("{} with Q (peck tapping on Fanuc and Haas controls) is expanded as one tap to the bottom", name));
  // What LinuxCNC does is what its machine does; a Fanuc control taps along the drilling axis.
  const bool tapAsLinuxcnc = (motion == kG84 || motion == kG74) && state_.plane != Plane::XY && !options_.fanuc;
  if (tapAsLinuxcnc) warnOnce(warnedLinuxcncTap_, column, linuxcncTapWarning(name, ax));
  const Vec3 start = state_.position;
  // x, y, z below are the cycle's a, b, c axes.
  const char aLetter = kAxisLetter[ax.a], bLetter = kAxisLetter[ax.b];
  double oldZ = start[ax.c];
  if (first) state_.cycleStartZ = oldZ;
  double x, y, r, bottom, dx = 0, dy = 0;
  if (!state_.incremental) {
    r = rWord + state_.offset[ax.c];
    bottom = zWord + state_.offset[ax.c];
    x = block.has(aLetter) ? length(block.get(aLetter)) + state_.offset[ax.a] : start[ax.a];
    y = block.has(bLetter) ? length(block.get(bLetter)) + state_.offset[ax.b] : start[ax.b];
  } else {
    dx = block.has(aLetter) ? length(block.get(aLetter)) : 0.0;
    dy = block.has(bLetter) ? length(block.get(bLetter)) : 0.0;
    r = rWord + state_.cycleStartZ;
    bottom = r + zWord;
    x = start[ax.a];
    y = start[ax.b];
  }
  if (r < bottom) return fail(column, fmt::format("R less than {} in canned cycle in {} plane", cLetter, ax.plane));
  const double pecks = (motion == kG73 || motion == kG83) ? (r - bottom) / peck : 1.0;
  if (pecks > kMaxPecks)
    return fail(block.has('Q') ? block.col('Q') : column,
                fmt::format("Q value too small: over {} pecks", kMaxPecks));
  if (static_cast<double>(repeats) * (3.0 * pecks + 4.0) > kMaxCycleMoves)
    return fail(column, "Canned cycle expands to too many moves (L and Q)");

  // Cycles run in exact stop mode, whatever G61/G64 says.
  auto at = [&](double pa, double pb, double pc) {
    Vec3 v;
    v[ax.a] = pa;
    v[ax.b] = pb;
    v[ax.c] = pc;
    return v;
  };
  auto rapid = [&](double px, double py, double pz) {
    emit(MoveKind::Rapid, at(px, py, pz), 0.0f, kExactStop);
  };
  const float feed = static_cast<float>(state_.feed);
  auto feedTo = [&](double px, double py, double pz) {
    const Vec3& o = state_.offset;  // G92 / G52 apply after LinuxCNC's swap
    emit(MoveKind::Linear, tapAsLinuxcnc ? linuxcncTapEnd(state_.plane, at(px, py, pz) - o) + o : at(px, py, pz),
         feed, kExactStop);
  };

  if (oldZ < r) {
    rapid(start[ax.a], start[ax.b], r);
    oldZ = r;
  }
  const double clear = state_.retractToR ? r : oldZ;
  for (long i = 0; i < repeats; ++i) {
    x += dx;
    y += dy;
    rapid(x, y, oldZ);
    if (oldZ != r) rapid(x, y, r);
    switch (motion) {
      case kG81:
        feedTo(x, y, bottom);
        rapid(x, y, clear);
        break;
      case kG82:
        feedTo(x, y, bottom);
        emit(MoveKind::Dwell, state_.position, static_cast<float>(dwellSeconds), kExactStop);
        rapid(x, y, clear);
        break;
      case kG83:  // peck: back out to R after each peck, rapid down to just above the last one
        for (double depth = r - peck; depth > bottom; depth -= peck) {
          feedTo(x, y, depth);
          rapid(x, y, r);
          rapid(x, y, depth + kPeckClearance);
        }
        feedTo(x, y, bottom);
        rapid(x, y, clear);
        break;
      case kG73:  // chip breaking: back off a little after each peck
        for (double depth = r - peck; depth > bottom; depth -= peck) {
          feedTo(x, y, depth);
          rapid(x, y, depth + kPeckClearance);
        }
        feedTo(x, y, bottom);
        rapid(x, y, clear);
        break;
      case kG84:  // tapping: feed in, reverse the spindle (the motion stops), feed out
      case kG74:
      case kG89:  // boring: feed in, dwell, feed out
        feedTo(x, y, bottom);
        moves_.back().flags |= kStopAfter;
        if (dwellSeconds > 0) emit(MoveKind::Dwell, state_.position, static_cast<float>(dwellSeconds), kExactStop);
        feedTo(x, y, clear);
        break;
      case kG85:  // boring: feed in, feed out to R
        feedTo(x, y, bottom);
        feedTo(x, y, r);
        rapid(x, y, clear);  // rs274 makes this move even when it has no length (G99)
        break;
      case kG86:  // boring: feed in, dwell, stop the spindle, rapid out
        feedTo(x, y, bottom);
        emit(MoveKind::Dwell, state_.position, static_cast<float>(dwellSeconds), kExactStop | kStopAfter);
        rapid(x, y, clear);
        break;
      case kG88:  // boring: feed in, dwell, stop for the operator to retract by hand
        feedTo(x, y, bottom);
        emit(MoveKind::Dwell, state_.position, static_cast<float>(dwellSeconds), kExactStop | kStopAfter);
        break;
      default: break;
    }

    oldZ = clear;
  }
  if (tapAsLinuxcnc && repeats > 0) {
    // LinuxCNC takes the tool to be over the hole while its last move ended elsewhere: later
    // moves are computed from the former and start from the latter.
    const Vec3 ended = state_.position;
    state_.position = at(x, y, oldZ);
    state_.tapEndedElsewhere = (ended - state_.position).norm() > kLengthEpsilon;
  }
  state_.cyclePlane = state_.plane;
  state_.cycleZ = zWord;
  state_.cycleR = rWord;
  state_.cycleQ = peck;
  state_.cycleP = dwellSeconds;
  return true;
}

}  // namespace isurface::gcode
