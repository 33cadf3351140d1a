#pragma once
// Cutter radius compensation (G41/G42) as LinuxCNC applies it: the tool's centre runs at the
// tool radius beside the programmed path. Each move's offset is known only when the next move
// says which way the path turns, so the last offset move stays open: an inside corner moves its
// end to where the two offset paths meet; an outside corner adds an arc around the programmed
// corner. Pure geometry in the plane's (u, v) coordinates (isurface/base/geometry.h); the
// interpreter applies the steps to its moves. Private to the gcode module.
#include <Eigen/Core>

#include <optional>
#include <string>

#include "isurface/base/geometry.h"
#include "isurface/gcode/program.h"

namespace isurface::gcode {

using Vec2 = Eigen::Vector2d;

// One move the compensated path is made of; the feed is the programmed move's.
struct CompensatedMove {
  MoveKind kind = MoveKind::Linear;
  Vec3 end = Vec3::Zero();     // mm
  Vec3 centre = Vec3::Zero();  // arcs
  unsigned turns = 1;
};

// What one programmed move becomes.
struct CompensationStep {
  std::optional<Vec2> openMoveEnd;  // the open offset move (and the moves with no motion in the plane after it) now ends here
  bool extendsOpenMove = false;     // the new move has no motion in the plane: it moves with the open move's end
  CompensatedMove moves[3];
  int count = 0;
  void add(const CompensatedMove& m) { moves[count++] = m; }
};

class CutterCompensation {
 public:
  enum Side { kLeft = 1, kRight = -1 };

  // Turns compensation on; `tool` is where the tool is (mm). The next move is the entry move.
  // `inch`: the program is in inches (LinuxCNC's gouge tolerances depend on it).
  void start(Side side, double radiusMm, Plane plane, const Vec3& tool, bool inch);
  // Turns it off; `tool` gets where the tool is (the end of the last offset move). Returns an
  // error message when the last offset arc could not end there.
  std::string stop(Vec3& tool);
  bool on() const { return on_; }
  const Vec3& tool() const { return tool_; }

  // Offsets a straight move (`rapid`: G0, which goes around an outside corner by two straight
  // traverses instead of an arc) from the programmed point `from` to `to`. Returns an error
  // message, empty when the tool can follow the move.
  std::string line(const Vec3& from, const Vec3& to, bool rapid, CompensationStep& step);
  // Offsets an arc about `centre` (plane axis point), counter-clockwise when `ccw`.
  std::string arc(const Vec3& from, const Vec3& to, const Vec3& centre, bool ccw, unsigned turns,
                  CompensationStep& step);

 private:
  // The open offset move: a line from `start` along `direction`, or an arc about `centre`.
  struct OpenMove {
    bool arc = false;
    Vec2 start = Vec2::Zero();
    Vec2 through = Vec2::Zero();    // lines: a point the line an inside corner moves the end along
    Vec2 direction = Vec2::Zero();
    Vec2 centre = Vec2::Zero();
    double radius = 0;
    bool ccw = true;
    bool toolOutside = false;
    double sweep = 0;                 // radians from start to its offset end (one turn at most)
    double programmedSweep = 0;       // radians, of the programmed arc (2 pi: a full circle)
    Vec2 endTangent = Vec2::Zero();   // of the programmed move
  };
  // A new offset move: where it would start and which way it leaves the programmed corner.
  struct NextMove {
    Vec2 corner, start, startTangent, end;
    bool arc = false;
    Vec2 centre = Vec2::Zero();
    double radius = 0;
    bool ccw = true;
    bool toolOutside = false;
    double sweep = 0;
    Vec2 lineShift = Vec2::Zero();  // arcs: where the corner is taken to be, from the programmed one
  };

  Vec2 planar(const Vec3& p) const { return {p[axes_.u], p[axes_.v]}; }
  Vec3 spatial(const Vec2& p, double w) const;
  Vec2 normal(const Vec2& tangent) const;  // towards the compensated side
  // Joins the open move to `next` at the programmed corner: the corner arc or the moved end.
  // Returns the point the new move starts from, or an error.
  std::string turnCorner(const NextMove& next, bool rapid, CompensationStep& step, Vec2& startsAt);
  std::optional<Vec2> insideCorner(const NextMove& next) const;
  // The open arc may end at `end` without sweeping further than programmed.
  bool arcEndsWithin(const Vec2& end) const;

  bool on_ = false;
  bool inch_ = false;
  bool entered_ = false;  // the entry move was made
  Side side_ = kLeft;
  double radius_ = 0;     // mm
  PlaneAxes axes_{0, 1, 2};
  Vec3 tool_ = Vec3::Zero();
  OpenMove open_;
  // The last inside corner cut both moves short (turning back, it may lengthen them instead).
  bool cornerTrims_ = false;
};

}  // namespace isurface::gcode
