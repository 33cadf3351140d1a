#include "isurface/gcode/path_segment.h"

namespace isurface {

PathSegment PathSegment::from(const Program& program, std::size_t moveIndex) {
  return from(program.startOf(moveIndex), program.moves[moveIndex]);
}

PathSegment PathSegment::from(const Vec3& start, const Move& move) {
  PathSegment seg;
  seg.start = start;
  seg.end = move.end;
  if (move.isArc()) {
    seg.arc = true;
    seg.arcGeometry = ArcGeometry::from(seg.start, move);
    seg.length = seg.arcGeometry.length();
  } else if (move.isMotion()) {
    const Vec3 delta = seg.end - seg.start;
    seg.length = delta.norm();
    if (seg.length > 0) seg.direction = delta / seg.length;
  }
  if (!(seg.length > kLengthEpsilon)) seg.length = 0;
  return seg;
}

Vec3 PathSegment::at(double s) const {
  if (length <= 0) return end;
  if (s <= 0) return start;
  if (s >= length) return end;
  if (arc) return arcGeometry.at(s / length);
  return start + direction * s;
}

}  // namespace isurface
