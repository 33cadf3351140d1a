#include "isurface/workflow/same_program.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "isurface/base/geometry.h"
#include "isurface/workflow/run_inputs.h"

namespace isurface {

namespace {

constexpr std::size_t kChecks = 2000;          // samples of a checked against b
constexpr std::size_t kPointsPerLine = 400;    // of b's samples of a line, looked at most

// b's samples per line, at most kPointsPerLine of each, evenly spread.
std::unordered_map<std::uint32_t, std::vector<Vec3>> pointsByLine(const Trajectory& b) {
  std::unordered_map<std::uint32_t, std::vector<std::size_t>> indices;
  b.line.forEachRun([&](std::uint32_t line, std::size_t begin, std::size_t end) {
    if (line == 0) return;
    std::vector<std::size_t>& of = indices[line];
    for (std::size_t i = begin; i < end; ++i) of.push_back(i);
  });
  std::unordered_map<std::uint32_t, std::vector<Vec3>> points;
  for (const auto& [line, of] : indices) {
    const std::size_t step = std::max<std::size_t>(1, of.size() / kPointsPerLine);
    std::vector<Vec3>& p = points[line];
    for (std::size_t k = 0; k < of.size(); k += step) p.push_back(b.commanded(of[k]));
    p.push_back(b.commanded(of.back()));
  }
  return points;
}

}  // namespace

std::optional<std::string> runsMismatch(const Trajectory& a, const Trajectory& b) {
  if (!a.hasLine || !b.hasLine || a.size() == 0 || b.size() == 0) return std::nullopt;
  const auto ofB = pointsByLine(b);
  std::size_t withLine = 0, onCommonLines = 0;
  a.line.forEachRun([&](std::uint32_t line, std::size_t begin, std::size_t end) {
    if (line == 0) return;
    withLine += end - begin;
    if (ofB.count(line)) onCommonLines += end - begin;
  });
  // No common line at all is the comparison's own refusal ("shares no G-code line").
  if (withLine == 0 || onCommonLines == 0) return std::nullopt;
  if (2 * onCommonLines < withLine)
    return fmt::format("only {:.1f} % of its samples lie on lines the other run has", 100.0 * double(onCommonLines) / double(withLine));
  const std::size_t step = std::max<std::size_t>(1, a.size() / kChecks);
  std::size_t checked = 0, off = 0;
  for (std::size_t i = 0; i < a.size(); i += step) {
    const std::uint32_t line = a.line[i];
    const Vec3 p = a.commanded(i);
    if (line == 0 || !ofB.count(line) || !p.allFinite()) continue;
    ++checked;
    double nearest = INFINITY;
    for (const std::uint32_t l : {line - 1, line, line + 1}) {
      const auto it = ofB.find(l);
      if (it == ofB.end()) continue;
      // To the polyline through b's points: a long line keeps few of its samples.
      const std::vector<Vec3>& q = it->second;
      nearest = std::min(nearest, (q.front() - p).norm());
      for (std::size_t k = 1; k < q.size(); ++k) nearest = std::min(nearest, distanceToSegment(p, q[k - 1], q[k]));
    }
    if (nearest > kJoinDistance) ++off;
  }
  if (checked == 0 || double(off) <= kRunsOffShare * double(checked)) return std::nullopt;
  return fmt::format("{} of {} samples checked lie farther than {:g} mm from the other run's samples of their line", off,
                     checked, kJoinDistance);
}

}  // namespace isurface
