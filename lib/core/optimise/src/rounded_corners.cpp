#include "isurface/optimise/rounded_corners.h"

#include <algorithm>
#include <cmath>

#include "isurface/base/tolerances.h"

namespace isurface {

namespace {

// Of each leg, the most an arc may take: half, so that the arcs at both ends of a short leg meet
// in its middle (the doubled point is written once) rather than leave a sliver of it between
// them, whose direction the program's last decimal would blur.
constexpr double kLegShare = 0.5;
// rad: a corner sharper than this is a turn back, whose arc within the tube would be a point.
constexpr double kSharpestCorner = 2.8;
// mm: no chord of an arc is shorter, unless the arc is. The 4 or 5 decimals a program is written
// with blur a shorter chord's direction (0.25 um across 10 um is 0.025 rad), and the NC would
// see the noise as corners; finer chords would also only multiply lines.
constexpr double kShortestChord = 0.02;
// mm: two arcs that each took half of the leg between them end and start this close.
constexpr double kJoinedArcs = 1e-6;

struct Arc {
  Vec3 centre, fromCentreStart, fromCentreEnd;
  double turn = 0;  // rad
  int pieces = 0;   // 0: the corner is kept
  Vec3 at(int piece) const {
    const double t = double(piece) / pieces, s = std::sin(turn);
    return centre + (std::sin((1 - t) * turn) / s) * fromCentreStart + (std::sin(t * turn) / s) * fromCentreEnd;
  }
};

// The arc at `corner` between legs from `before` and to `after`, or none (pieces 0) where the
// corner is too slight, too sharp, or a leg has no length.
Arc arcAt(const Vec3& before, const Vec3& corner, const Vec3& after, double tube, double pieceTurn) {
  Arc arc;
  const Vec3 in = corner - before, out = after - corner;
  const double inLength = in.norm(), outLength = out.norm();
  if (inLength < kLengthEpsilon || outLength < kLengthEpsilon) return arc;
  const Vec3 u = in / inLength, w = out / outLength;
  const double turn = std::acos(std::clamp(u.dot(w), -1.0, 1.0));
  if (turn <= pieceTurn || turn > kSharpestCorner) return arc;
  // The corner lies R / cos(turn / 2) from the centre; the chord nearest it, R cos(turn / pieces
  // / 2) (its middle, with an odd count) or R (a point on the bisector, with an even one).
  auto radiusFor = [&](int pieces) {
    const double nearest = pieces % 2 == 0 ? 1.0 : std::cos(0.5 * turn / pieces);
    const double radius = tube / (1.0 / std::cos(0.5 * turn) - nearest);
    const double tangent = std::min({radius * std::tan(0.5 * turn), kLegShare * inLength, kLegShare * outLength});
    return tangent / std::tan(0.5 * turn);
  };
  int pieces = static_cast<int>(std::ceil(turn / pieceTurn));
  double radius = radiusFor(pieces);
  while (pieces > 1 && 2.0 * radius * std::sin(0.5 * turn / pieces) < kShortestChord) radius = radiusFor(--pieces);
  const double tangent = radius * std::tan(0.5 * turn);
  const Vec3 start = corner - tangent * u, end = corner + tangent * w;
  const Vec3 bisector = (w - u).normalized();
  arc.centre = corner + bisector * (radius / std::cos(0.5 * turn));
  arc.fromCentreStart = start - arc.centre;
  arc.fromCentreEnd = end - arc.centre;
  arc.turn = turn;
  arc.pieces = pieces;
  return arc;
}

}  // namespace

RoundedPath roundedCorners(const std::vector<Vec3>& points, double tube, double pieceTurn) {
  RoundedPath rounded;
  if (points.empty()) return rounded;
  rounded.points.push_back(points.front());
  for (std::size_t k = 1; k < points.size(); ++k) {
    const bool interior = k + 1 < points.size() && tube > 0 && pieceTurn > 0;
    const Arc arc = interior ? arcAt(points[k - 1], points[k], points[k + 1], tube, pieceTurn) : Arc{};
    if (arc.pieces == 0) {
      rounded.points.push_back(points[k]);
      rounded.oldSegment.push_back(k - 1);
      continue;
    }
    // The arc's first half stands for the leg into the corner, its second for the leg out. Its
    // start is the end of the arc before when both took half of the leg between them.
    for (int piece = 0; piece <= arc.pieces; ++piece) {
      const Vec3 p = arc.at(piece);
      if (piece == 0 && (p - rounded.points.back()).norm() < kJoinedArcs) continue;
      rounded.points.push_back(p);
      rounded.oldSegment.push_back(2 * piece <= arc.pieces ? k - 1 : k);
    }
  }
  return rounded;
}

}  // namespace isurface
