#include "isurface/sts/sts_samples.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "isurface/base/units.h"

namespace isurface {

Trajectory stsTrajectory(const StsJobResult& job, const StsJobOptions& options, const std::string& ncText,
                         const std::string& source) {
  // The physical line of the first node block ("N1 ...").
  std::uint32_t firstBlock = 0, lineNumber = 0;
  std::istringstream lines(ncText);
  for (std::string line; std::getline(lines, line);) {
    ++lineNumber;
    if (line.rfind("N1 ", 0) == 0) {
      firstBlock = lineNumber;
      break;
    }
  }
  Trajectory t;
  t.source = source;
  const double secondsPerRadian = secondsPerRadianAtRpm(options.spindleRpm);
  t.cycle = job.nodes.size() > 1 ? std::abs(job.nodes[1].theta - job.nodes[0].theta) * secondsPerRadian : 0.001;
  std::vector<double> discrete, interpolation;
  for (std::size_t k = 0; k < job.nodes.size(); ++k) {
    const SpiralPoint& n = job.nodes[k];
    t.x.push_back(n.x());
    t.y.push_back(n.y());
    t.z.push_back(n.z);
    t.time.push_back(n.theta * secondsPerRadian);
    t.line.push_back(firstBlock ? firstBlock + static_cast<std::uint32_t>(k) : 0);
    // The contact-point segment this node falls in (the CCPs are in increasing theta).
    const auto& ccps = job.contactPoints;
    const auto after = std::upper_bound(ccps.begin(), ccps.end(), n.theta,
                                        [](double theta, const SpiralPoint& p) { return theta < p.theta; });
    const std::size_t segment =
        std::min<std::size_t>(after == ccps.begin() ? 0 : (after - ccps.begin()) - 1, job.discrete.perSegment.size() - 1);
    discrete.push_back(job.discrete.perSegment.empty() ? 0.0 : 1000.0 * job.discrete.perSegment[segment]);
    const std::size_t own = std::min(k, job.interpolation.perSegment.size() - 1);
    interpolation.push_back(job.interpolation.perSegment.empty() ? 0.0 : 1000.0 * job.interpolation.perSegment[own]);
  }
  t.hasLine = firstBlock != 0;
  t.irregularTime = true;
  t.extra.emplace_back("discrete_error_um", std::move(discrete));
  t.extra.emplace_back("interpolation_error_um", std::move(interpolation));
  return t;
}

}  // namespace isurface
