// G68 / G69: Fanuc's coordinate rotation. After `G68 X.. Y.. R..` the program's points turn by R
// degrees (counter-clockwise seen along the plane's normal) about (X, Y); G69 ends it. A word
// left out of a block keeps the program's coordinate in the turned frame, as on the control.
#include <fmt/format.h>

#include <cmath>

#include "interpreter_state.h"

namespace isurface::gcode {

namespace {

constexpr char kAxisLetter[3] = {'X', 'Y', 'Z'};

}  // namespace

bool InterpreterState::setRotation(const Block& block, int code, std::uint32_t column) {
  if (code == kG69) {
    state_.rotation = 0;
    return true;
  }
  if (!block.has('R')) return fail(column, "G68 needs an R word: the angle of rotation, in degrees");
  const PlaneAxes ax = planeAxes(state_.plane);
  if (block.has(kAxisLetter[ax.w]))
    return fail(block.col(kAxisLetter[ax.w]),
                fmt::format("{} word with G68: the centre of rotation is in the plane", kAxisLetter[ax.w]));
  if (block.has('A') || block.has('B') || block.has('C'))
    return fail(column, "G68 takes the centre's two coordinates in the plane and R, no rotary axis words");
  // The centre in program coordinates; a coordinate left out is where the tool is.
  const Vec3 here = unrotated(state_.position) - state_.offset;
  Vec3 centre = here;
  for (const int axis : {ax.u, ax.v}) {
    const char c = kAxisLetter[axis];
    if (block.has(c)) centre[axis] = state_.incremental ? here[axis] + length(block.get(c)) : length(block.get(c));
  }
  const double angle = block.get('R') * kPi / 180;
  if (!std::isfinite(angle)) return fail(block.col('R'), "G68 R is not a finite angle");
  // Incremental, R adds to the rotation in effect.
  state_.rotation = state_.incremental && state_.rotation != 0 ? state_.rotation + angle : angle;
  state_.rotationCentre = centre;
  state_.rotationPlane = state_.plane;
  return true;
}

void InterpreterState::noteFrame() {
  if (sink_) return;
  const CoordinateFrame frame{movesMade(), state_.offset, state_.rotation, state_.rotationCentre, state_.rotationPlane};
  std::vector<CoordinateFrame>& frames = result_.program.frames;
  if (frame.sameAs(frames.empty() ? CoordinateFrame{} : frames.back())) return;
  if (!frames.empty() && frames.back().firstMove == frame.firstMove) frames.back() = frame;
  else frames.push_back(frame);
}

Vec3 InterpreterState::rotatedVector(const Vec3& v) const {
  if (state_.rotation == 0) return v;
  const PlaneAxes ax = planeAxes(state_.rotationPlane);
  const double c = std::cos(state_.rotation), s = std::sin(state_.rotation);
  Vec3 out = v;
  out[ax.u] = c * v[ax.u] - s * v[ax.v];
  out[ax.v] = s * v[ax.u] + c * v[ax.v];
  return out;
}

Vec3 InterpreterState::rotated(const Vec3& p) const {
  if (state_.rotation == 0) return p;
  const Vec3 pivot = state_.rotationCentre + state_.offset;
  return pivot + rotatedVector(p - pivot);
}

Vec3 InterpreterState::unrotated(const Vec3& p) const {
  if (state_.rotation == 0) return p;
  const PlaneAxes ax = planeAxes(state_.rotationPlane);
  const Vec3 pivot = state_.rotationCentre + state_.offset;
  const Vec3 d = p - pivot;
  const double c = std::cos(state_.rotation), s = std::sin(state_.rotation);
  Vec3 out = d;
  out[ax.u] = c * d[ax.u] + s * d[ax.v];
  out[ax.v] = -s * d[ax.u] + c * d[ax.v];
  return pivot + out;
}

}  // namespace isurface::gcode
