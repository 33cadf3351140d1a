#include "isurface/gcode/arc.h"

#include <cmath>

#include "isurface/base/tolerances.h"
#include "isurface/base/units.h"

namespace isurface {

ArcGeometry ArcGeometry::from(const Vec3& start, const Move& move) {
  ArcGeometry g;
  g.axes = planeAxes(move.plane);
  g.centre = move.centre;
  const int u = g.axes.u, v = g.axes.v, w = g.axes.w;
  const double su = start[u] - move.centre[u], sv = start[v] - move.centre[v];
  const double eu = move.end[u] - move.centre[u], ev = move.end[v] - move.centre[v];
  g.startRadius = std::hypot(su, sv);
  g.endRadius = std::hypot(eu, ev);
  g.startAngle = std::atan2(sv, su);
  g.startW = start[w];
  g.endW = move.end[w];
  const double endAngle = std::atan2(ev, eu);
  const bool ccw = move.kind == MoveKind::ArcCCW;
  double sweep = endAngle - g.startAngle;
  // Start and end coincide in the plane: a full circle, as in RS274NGC.
  const bool samePoint = std::hypot(eu - su, ev - sv) < kLengthEpsilon * (1.0 + g.startRadius);
  if (ccw) {
    while (sweep <= 0) sweep += kTwoPi;
    if (samePoint) sweep = kTwoPi;
  } else {
    while (sweep >= 0) sweep -= kTwoPi;
    if (samePoint) sweep = -kTwoPi;
  }
  if (sweep > kTwoPi) sweep -= kTwoPi;
  if (sweep < -kTwoPi) sweep += kTwoPi;
  const double extra = kTwoPi * (move.turns > 1 ? move.turns - 1 : 0);
  g.sweep = ccw ? sweep + extra : sweep - extra;
  if (g.startRadius < kLengthEpsilon && g.endRadius < kLengthEpsilon) g.sweep = 0;
  return g;
}

double ArcGeometry::length() const {
  const double planar = std::abs(sweep) * 0.5 * (startRadius + endRadius);
  return std::hypot(planar, endW - startW);
}

Vec3 ArcGeometry::at(double f) const {
  const double angle = startAngle + sweep * f;
  const double r = startRadius + (endRadius - startRadius) * f;
  Vec3 p;
  p[axes.u] = centre[axes.u] + r * std::cos(angle);
  p[axes.v] = centre[axes.v] + r * std::sin(angle);
  p[axes.w] = startW + (endW - startW) * f;
  return p;
}

Vec3 ArcGeometry::tangentAt(double f) const {
  const double angle = startAngle + sweep * f;
  const double r = startRadius + (endRadius - startRadius) * f;
  // d/df of the position.
  const double c = std::cos(angle), s = std::sin(angle);
  const double dr = endRadius - startRadius;
  Vec3 d;
  d[axes.u] = dr * c - r * s * sweep;
  d[axes.v] = dr * s + r * c * sweep;
  d[axes.w] = endW - startW;
  const double n = d.norm();
  return n > 0 ? Vec3(d / n) : Vec3(Vec3::Zero());
}

}  // namespace isurface
