#include "isurface/sts/sts_report.h"
#include "isurface/base/units.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "isurface/base/diagnostic.h"

namespace isurface {

StsCase paperToricCase() {
  StsCase c;
  c.surface = "toric";
  c.spiral.workpieceRadius = 20;
  c.spiral.feedPerRev = 0.5;
  c.spiral.toolRadius = 0.2;
  c.spiral.heightStep = 0.04;
  c.spiral.arcStep = 1;
  c.spiral.angleStep = 5 / kDegreesPerRadian;
  return c;
}

StsCase paperSinusoidCase() {
  StsCase c;
  c.surface = "sinusoid";
  c.spiral.workpieceRadius = 30;
  c.spiral.feedPerRev = 0.5;
  c.spiral.toolRadius = 0.2;
  c.spiral.heightStep = 0.1;
  c.spiral.arcStep = 1;
  c.spiral.angleStep = 3 / kDegreesPerRadian;
  return c;
}

// An error larger than the workpiece itself is not a machining error but a surface that jumps (a
// step, `x>0?1:0`) or whose slope is not finite between the points: refused where it happens.
static void requirePlausibleError(const ErrorProfile& e, const SpiralParameters& p, const char* which) {
  if (std::isfinite(e.max) && e.max <= p.workpieceRadius) return;
  throw InputError({"sts", 0, 0,
                    fmt::format("the {} error reaches {:.4g} mm at r = {:.4g} mm, theta = {:.4g} rad, more than the workpiece's "
                                "radius: the surface is not continuous or not smooth along the tool path there",
                                which, e.max, e.radiusAtMax, e.thetaAtMax)});
}

StsJobResult runStsJob(const StsSurface& surface, const SpiralParameters& p, const StsJobOptions& o) {
  p.validate();
  // A slow tool servo turns at a few to a few thousand rev/min; beyond these bounds the PVT
  // blocks' times and speeds are no longer numbers a control reads (1e-300 ms, VX-inf).
  if (!(o.spindleRpm >= kSlowestSpindleRpm && o.spindleRpm <= kFastestSpindleRpm))
    throw InputError({"sts", 0, 0,
                      fmt::format("--spindle-rpm {:g} is not from {:g} to {:g} rev/min", o.spindleRpm, kSlowestSpindleRpm,
                                  kFastestSpindleRpm)});
  if (!(o.rhoMax >= 0) || !std::isfinite(o.rhoMax))
    throw InputError({"sts", 0, 0, fmt::format("--rho-max {:g} must be a curvature of 0 (the mean) or more, 1/mm", o.rhoMax)});
  if (o.samplesPerSegment < 1) throw InputError({"sts", 0, 0, "--samples must be at least 1"});
  if (o.maxInserted < 0) throw InputError({"sts", 0, 0, "--max-inserted must not be negative"});
  // Bounded up front: each costs that many surface evaluations per contact point or node.
  if (o.samplesPerSegment > 10000) throw InputError({"sts", 0, 0, "--samples must be at most 10000"});
  if (o.maxInserted > 1000) throw InputError({"sts", 0, 0, "--max-inserted must be at most 1000"});
  if (o.uniformNodeCount > 20000000) throw InputError({"sts", 0, 0, "--uniform-nodes must be at most 20000000"});
  StsJobResult r;
  r.contactPoints = discretiseSpiral(surface, p, o.discretisation);
  r.discrete = discreteError(surface, p, r.contactPoints, o.samplesPerSegment);
  std::vector<double> angles;
  if (o.nodes == StsNodes::Uniform) {
    angles = uniformNodeAngles(p, o.uniformNodeCount ? o.uniformNodeCount : r.contactPoints.size());
  } else {
    NonUniformNodes n = nonUniformNodeAngles(surface, p, r.contactPoints, o.rhoMax, o.maxInserted);
    angles = std::move(n.theta);
    r.rhoMax = n.rhoMax;
    r.insertedNodes = n.inserted;
  }
  r.nodes = cuttingLocationPointsAt(surface, p, angles);
  r.track = buildPvtTrack(r.nodes, o.interpolation);
  if (o.interpolation != StsInterpolation::Hermite) {
    const StsInterpolation other = o.interpolation == StsInterpolation::SplineThreeSlope
                                       ? StsInterpolation::SplineThreeMoment
                                       : StsInterpolation::SplineThreeSlope;
    const PvtTrack check = buildPvtTrack(r.nodes, other);
    for (std::size_t i = 0; i < check.slope.size(); ++i)
      r.splineSlopeDisagreement =
          std::max(r.splineSlopeDisagreement, std::abs(check.slope[i] - r.track.slope[i]));
  }
  r.interpolation = interpolationError(surface, p, r.track, o.samplesPerSegment);
  requirePlausibleError(r.discrete, p, "discrete");
  requirePlausibleError(r.interpolation, p, "interpolation");
  return r;
}

std::string formatStsNcProgram(const StsSurface& surface, const SpiralParameters& p,
                               const StsJobOptions& o, const StsJobResult& r) {
  const double omega = rpmToRadPerS(o.spindleRpm);  // rad/s
  const double vx = -p.feedPerRev / (2 * kPi) * omega;   // mm/s, constant along the spiral
  const double vc = rpmToDegreesPerS(o.spindleRpm);      // deg/s
  std::string out;
  out += "; slow tool servo turning tool path (isurface-cli sts)\n";
  out += fmt::format("; surface: {}\n", surface.name());
  out += fmt::format("; discretise={} nodes={} interp={}\n", toString(o.discretisation),
                     toString(o.nodes), toString(o.interpolation));
  out += fmt::format(
      "; workpiece radius {} mm, feed {} mm/rev, tool nose radius {} mm, spindle {} rpm\n",
      p.workpieceRadius, p.feedPerRev, p.toolRadius, o.spindleRpm);
  out += fmt::format("; max discrete error {:.6g} mm, max interpolation error {:.6g} mm\n",
                     r.discrete.max, r.interpolation.max);
  out += "; PVT blocks: N<k> X<radius mm> C<spindle angle deg, accumulated> Z<tool height mm>\n";
  out += ";   ; T<time from the previous block, ms> VX<mm/s> VC<deg/s> VZ<mm/s> at the block's end\n";
  out += "G90\n";
  double previous = r.track.theta.empty() ? 0 : r.track.theta.front();
  for (std::size_t i = 0; i < r.nodes.size(); ++i) {
    const SpiralPoint& q = r.nodes[i];
    const double dtMs = (q.theta - previous) / omega * 1000;
    previous = q.theta;
    out += fmt::format("N{} X{:.6f} C{:.6f} Z{:.7f} ; T{:.4f} VX{:.6f} VC{:.4f} VZ{:.7f}\n", i + 1,
                       q.r, q.theta * kDegreesPerRadian, q.z, dtMs, vx, vc, r.track.slope[i] * omega);
  }
  out += "M30\n";
  return out;
}

nlohmann::json stsReportJson(const StsSurface& surface, const SpiralParameters& p,
                             const StsJobOptions& o, const StsJobResult& r) {
  auto profile = [](const ErrorProfile& e) {
    return nlohmann::json{{"max_mm", e.max},
                          {"theta_at_max_rad", e.thetaAtMax},
                          {"radius_at_max_mm", e.radiusAtMax},
                          {"interior_max_mm", e.interiorMax},
                          {"per_segment_max_mm", e.perSegment}};
  };
  nlohmann::json j;
  j["surface"] = surface.name();
  j["parameters"] = {{"workpiece_radius_mm", p.workpieceRadius}, {"feed_mm_per_rev", p.feedPerRev},
                     {"angle_step_deg", p.angleStep * kDegreesPerRadian}, {"arc_step_mm", p.arcStep},
                     {"height_step_mm", p.heightStep}, {"tool_radius_mm", p.toolRadius},
                     {"spindle_rpm", o.spindleRpm}, {"samples_per_segment", o.samplesPerSegment}};
  j["discretise"] = toString(o.discretisation);
  j["nodes"] = toString(o.nodes);
  j["interp"] = toString(o.interpolation);
  j["contact_points"] = r.contactPoints.size();
  j["interpolation_nodes"] = r.nodes.size();
  if (o.nodes == StsNodes::NonUniform) {
    j["rho_max_per_mm"] = r.rhoMax;
    j["inserted_nodes"] = r.insertedNodes;
  }
  if (o.interpolation != StsInterpolation::Hermite)
    j["spline_slope_disagreement_mm_per_rad"] = r.splineSlopeDisagreement;
  j["discrete_error"] = profile(r.discrete);
  j["interpolation_error"] = profile(r.interpolation);
  return j;
}

StsPaperComparison compareWithPaper(const StsCase& c) {
  const auto surface = makeStsSurface(c.surface);
  StsPaperComparison out;
  out.surface = c.surface;
  const bool toric = c.surface == "toric";
  out.paperHeightReduction = toric ? 0.70 : 0.80;
  out.paperNodeReduction = toric ? 0.70 : 0.30;
  auto maxima = [](const ErrorProfile& e) { return StsErrorMaxima{e.max, e.interiorMax}; };
  const auto angle = discretiseSpiral(*surface, c.spiral, StsDiscretisation::EqualAngle);
  const auto arc = discretiseSpiral(*surface, c.spiral, StsDiscretisation::EqualArcLength);
  const auto height = discretiseSpiral(*surface, c.spiral, StsDiscretisation::EqualHeight);
  out.ccpAngle = angle.size();
  out.ccpArc = arc.size();
  out.ccpHeight = height.size();
  out.discreteAngle = maxima(discreteError(*surface, c.spiral, angle));
  out.discreteArc = maxima(discreteError(*surface, c.spiral, arc));
  out.discreteHeight = maxima(discreteError(*surface, c.spiral, height));

  const NonUniformNodes nonUniform = nonUniformNodeAngles(*surface, c.spiral, height, 0);
  out.nodeCount = nonUniform.theta.size();
  const auto nodesNonUniform = cuttingLocationPointsAt(*surface, c.spiral, nonUniform.theta);
  const auto nodesUniform =
      cuttingLocationPointsAt(*surface, c.spiral, uniformNodeAngles(c.spiral, out.ccpHeight));
  auto error = [&](const std::vector<SpiralPoint>& nodes, StsInterpolation m) {
    return maxima(interpolationError(*surface, c.spiral, buildPvtTrack(nodes, m)));
  };
  out.hermiteUniform = error(nodesUniform, StsInterpolation::Hermite);
  out.hermiteNonUniform = error(nodesNonUniform, StsInterpolation::Hermite);
  out.splineSlope = error(nodesNonUniform, StsInterpolation::SplineThreeSlope);
  out.splineMoment = error(nodesNonUniform, StsInterpolation::SplineThreeMoment);
  const PvtTrack a = buildPvtTrack(nodesNonUniform, StsInterpolation::SplineThreeSlope);
  const PvtTrack b = buildPvtTrack(nodesNonUniform, StsInterpolation::SplineThreeMoment);
  for (std::size_t i = 0; i < a.slope.size(); ++i)
    out.slopeDisagreement = std::max(out.slopeDisagreement, std::abs(a.slope[i] - b.slope[i]));
  return out;
}

std::string formatStsPaperTable(const std::vector<StsPaperComparison>& rows) {
  using Row = StsPaperComparison;
  // Each surface gets two columns: the whole path, and away from its ends (interior).
  auto um = [](const StsErrorMaxima& e) {
    return fmt::format("{:>12.4g}{:>12.4g}", e.overall * 1000, e.interior * 1000);
  };
  auto pct = [](double a) { return fmt::format("{:.0f}%", a * 100); };
  auto reduction = [&](const StsErrorMaxima& better, const StsErrorMaxima& worse) {
    return fmt::format("{:>12}{:>12}", pct(1 - better.overall / worse.overall),
                       pct(1 - better.interior / worse.interior));
  };
  auto ratio = [](const StsErrorMaxima& a, const StsErrorMaxima& b) {
    return fmt::format("{:>11.3g}x{:>11.3g}x", a.overall / b.overall, a.interior / b.interior);
  };
  auto plain = [](const std::string& v) { return fmt::format("{:>24}", v); };
  std::string out =
      "Slow tool servo tool paths, paper Tables 1 and 2 parameters; errors are maxima in um over\n"
      "the whole path and over its interior (more than one revolution from the rim and centre)\n";
  out += fmt::format("{:<44}", "");
  for (const Row& r : rows) out += fmt::format("{:>24}{:>8}", r.surface + " all / interior", "paper");
  out += "\n";
  auto line = [&](const std::string& label, auto ours, auto paper) {
    out += fmt::format("{:<44}", label);
    for (const Row& r : rows) out += fmt::format("{}{:>8}", ours(r), paper(r));
    out += "\n";
  };
  auto none = [](const Row&) { return std::string("-"); };
  line("CCPs equal angle / arc / height",
       [&](const Row& r) { return plain(fmt::format("{}/{}/{}", r.ccpAngle, r.ccpArc, r.ccpHeight)); }, none);
  line("discrete error, equal angle", [&](const Row& r) { return um(r.discreteAngle); }, none);
  line("discrete error, equal arc length", [&](const Row& r) { return um(r.discreteArc); }, none);
  line("discrete error, equal height", [&](const Row& r) { return um(r.discreteHeight); }, none);
  line("  reduction, equal height vs equal angle",
       [&](const Row& r) { return reduction(r.discreteHeight, r.discreteAngle); },
       [&](const Row& r) { return pct(r.paperHeightReduction); });
  line("interpolation nodes, uniform / non-uniform",
       [&](const Row& r) { return plain(fmt::format("{}/{}", r.ccpHeight, r.nodeCount)); }, none);
  line("interp. error, uniform Hermite", [&](const Row& r) { return um(r.hermiteUniform); }, none);
  line("interp. error, non-uniform Hermite", [&](const Row& r) { return um(r.hermiteNonUniform); }, none);
  line("  reduction, non-uniform vs uniform",
       [&](const Row& r) { return reduction(r.hermiteNonUniform, r.hermiteUniform); },
       [&](const Row& r) { return pct(r.paperNodeReduction); });
  line("interp. error, non-uniform spline 3-slope", [&](const Row& r) { return um(r.splineSlope); }, none);
  line("interp. error, non-uniform spline 3-moment", [&](const Row& r) { return um(r.splineMoment); }, none);
  line("  ratio, Hermite / spline (non-uniform)",
       [&](const Row& r) { return ratio(r.hermiteNonUniform, r.splineSlope); },
       [&](const Row& r) { return fmt::format("~{:.0f}x", r.paperSplineRatio); });
  line("3-slope vs 3-moment node slopes, mm/rad",
       [&](const Row& r) { return plain(fmt::format("{:.1e}", r.slopeDisagreement)); }, none);
  return out;
}

}  // namespace isurface
