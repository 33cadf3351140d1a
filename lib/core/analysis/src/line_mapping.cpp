#include "isurface/analysis/line_mapping.h"
#include "isurface/base/tolerances.h"
#include "isurface/base/units.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "isurface/gcode/path_segment.h"

namespace isurface {
namespace {

// Moves this close (mm) to a sample count as equally near: the direction of travel decides
// between them, so that a move retracing the previous one (up then straight down again) is told
// apart from it.
constexpr double kTieDistance = 0.005;

using Nearest = PathPoint;

Nearest nearestOnSegment(const PathSegment& seg, const Vec3& p) { return seg.nearest(p); }

// For each segment, the line a sample takes once it is within blendLead[k] mm of the segment's
// end (its own line when no blend follows, blendLead 0).
struct BlendHandover {
  std::vector<double> lead;            // mm
  std::vector<std::uint32_t> nextLine;
};

BlendHandover blendHandovers(const std::vector<PathSegment>& segments, const std::vector<std::uint32_t>& lines,
                             const std::vector<bool>& stops, const LineMappingOptions& options) {
  BlendHandover h{std::vector<double>(segments.size(), 0.0), lines};
  if (!options.nextLineInBlends) return h;
  for (std::size_t k = 0; k + 1 < segments.size(); ++k) {
    if (stops[k] || segments[k].length <= 0) continue;
    std::size_t j = k + 1;  // zero-length moves are dropped by the planner: blend into the next real one
    while (j < segments.size() && segments[j].length <= 0) ++j;
    if (j == segments.size()) continue;
    const double cosine = std::clamp(segments[k].endTangent().dot(segments[j].startTangent()), -1.0, 1.0);
    const double deflection = std::acos(cosine);  // rad
    // A reversal cannot be blended: the planner stops there.
    if (deflection < options.blendMinAngle || deflection > kPi - 0.01) continue;
    h.lead[k] = std::min(options.blendFraction * std::min(segments[k].length, segments[j].length),
                         options.maxBlendLead);
    h.nextLine[k] = lines[j];
  }
  return h;
}

bool finite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

// Unit direction of travel at sample i from its neighbours, zero at a standstill.
Vec3 travelDirection(const Trajectory& t, std::size_t i) {
  const std::size_t a = i > 0 ? i - 1 : i, b = i + 1 < t.size() ? i + 1 : i;
  const Vec3 pa = t.commanded(a), pb = t.commanded(b);
  if (!finite(pa) || !finite(pb)) return Vec3::Zero();
  const Vec3 d = pb - pa;
  const double len = d.norm();
  return len > kLengthEpsilon ? Vec3(d / len) : Vec3(Vec3::Zero());
}

}  // namespace

double distanceToMove(const Program& program, std::size_t moveIndex, const Vec3& point) {
  return nearestOnSegment(PathSegment::from(program, moveIndex), point).distance;
}

LineMappingOptions linuxcncLineMappingOptions() {
  LineMappingOptions o;
  o.nextLineInBlends = true;
  o.blendMinAngle = 0.001;
  o.blendFraction = 0.42;
  o.maxBlendLead = 0.5;
  return o;
}

LineMapping mapSamplesToLines(const Trajectory& samples, const Program& program, const LineMappingOptions& options) {
  LineMapping out;
  const std::size_t n = samples.size();
  out.line.assign(n, 0);
  out.distance.assign(n, std::numeric_limits<double>::quiet_NaN());
  out.report.tolerance = options.tolerance;

  std::vector<PathSegment> segments;
  std::vector<std::uint32_t> lines;
  std::vector<bool> stops;  // the move ends at standstill: nothing blends past its end
  for (std::size_t m = 0; m < program.moves.size(); ++m)
    if (program.moves[m].isMotion()) {
      segments.push_back(PathSegment::from(program, m));
      lines.push_back(program.moves[m].line);
      const bool dwellNext = m + 1 < program.moves.size() && !program.moves[m + 1].isMotion();
      stops.push_back((program.moves[m].flags & (kExactStop | kStopAfter)) != 0 || dwellNext);
    }
  if (segments.empty()) return out;
  const BlendHandover handover = blendHandovers(segments, lines, stops, options);

  const std::size_t lookahead = std::max<std::size_t>(options.lookaheadMoves, 1);
  std::size_t current = 0;  // the walk only moves forward through `segments`
  double sum = 0;
  std::size_t within = 0;
  std::vector<Nearest> candidates;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = samples.commanded(i);
    if (!finite(p)) continue;
    const std::size_t last = std::min(segments.size() - 1, current + lookahead);
    candidates.clear();
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = current; k <= last; ++k) {
      candidates.push_back(nearestOnSegment(segments[k], p));
      nearest = std::min(nearest, candidates.back().distance);
    }
    const Vec3 dir = travelDirection(samples, i);
    std::size_t chosen = current;
    double bestScore = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      if (candidates[k].distance > nearest + kTieDistance) continue;
      // Among equally near moves: the one heading the way the sample travels; at a standstill
      // (score 0 everywhere) the earliest.
      const double score = candidates[k].tangent.dot(dir);
      if (score > bestScore + kRoundingSlack) bestScore = score, chosen = current + k;
    }
    const Nearest& best = candidates[chosen - current];
    const double d = best.distance;
    current = chosen;
    const bool inBlend = segments[current].length - best.along < handover.lead[current];
    out.line[i] = inBlend ? handover.nextLine[current] : lines[current];
    out.distance[i] = d;
    sum += d;
    out.report.maxDistance = std::max(out.report.maxDistance, d);
    if (d <= options.tolerance) ++within;
    ++out.report.samples;
  }
  if (out.report.samples > 0) {
    out.report.meanDistance = sum / double(out.report.samples);
    out.report.fractionWithin = double(within) / double(out.report.samples);
  }
  return out;
}

}  // namespace isurface
