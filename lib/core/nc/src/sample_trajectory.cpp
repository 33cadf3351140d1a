// Simulated samples as a Trajectory.
#include "isurface/nc/sample_trajectory.h"

namespace isurface {

Trajectory trajectoryFromSamples(const std::vector<SimSample>& samples, double cycle, const std::string& source) {
  const std::size_t n = samples.size();
  Trajectory out;
  out.source = source;
  out.cycle = cycle;
  out.hasLine = true;
  out.time.resize(n);
  out.line.resize(n);
  out.block.resize(n);
  out.x.resize(n);
  out.y.resize(n);
  out.z.resize(n);
  out.fbX.resize(n);
  out.fbY.resize(n);
  out.fbZ.resize(n);
  out.feed.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const SimSample& s = samples[i];
    out.time[i] = double(i) * cycle;
    out.line[i] = s.line;
    out.block[i] = s.block;
    out.x[i] = s.x;
    out.y[i] = s.y;
    out.z[i] = s.z;
    out.fbX[i] = s.fbX;
    out.fbY[i] = s.fbY;
    out.fbZ[i] = s.fbZ;
    out.feed[i] = s.feed;
  }
  return out;
}

}  // namespace isurface
