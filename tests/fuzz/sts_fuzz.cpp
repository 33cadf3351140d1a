// Fuzz target: the slow tool servo job from its user-given parts, the surface expression
// (muParser) and the parameters. The first line is the surface (toric, sinusoid or an
// expression z = f(x, y)); each further line is "name value" for radius, feed, angle, arc,
// height, tool, rho, inserted, uniform, samples, discretise, nodes or interp. Whatever is
// accepted must run to the end in bounded time and memory (libFuzzer's -timeout and
// -rss_limit_mb) with finite figures; everything else must be an InputError.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "fuzz_support.h"
#include "isurface/base/units.h"
#include "isurface/sts/sts_report.h"
#include "isurface/sts/sts_surface.h"

namespace {

void apply(const std::string& name, const std::string& value, isurface::SpiralParameters& p,
           isurface::StsJobOptions& o) {
  const double v = std::strtod(value.c_str(), nullptr);
  if (name == "radius") p.workpieceRadius = v;
  else if (name == "feed") p.feedPerRev = v;
  else if (name == "angle") p.angleStep = v / isurface::kDegreesPerRadian;
  else if (name == "arc") p.arcStep = v;
  else if (name == "height") p.heightStep = v;
  else if (name == "tool") p.toolRadius = v;
  else if (name == "rho") o.rhoMax = v;
  else if (name == "inserted") o.maxInserted = static_cast<int>(std::fmax(-1e9, std::fmin(1e9, v)));
  else if (name == "uniform") o.uniformNodeCount = v > 0 && v < 1e12 ? static_cast<std::size_t>(v) : 0;
  else if (name == "samples") o.samplesPerSegment = static_cast<int>(std::fmax(-1e9, std::fmin(1e9, v)));
  else if (name == "discretise") o.discretisation = isurface::parseStsDiscretisation(value);
  else if (name == "nodes") o.nodes = isurface::parseStsNodes(value);
  else if (name == "interp") o.interpolation = isurface::parseStsInterpolation(value);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::string surfaceLine;
  std::getline(in, surfaceLine);
  isurface::fuzz::expectOnlyInputErrors([&] {
    const auto surface = isurface::makeStsSurface(surfaceLine);
    isurface::SpiralParameters p;
    isurface::StsJobOptions o;
    // A small part by default: each input should take milliseconds unless it asks for more.
    p.workpieceRadius = 2.0;
    p.feedPerRev = 0.2;
    std::string name, value;
    while (in >> name >> value) apply(name, value, p, o);
    const isurface::StsJobResult r = isurface::runStsJob(*surface, p, o);
    for (const isurface::SpiralPoint& node : r.nodes)
      if (!std::isfinite(node.r) || !std::isfinite(node.theta)) std::abort();  // a finding
  });
  return 0;
}
