#include "isurface/map/tool_axes.h"

#include "isurface/base/diagnostic.h"

namespace isurface::vis {

namespace {

constexpr const char* kAxisChannels[3] = {"tool_i", "tool_j", "tool_k"};

}  // namespace

bool hasToolAxes(const Trajectory& samples) {
  for (const char* name : kAxisChannels)
    if (!samples.extraChannel(name)) return false;
  return true;
}

std::vector<std::array<Vec3, 2>> toolAxisMarks(const Trajectory& samples, const PassSet& passes, double spacing,
                                               double length) {
  if (!hasToolAxes(samples))
    throw InputError(Diagnostic{samples.source, 0, 0,
                                "the samples have no tool axis (tool_i tool_j tool_k channels): a five-axis machine's "
                                "simulation writes it (docs/five-axis.md)"});
  const std::vector<double>* axis[3];
  for (int i = 0; i < 3; ++i) axis[i] = samples.extraChannel(kAxisChannels[i]);
  std::vector<std::array<Vec3, 2>> marks;
  for (const Pass& pass : passes.passes) {
    double travelled = spacing;  // a stroke at the pass's start
    for (std::size_t i = pass.begin; i < pass.end; ++i) {
      if (i > pass.begin) travelled += (samples.commanded(i) - samples.commanded(i - 1)).norm();
      if (travelled < spacing) continue;
      const Vec3 direction((*axis[0])[i], (*axis[1])[i], (*axis[2])[i]);
      const Vec3 tip = samples.commanded(i);
      if (!direction.allFinite() || !tip.allFinite() || direction.norm() < 1e-9) continue;
      marks.push_back({tip, tip + direction.normalized() * length});
      travelled = 0;
    }
  }
  return marks;
}

}  // namespace isurface::vis
