// Straight moves, arcs (centre and radius formats, all planes, helices, turns), dwell, G28/G30.
#include <fmt/format.h>

#include <cmath>

#include "interpreter_state.h"
#include "isurface/base/tolerances.h"
#include "isurface/base/units.h"
#include "isurface/gcode/arc.h"

namespace isurface::gcode {

namespace {

constexpr std::uint32_t kAxisBits =
    letterBit('X') | letterBit('Y') | letterBit('Z') | letterBit('A') | letterBit('B') |
    letterBit('C');

constexpr char kAxisLetter[3] = {'X', 'Y', 'Z'};
constexpr char kOffsetLetter[3] = {'I', 'J', 'K'};

const char* planeName(Plane plane) {
  switch (plane) {
    case Plane::ZX: return "XZ";
    case Plane::YZ: return "YZ";
    default: return "XY";
  }
}

// "X and Y" for the plane's two axes in alphabetical order, as LinuxCNC names them.
std::string planeAxesNames(Plane plane) {
  switch (plane) {
    case Plane::ZX: return "X and Z";
    case Plane::YZ: return "Y and Z";
    default: return "X and Y";
  }
}

std::string point2(const PlaneAxes& ax, double a, double b) {
  return fmt::format("({}{:.4f},{}{:.4f})", kAxisLetter[ax.u], a, kAxisLetter[ax.v], b);
}

}  // namespace

bool InterpreterState::hasAxisWords(const Block& block) const { return (block.present & kAxisBits) != 0; }

Vec3 InterpreterState::targetOf(const Block& block) const {
  // Under G68 the words are read in the turned frame (G53 machine moves are not turned).
  const bool turned = state_.rotation != 0 && !machineCoordinates_;
  Vec3 t = turned ? unrotated(state_.position) : state_.position;
  for (int i = 0; i < 3; ++i) {
    const char c = kAxisLetter[i];
    if (!block.has(c)) continue;
    const double v = length(block.get(c));
    t[i] = state_.incremental ? t[i] + v : v + programOffset()[i];
  }
  return turned ? rotated(t) : t;
}

bool InterpreterState::setOffset(const Block& block, int code) {
  switch (code) {
    case kG92:
      if (!hasAxisWords(block)) return fail(block.gColumn[0], "G92 needs at least one axis word");
      for (int i = 0; i < 3; ++i)
        if (block.has(kAxisLetter[i])) state_.offset[i] = state_.position[i] - length(block.get(kAxisLetter[i]));
      state_.offsetStored = state_.offset;
      return true;
    case kG52:
      for (int i = 0; i < 3; ++i)
        if (block.has(kAxisLetter[i])) state_.offset[i] = length(block.get(kAxisLetter[i]));
      state_.offsetStored = state_.offset;
      return true;
    // As LinuxCNC keeps the offset in parameters #5211-#5213: G92.2 sets it to zero and leaves
    // them, G92.3 takes it from them, G92.1 clears both.
    case kG92_1: state_.offset = state_.offsetStored = Vec3::Zero(); return true;
    case kG92_2: state_.offset = Vec3::Zero(); return true;
    case kG92_3: state_.offset = state_.offsetStored; return true;
    default: return true;
  }
}

void InterpreterState::emit(MoveKind kind, const Vec3& end, float feed, std::uint8_t extraFlags) {
  if (options_.callStack) reportCallStack();
  if (state_.rotary != rotaryNoted_) noteRotary();
  Move& m = moves_.emplace_back();
  m.end = end;
  m.line = moveLine();
  m.column = moveColumn();
  m.feed = feed;
  m.kind = kind;
  m.flags = static_cast<std::uint8_t>(pathFlags() | extraFlags);
  if (kind == MoveKind::Dwell) return;
  state_.position = end;
  state_.tapEndedElsewhere = false;
}

void InterpreterState::emitArc(MoveKind kind, const Vec3& end, const Vec3& centre, unsigned turns,
                      float feed) {
  if (options_.callStack) reportCallStack();
  if (state_.rotary != rotaryNoted_) noteRotary();
  Move& m = moves_.emplace_back();
  m.end = end;
  m.centre = centre;
  m.line = moveLine();
  m.column = moveColumn();
  m.feed = feed;
  m.kind = kind;
  m.plane = state_.plane;
  m.flags = pathFlags();
  m.turns = static_cast<std::uint16_t>(turns);
  state_.position = end;
  state_.tapEndedElsewhere = false;
}

bool InterpreterState::straight(const Block& block, int motion, std::uint32_t column) {
  Vec3 end;
  if (!machineCoordinates_) end = targetOf(block);
  else if (!machineTarget(block, column, end)) return false;
  state_.tapEndedElsewhere = false;  // here, not at the emit: compensation may hold the move back
  if (motion == kG0) return emitPath(MoveKind::Rapid, end, Vec3::Zero(), 1, 0.0f, column);
  double feed = state_.feed;
  if (state_.inverseTime) {
    if (!block.has('F')) return fail(column, "F word missing with inverse time G1 move");
    if (feed <= 0) return fail(column, "Cannot do G1 with zero feed rate");
    // F is moves per minute: the feed along X Y Z, or along A B C in deg/min when only they
    // move (rs274's find_straight_length).
    double length = (end - state_.position).norm();
    if (length < 1e-12) {
      double turn = 0;
      for (std::size_t i = 0; i < 3; ++i) turn += std::pow(state_.rotary[i] - rotaryNoted_[i], 2);
      length = std::sqrt(turn);
    }
    feed = length * state_.feed;
  } else if (feed <= 0) {
    return fail(column, "Cannot do G1 with zero feed rate");
  }
  return emitPath(MoveKind::Linear, end, Vec3::Zero(), 1, static_cast<float>(feed), column);
}

bool InterpreterState::arc(const Block& block, int motion, std::uint32_t column) {
  // Its centre would be measured from one point and its start taken at another: no arc to draw.
  if (state_.tapEndedElsewhere)
    return fail(column, "Arc right after a G84 / G74 in G18 or G19: LinuxCNC starts it where the tap's last "
                        "feed ended, not over the hole; put a G0 or G1 between them");
  const Plane plane = state_.plane;
  const PlaneAxes ax = planeAxes(plane);
  const char normalOffset = kOffsetLetter[ax.w];
  if (block.has(normalOffset))
    return fail(block.col(normalOffset),
                fmt::format("{} word given for arc in {} plane",
                            static_cast<char>(normalOffset | 0x20), planeName(plane)));
  const bool rFormat = block.has('R');
  // Without an end point in the plane, a centre-format arc is a full circle back to where it
  // started (as LinuxCNC draws it); a radius-format one has no circle to choose.
  if (rFormat && !block.has(kAxisLetter[ax.u]) && !block.has(kAxisLetter[ax.v]))
    return fail(column, fmt::format("{} words missing for arc in {} plane",
                                    planeAxesNames(plane), planeName(plane)));
  const bool centreFormat = block.has(kOffsetLetter[ax.u]) || block.has(kOffsetLetter[ax.v]);
  if (rFormat && centreFormat)
    return fail(block.col('R'), "Mixed radius-ijk format for arc");
  if (!rFormat && !centreFormat)
    return fail(column, fmt::format("R, {} word missing for arc in {} plane",
                                    plane == Plane::XY   ? "I or J"
                                    : plane == Plane::ZX ? "I or K"
                                                         : "J or K",
                                    planeName(plane)));
  if (state_.inverseTime && !block.has('F'))
    return fail(column, "F word missing with inverse time arc move");
  if (state_.feed <= 0) return fail(column, "Cannot make arc with zero feed rate");

  unsigned turns = 1;
  if (block.has('P')) {
    const double p = block.get('P');
    const double rounded = std::nearbyint(p);
    if (std::fabs(p - rounded) > kWholeNumberTolerance)
      return fail(block.col('P'), "P value not an integer with G2 or G3");
    if (rounded < 1) return fail(block.col('P'), "P value must be at least 1 with G2 or G3");
    if (rounded > 10000) return fail(block.col('P'), "P value too large with G2 or G3 (over 10000 turns)");
    turns = static_cast<unsigned>(rounded);
  }

  const Vec3 start = state_.position;
  const Vec3 end = targetOf(block);
  const double su = start[ax.u], sv = start[ax.v], eu = end[ax.u], ev = end[ax.v];
  Vec3 centre = start;  // the normal coordinate stays the start's
  const double minRadius = options_.arcReachTolerance;

  if (rFormat) {
    const double radius = length(block.get('R'));
    if (su == eu && sv == ev)
      return fail(block.col('R'), "Current point same as end point of arc");
    const double absRadius = std::fabs(radius);
    const double midU = 0.5 * (su + eu), midV = 0.5 * (sv + ev);
    double half = std::hypot(midU - eu, midV - ev);
    if (half - absRadius > options_.arcReachTolerance || absRadius < kLengthEpsilon)
      return fail(block.col('R'), "Arc radius too small to reach end point");
    if (half / absRadius > 1 - kRatioEpsilon) half = absRadius;  // a semicircle, within the tolerance
    const double chordAngle = std::atan2(ev - sv, eu - su);
    const bool right = (motion == kG2) == (radius > 0);
    const double theta = right ? chordAngle - kHalfPi : chordAngle + kHalfPi;
    const double offset = absRadius * std::cos(std::asin(half / absRadius));
    centre[ax.u] = midU + offset * std::cos(theta);
    centre[ax.v] = midV + offset * std::sin(theta);
  } else {
    const char cu = kOffsetLetter[ax.u], cv = kOffsetLetter[ax.v];
    const double iu = block.has(cu) ? length(block.get(cu)) : 0.0;
    const double iv = block.has(cv) ? length(block.get(cv)) : 0.0;
    centre[ax.u] = state_.arcAbsolute ? iu + state_.offset[ax.u] : su + iu;
    centre[ax.v] = state_.arcAbsolute ? iv + state_.offset[ax.v] : sv + iv;
    if (state_.rotation != 0) {  // I, J, K turn with the frame
      if (state_.rotationPlane != plane)
        return fail(column, "An arc outside the plane of the G68 rotation is not supported");
      Vec3 ijk = Vec3::Zero();
      ijk[ax.u] = iu;
      ijk[ax.v] = iv;
      Vec3 absolute = unrotated(start);
      absolute[ax.u] = centre[ax.u];
      absolute[ax.v] = centre[ax.v];
      const Vec3 turned = state_.arcAbsolute ? rotated(absolute) : start + rotatedVector(ijk);
      centre[ax.u] = turned[ax.u];
      centre[ax.v] = turned[ax.v];
    }
    const double r1 = std::hypot(su - centre[ax.u], sv - centre[ax.v]);
    const double r2 = std::hypot(eu - centre[ax.u], ev - centre[ax.v]);
    auto where = [&] {
      return fmt::format("start={} center={} end={} r1={:.4f} r2={:.4f}", point2(ax, su, sv),
                         point2(ax, centre[ax.u], centre[ax.v]), point2(ax, eu, ev), r1, r2);
    };
    if (r1 < minRadius || r2 < minRadius) return fail(column, "Zero-radius arc: " + where());
    const double absErr = std::fabs(r1 - r2);
    const double relErr = absErr / std::max(r1, r2);
    const double tol = state_.inch ? options_.arcRadiusToleranceInch : options_.arcRadiusTolerance;
    if (absErr > 100 * tol ||
        (absErr > tol && relErr > options_.arcRadiusRelativeTolerance))
      return fail(column,
                  fmt::format("Radius to end of arc differs from radius to start: {} abs_err={:.4g} "
                              "rel_err={:.4f}%",
                              where(), absErr, relErr * 100));
  }

  const MoveKind kind = motion == kG2 ? MoveKind::ArcCW : MoveKind::ArcCCW;
  double feed = state_.feed;
  if (state_.inverseTime) {
    Move probe;
    probe.end = end;
    probe.centre = centre;
    probe.kind = kind;
    probe.plane = plane;
    probe.turns = static_cast<std::uint16_t>(turns);
    feed = ArcGeometry::from(start, probe).length() * state_.feed;
  }
  return emitPath(kind, end, centre, turns, static_cast<float>(feed), column);
}

bool InterpreterState::dwell(const Block& block, std::uint32_t column) {
  if (!block.has('P')) return fail(column, "Dwell time P word missing with G4");
  const double seconds = block.get('P');
  if (seconds < 0) return fail(block.col('P'), "Negative dwell time P word used with G4");
  if (!comp_.on()) {
    emit(MoveKind::Dwell, state_.position, static_cast<float>(seconds));
    return true;
  }
  // Where the tool is, beside the programmed point; an inside corner after it moves it too.
  emit(MoveKind::Dwell, comp_.tool(), static_cast<float>(seconds));
  compOpenMoves_.push_back(delivered_ + moves_.size() - 1);
  return true;
}

bool InterpreterState::homeMove(const Block& block, int code) {
  // The reference position is in machine coordinates. As rs274: through the intermediate point
  // (where the tool is, without axis words), then the named axes (all without any) go there.
  const Vec3& home = code == kG28 ? state_.g28 : state_.g30;
  const bool all = !hasAxisWords(block);
  const Vec3 via = all ? state_.position : targetOf(block);
  emit(MoveKind::Rapid, via, 0.0f);
  Vec3 dest = machineOf(via);
  for (int i = 0; i < 3; ++i)
    if (all || block.has(kAxisLetter[i])) dest[i] = home[i];
  emit(MoveKind::Rapid, workOf(dest), 0.0f);
  return true;
}

}  // namespace isurface::gcode
