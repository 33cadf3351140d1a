// LinuxCNC's coordinate systems G54-G59.3: their origins and XY rotations (G10 L2 / L20), the
// position carried over when the active one changes, G53 machine moves, G43.1 tool length.
// Moves stay in the active system's coordinates (G92 / G52 included), unrotated, as rs274 prints
// them; a machine position is rotated(position) + origin.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interpreter_state.h"

namespace isurface::gcode {

namespace {

constexpr char kAxisLetter[3] = {'X', 'Y', 'Z'};

// p turned by `degrees` about +Z.
Vec3 turnedXY(const Vec3& p, double degrees) {
  if (degrees == 0) return p;
  const double a = degrees * M_PI / 180, c = std::cos(a), s = std::sin(a);
  return Vec3(c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z());
}

}  // namespace

int workSystemIndex(int coordSystem) {
  switch (coordSystem) {
    case 540: return 1;
    case 550: return 2;
    case 560: return 3;
    case 570: return 4;
    case 580: return 5;
    case 590: return 6;
    case 591: return 7;
    case 592: return 8;
    case 593: return 9;
    default: return 0;  // Fanuc's G54.1 P: not modelled, no offset
  }
}

Vec3 InterpreterState::machineOf(const Vec3& position) const {
  const WorkSystem& w = state_.work[workSystemIndex(state_.coordSystem)];
  return turnedXY(position, w.rotation) + w.origin;
}

Vec3 InterpreterState::workOf(const Vec3& machine) const {
  const WorkSystem& w = state_.work[workSystemIndex(state_.coordSystem)];
  return turnedXY(machine - w.origin, -w.rotation);
}

void InterpreterState::selectCoordSystem(int code) {
  const Vec3 machine = machineOf(state_.position);
  state_.coordSystem = code;
  state_.position = workOf(machine);
}

// G10 L2 P0-P9 (P0: the active system) sets origins (X Y Z) and the rotation (R, degrees); L20
// sets them so that where the tool is has the coordinates given. Other L values (the tool table's)
// change no move. The Fanuc dialect's G10 (P0 the external offset, L20 its extended systems) is
// left as it was: recorded, not applied.
bool InterpreterState::setWorkOffset(const Block& block, std::uint32_t column) {
  if (!block.has('L')) return fail(column, "G10 needs an L word");
  const double l = block.get('L');
  if ((l != 2 && l != 20) || options_.fanuc) return true;
  if (!block.has('P')) return fail(column, fmt::format("G10 L{} needs a P word", l));
  const double p = block.get('P');
  if (p != std::floor(p) || p < 0 || p > 9)
    return fail(column, fmt::format("G10 L{} P{}: the coordinate system number must be 0 to 9", l, p));
  const int active = workSystemIndex(state_.coordSystem);
  const int n = p == 0 ? active : static_cast<int>(p);
  if (n == 0) return fail(column, "G10 P0 while a Fanuc G54.1 system is active");
  const Vec3 machine = machineOf(state_.position);
  WorkSystem& w = state_.work[n];
  if (block.has('R')) w.rotation = block.get('R');
  if (l == 2) {
    for (int i = 0; i < 3; ++i)
      if (block.has(kAxisLetter[i])) w.origin[i] = length(block.get(kAxisLetter[i]));
  } else {
    // The point where the tool is, with the axes given, in the system's program coordinates.
    Vec3 at = workOf(machine) - state_.offset;
    for (int i = 0; i < 3; ++i)
      if (block.has(kAxisLetter[i])) at[i] = length(block.get(kAxisLetter[i]));
    const Vec3 origin = machine - turnedXY(at + state_.offset, w.rotation);
    for (int i = 0; i < 3; ++i)
      if (block.has(kAxisLetter[i]) || (i < 2 && w.rotation != 0)) w.origin[i] = origin[i];
  }
  if (n == active) state_.position = workOf(machine);
  return true;
}

// G53: the axes given are machine coordinates (less the G43.1 tool length along Z, as LinuxCNC
// takes it), the others stay where the tool is.
bool InterpreterState::machineTarget(const Block& block, std::uint32_t column, Vec3& target) {
  if (block.has('Z') && state_.toolLength == kG43 && !options_.fanuc)
    return fail(column, "G53 with a Z word under a G43 H tool length offset is not supported");
  Vec3 machine = machineOf(state_.position);
  for (int i = 0; i < 3; ++i)
    if (block.has(kAxisLetter[i])) machine[i] = length(block.get(kAxisLetter[i])) - (i == 2 ? state_.toolLengthZ : 0);
  target = workOf(machine);
  return true;
}

bool InterpreterState::readMachineParameter(int number, double& value) const {
  const double perMm = state_.inch ? 1 / kMmPerInch : 1.0;
  const auto axes = [&](int first, const Vec3& v) {
    value = number - first < 3 ? v[number - first] * perMm : 0.0;
  };
  if (number >= 5021 && number <= 5029) {
    axes(5021, machineOf(state_.position) + Vec3(0, 0, state_.toolLengthZ));
  } else if (number >= 5161 && number <= 5169) {
    axes(5161, state_.g28);
  } else if (number >= 5181 && number <= 5189) {
    axes(5181, state_.g30);
  } else if (number == 5220) {
    value = std::max(1, workSystemIndex(state_.coordSystem));
  } else if (number >= 5221 && number <= 5410) {
    const WorkSystem& w = state_.work[static_cast<std::size_t>((number - 5221) / 20 + 1)];
    const int k = (number - 5221) % 20;
    if (k == 9) value = w.rotation;
    else if (k < 10) value = k < 3 ? w.origin[k] * perMm : 0.0;
    else return false;
  } else {
    return false;
  }
  return true;
}

}  // namespace isurface::gcode
