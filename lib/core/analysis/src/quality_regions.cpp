#include "isurface/analysis/quality_regions.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "isurface/analysis/quantities.h"

namespace isurface {

namespace {

// Union-find over vertices, for the connected flagged parts of the mesh.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  std::uint32_t find(std::uint32_t v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::uint32_t> parent_;
};

double ratio(float value, double threshold) {
  return std::isfinite(value) && threshold > 0 ? std::abs(value) / threshold : 0.0;
}

// Per vertex: whether it lies within `length` (mm, along its pass) of the pass's first or last vertex.
std::vector<char> nearPassEnds(const std::vector<Vec3>& positions, const SurfaceMesh& mesh, double length) {
  std::vector<char> near(positions.size(), 0);
  std::vector<double> along(positions.size(), 0.0);
  for (std::size_t p = 0; p + 1 < mesh.passFirstVertex.size(); ++p) {
    const std::size_t first = mesh.passFirstVertex[p], end = mesh.passFirstVertex[p + 1];
    if (first >= end) continue;
    for (std::size_t v = first + 1; v < end; ++v) along[v] = along[v - 1] + (positions[v] - positions[v - 1]).norm();
    const double total = along[end - 1];
    for (std::size_t v = first; v < end; ++v) near[v] = along[v] <= length || total - along[v] <= length;
  }
  return near;
}

}  // namespace

QualityReport findQualityRegions(const Trajectory& samples, const SurfaceMesh& mesh,
                                 const QualityThresholds& thresholds) {
  QualityReport report;
  const std::size_t n = mesh.vertexSample.size();
  report.vertices = n;
  if (n == 0) return report;
  const std::vector<float> speed = vertexQuantity(Quantity::SpeedInconsistency, samples, mesh);
  const std::vector<float> accel = vertexQuantity(Quantity::AccelerationInconsistency, samples, mesh);
  const std::vector<float> jerk = vertexQuantity(Quantity::Jerk, samples, mesh);
  std::vector<float> deviation;
  if (samples.hasFeedback()) deviation = vertexQuantity(Quantity::Deviation, samples, mesh);

  std::vector<double> worst(n, 0.0);
  for (std::size_t v = 0; v < n; ++v)
    worst[v] = std::max({ratio(speed[v], thresholds.speedInconsistency),
                         ratio(accel[v], thresholds.accelInconsistency), ratio(jerk[v], thresholds.jerk)});
  DisjointSets sets(n);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (worst[a] > 1 && worst[b] > 1) sets.join(a, b);
    }
  // Gather each part's figures under its root.
  std::vector<std::int64_t> regionOf(n, -1);
  std::vector<QualityRegion> parts;
  const std::vector<Vec3> positions = meshPositions(samples, mesh);
  std::vector<double> worstInPart;
  const std::vector<char> nearEnd = nearPassEnds(positions, mesh, thresholds.passEndLength);
  RunChannel<std::uint32_t>::Cursor lineOf = samples.line.cursor();
  std::vector<char> allNearEnds;
  for (std::size_t v = 0; v < n; ++v) {
    if (worst[v] <= 1) continue;
    ++report.flaggedVertices;
    const std::uint32_t root = sets.find(static_cast<std::uint32_t>(v));
    if (regionOf[root] < 0) {
      regionOf[root] = static_cast<std::int64_t>(parts.size());
      QualityRegion r;
      r.lower = r.upper = positions[v];
      r.firstLine = r.lastLine = lineOf[mesh.vertexSample[v]];
      parts.push_back(r);
      worstInPart.push_back(0);
      allNearEnds.push_back(1);
    }
    const std::size_t index = static_cast<std::size_t>(regionOf[root]);
    regionOf[v] = regionOf[root];
    QualityRegion& r = parts[index];
    const std::uint32_t line = lineOf[mesh.vertexSample[v]];
    if (line != 0) {
      r.firstLine = r.firstLine == 0 ? line : std::min(r.firstLine, line);
      r.lastLine = std::max(r.lastLine, line);
    }
    ++r.vertices;
    r.severity += worst[v];
    if (!nearEnd[v]) allNearEnds[index] = 0;
    r.lower = r.lower.cwiseMin(positions[v]);
    r.upper = r.upper.cwiseMax(positions[v]);
    r.centroid += positions[v];
    if (std::isfinite(speed[v])) r.maxSpeedInconsistency = std::max<double>(r.maxSpeedInconsistency, speed[v]);
    if (std::isfinite(accel[v])) r.maxAccelInconsistency = std::max<double>(r.maxAccelInconsistency, accel[v]);
    if (std::isfinite(jerk[v])) r.maxJerk = std::max<double>(r.maxJerk, jerk[v]);
    if (!deviation.empty() && std::isfinite(deviation[v]))
      r.maxDeviation = std::max<double>(r.maxDeviation, std::abs(deviation[v]));
    if (worst[v] > worstInPart[index]) {
      worstInPart[index] = worst[v];
      r.worstSample = mesh.vertexSample[v];
    }
  }
  for (const auto& t : mesh.triangles) {
    const std::int64_t a = regionOf[t[0]];
    if (a < 0 || regionOf[t[1]] != a || regionOf[t[2]] != a) continue;
    parts[static_cast<std::size_t>(a)].area +=
        0.5 * (positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]).norm();
  }
  for (std::size_t k = 0; k < parts.size(); ++k) {
    QualityRegion& r = parts[k];
    if (r.vertices < thresholds.minimumVertices) continue;
    r.atPassEnds = allNearEnds[k];
    r.centroid /= static_cast<double>(r.vertices);
    report.regions.push_back(r);
  }
  std::sort(report.regions.begin(), report.regions.end(),
            [](const QualityRegion& a, const QualityRegion& b) { return a.severity > b.severity; });
  return report;
}

const QualityRegion* worstRegionInsidePasses(const QualityReport& report) {
  for (const QualityRegion& r : report.regions)
    if (!r.atPassEnds) return &r;
  return nullptr;
}

}  // namespace isurface
