#pragma once
// The interpreted program: a flat list of moves in absolute workpiece millimetres, each tied to
// the physical source line that produced it. Arcs stay exact (centre, plane, turns).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "isurface/base/diagnostic.h"
#include "isurface/base/geometry.h"

namespace isurface {

enum class MoveKind : std::uint8_t {
  Rapid,   // G0: at the machine's rapid rate
  Linear,  // G1
  ArcCW,   // G2
  ArcCCW,  // G3
  Dwell,   // G4: no motion, `dwellSeconds()` of standstill
};

enum MoveFlags : std::uint8_t {
  kExactStop = 1,  // G61 in effect: the move ends at standstill
  kStopAfter = 2,  // a program stop, tool change or spindle change follows: end at standstill
  kExactPath = 4,  // G61 (with kExactStop): LinuxCNC keeps the feed through tangent junctions, G61.1 does not
};

// G64's tolerances from a move on (RS274/NGC `G64 P- Q-`, in mm): `blend` how far a blend may
// leave the programmed corner, `merge` how far points of collinear-ish short lines may lie off
// the one line a control may join them into (LinuxCNC's naive-CAM detector). 0: not given.
struct PathBlending {
  std::uint64_t firstMove = 0;
  double blend = 0;
  double merge = 0;
};

// The rotary axes' position (A, B, C in degrees, as the program writes them) at the end of move
// `move`, and of every move after it until the next such position.
struct RotaryPosition {
  std::uint64_t move = 0;
  std::array<double, 3> abc{};
};

// The program's own coordinate frame from a move on: G92 / G52's offset and G68's rotation.
// The moves are in workpiece coordinates; a point the program writes (X Y Z of a block) is
// toProgram() of the workpiece point it reaches. (Work offsets G54-G59 are not modelled: the
// workpiece's coordinates are G54's.)
struct CoordinateFrame {
  std::uint64_t firstMove = 0;
  Vec3 offset = Vec3::Zero();          // mm: the program's coordinates plus this are the workpiece's
  double rotation = 0;                 // radians, counter-clockwise about the plane's normal
  Vec3 rotationCentre = Vec3::Zero();  // program coordinates, mm
  Plane rotationPlane = Plane::XY;

  bool sameAs(const CoordinateFrame& other) const {
    return offset == other.offset && rotation == other.rotation && rotationCentre == other.rotationCentre &&
           rotationPlane == other.rotationPlane;
  }
  // A workpiece point in the program's coordinates: turned back about the centre, less the offset.
  Vec3 toProgram(const Vec3& workpiece) const {
    Vec3 d = workpiece - (rotationCentre + offset);
    if (rotation != 0) {
      const PlaneAxes ax = planeAxes(rotationPlane);
      const double c = std::cos(rotation), s = std::sin(rotation);
      const double u = c * d[ax.u] + s * d[ax.v], v = -s * d[ax.u] + c * d[ax.v];
      d[ax.u] = u;
      d[ax.v] = v;
    }
    return d + rotationCentre;
  }
};

// 64 bytes. The start of a move is the end of the previous one (Program::start for the first).
struct Move {
  Vec3 end = Vec3::Zero();     // mm
  Vec3 centre = Vec3::Zero();  // arcs: axis point, with the start's coordinate along the plane normal
  std::uint32_t line = 0;      // 1-based physical source line
  float feed = 0;              // mm/min programmed feed (0 for rapids); seconds for a dwell
  MoveKind kind = MoveKind::Linear;
  Plane plane = Plane::XY;
  std::uint8_t flags = 0;
  std::uint16_t turns = 1;     // arcs: 1 for an ordinary arc (or a full circle), more adds turns
  std::uint16_t column = 0;    // 1-based column of the word that made the move (0: unknown, or past 65535)

  bool isArc() const { return kind == MoveKind::ArcCW || kind == MoveKind::ArcCCW; }
  bool isMotion() const { return kind != MoveKind::Dwell; }
  double dwellSeconds() const { return kind == MoveKind::Dwell ? feed : 0.0; }
};
static_assert(sizeof(Move) == 64, "a Move is 64 bytes: programs of tens of millions of moves are held");

struct Program {
  std::string source;               // file name as given
  Vec3 start = Vec3::Zero();        // position before the first move, mm
  std::vector<Move> moves;
  std::vector<Diagnostic> warnings; // non-fatal notes (e.g. cutter compensation ignored)
  std::vector<PathBlending> blending; // each G64 that changed the tolerances, in move order
  std::vector<CoordinateFrame> frames; // each change of G92 / G52 / G68, in move order; none: no offset
  std::vector<RotaryPosition> rotary;  // each change of A, B or C, in move order; none: never moved
  std::uint32_t lineCount = 0;      // physical lines in the source
  bool inch = false;                // written in inches: the first G20/G21 was G20 (or the control's default)

  const Vec3& startOf(std::size_t i) const { return i == 0 ? start : moves[i - 1].end; }
  // A, B and C (deg) at the end of move `i`: all 0 until the program moves them.
  std::array<double, 3> rotaryAt(std::size_t i) const {
    const auto after = std::upper_bound(rotary.begin(), rotary.end(), i,
                                        [](std::size_t m, const RotaryPosition& r) { return m < r.move; });
    return after == rotary.begin() ? std::array<double, 3>{} : std::prev(after)->abc;
  }
  // The frame move `i` was programmed in.
  CoordinateFrame frameOf(std::size_t i) const {
    const auto after = std::upper_bound(frames.begin(), frames.end(), i,
                                        [](std::size_t move, const CoordinateFrame& f) { return move < f.firstMove; });
    return after == frames.begin() ? CoordinateFrame{} : *(after - 1);
  }
};

}  // namespace isurface
