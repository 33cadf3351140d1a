#pragma once
// The arc the generic control runs in place of a corner between two straight moves: tangent to
// both, ending `reach` mm from the corner along each, in the plane the two directions span
// (any plane, not only G17-G19). Smoothing the path this way before interpolation lets the
// control pass a chord junction at the speed the arc's radius allows instead of braking for a
// velocity step. Units: mm, rad.
#include <cmath>
#include <optional>

#include "isurface/base/geometry.h"
#include "isurface/gcode/path_segment.h"

#include "chord_spline.h"

namespace isurface {

class CornerBlend {
 public:
  // The blend at `corner` between unit directions `in` and `out` that reaches `reach` mm along
  // each; none where the directions are (nearly) parallel or opposite, or `reach` is not above 0.
  static std::optional<CornerBlend> at(const Vec3& corner, const Vec3& in, const Vec3& out, double reach);
  // How far a blend may reach so that it stays within `deviation` of the corner and within
  // `longest` along each line; 0 where no blend fits (a straight junction, a reversal).
  static double reachFor(const Vec3& in, const Vec3& out, double deviation, double longest);
  // The blend of `reach` between these directions, mm.
  static double radiusFor(const Vec3& in, const Vec3& out, double reach);

  double radius() const { return radius_; }
  // How far it passes from the corner, mm.
  double deviation() const { return radius_ * (1.0 / std::cos(0.5 * sweep_) - 1.0); }
  double length() const { return radius_ * sweep_; }
  const Vec3& start() const { return start_; }
  Vec3 end() const { return at(length()); }
  // The unit normal of its plane.
  Vec3 normal() const { return in_.cross(inward_); }
  Vec3 at(double s) const;          // s: mm from its start, clamped to its length
  Vec3 tangentAt(double s) const;   // unit, in the direction of travel

 private:
  Vec3 start_ = Vec3::Zero(), centre_ = Vec3::Zero();
  Vec3 in_ = Vec3::UnitX(), inward_ = Vec3::UnitY();  // unit tangent at the start; unit towards the centre there
  double radius_ = 0, sweep_ = 0;
};

// A line `move` without `trimStart` mm at its start and `trimEnd` mm at its end (an arc as it is).
PathSegment shortenedLine(const PathSegment& move, double trimStart, double trimEnd);

// A piece of the generic control's path: a program move (a line possibly shortened at its ends
// by the blends next to it), a corner blend, or a chord run as a curve.
class PathPiece {
 public:
  PathPiece() = default;
  explicit PathPiece(const PathSegment& move) : segment_(move) {}
  explicit PathPiece(const CornerBlend& blend) : blend_(blend) {}
  explicit PathPiece(const ChordSpline& curve) : curve_(curve) {}
  Vec3 at(double s) const { return blend_ ? blend_->at(s) : curve_ ? curve_->at(s) : segment_.at(s); }
  Vec3 end() const { return blend_ ? blend_->end() : curve_ ? curve_->end() : segment_.end; }
  Vec3 endTangent() const {
    return blend_ ? blend_->tangentAt(blend_->length()) : curve_ ? curve_->endTangent() : segment_.endTangent();
  }

 private:
  PathSegment segment_;
  std::optional<CornerBlend> blend_;
  std::optional<ChordSpline> curve_;
};

}  // namespace isurface
