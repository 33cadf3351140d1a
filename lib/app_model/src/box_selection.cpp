#include "isurface/app_model/box_selection.h"

#include <algorithm>
#include <cmath>

namespace isurface::app_model {

std::optional<std::pair<double, double>> ScreenProjection::operator()(const Vec3& point) const {
  const Eigen::Vector4d device = worldToDevice * Eigen::Vector4d(point.x(), point.y(), point.z(), 1.0);
  if (!(device.w() > 0)) return std::nullopt;
  const double x = device.x() / device.w(), y = device.y() / device.w();
  if (!std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
  return std::make_pair((x + 1) * 0.5 * width, height - (y + 1) * 0.5 * height);
}

std::optional<BoxSelection> selectInRectangle(const Trajectory& samples, const PassSet& surface,
                                              const ScreenProjection& projection, const ScreenRectangle& rectangle) {
  const double left = std::min(rectangle.x0, rectangle.x1), right = std::max(rectangle.x0, rectangle.x1);
  const double top = std::min(rectangle.y0, rectangle.y1), bottom = std::max(rectangle.y0, rectangle.y1);
  BoxSelection found;
  found.lines = LineRange{UINT32_MAX, 0};
  const std::size_t n = std::min(samples.size(), samples.line.size());
  RunChannel<std::uint32_t>::Cursor lineOf = samples.line.cursor();
  for (const Pass& pass : surface.passes) {
    for (std::size_t i = pass.begin; i < std::min(pass.end, n); ++i) {
      const std::uint32_t line = lineOf[i];
      if (line == 0) continue;
      const Vec3 p = samples.commanded(i);
      if (!p.allFinite()) continue;
      const auto at = projection(p);
      if (!at || at->first < left || at->first > right || at->second < top || at->second > bottom) continue;
      found.lower = found.samples ? found.lower.cwiseMin(p) : p;
      found.upper = found.samples ? found.upper.cwiseMax(p) : p;
      found.lines.first = std::min(found.lines.first, line);
      found.lines.last = std::max(found.lines.last, line);
      ++found.samples;
    }
  }
  if (found.samples == 0) return std::nullopt;
  return found;
}

}  // namespace isurface::app_model
