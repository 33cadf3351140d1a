// isurface-cli fit GCODE --lines A-B: the Akima spline through the CL points of those lines'
// cutting moves (in the chord-length parameter), resampled to G1 moves, as JSON.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "command.h"
#include "json_output.h"
#include "inputs.h"
#include "isurface/base/units.h"
#include "isurface/fitting/akima_spline.h"
#include "isurface/fitting/constant_speed_intervals.h"
#include "number_options.h"
#include "isurface/base/json_text.h"

namespace isurface::cli {
namespace {


struct FitOptions {
  std::string input, lines;
  double tolerance = 0.001;
};



double distanceToPolyline(const Vec3& x, const std::vector<Vec3>& q) {
  double best = q.empty() ? 0.0 : (x - q.front()).norm();
  for (std::size_t k = 0; k + 1 < q.size(); ++k) {
    const Vec3 ab = q[k + 1] - q[k];
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((x - q[k]).dot(ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (x - q[k] - t * ab).norm());
  }
  return best;
}

// Largest angle (degrees) between one segment's end tangent and the next one's start tangent.
double maxJoinAngleDeg(const std::vector<CubicSegment>& segments) {
  double worst = 0;
  for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
    const Vec3 a = segments[i].derivative(segments[i].length), b = segments[i + 1].derivative(0);
    // atan2 rather than acos: acos loses all precision for nearly parallel tangents.
    worst = std::max(worst, std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / kPi);
  }
  return worst;
}

int runFit(const FitOptions& o) {
  if (!(o.tolerance > 0)) badOption(o.input, "--tolerance must be > 0 mm");
  // Finer than a nanometre, the resampled moves would number in the billions.
  if (!(o.tolerance >= 1e-6 && o.tolerance <= 10)) badOption(o.input, "--tolerance must be from 1e-06 to 10 mm");
  LineRange range;
  try {
    range = parseLineRange(o.lines);
  } catch (const InputError& e) {
    badOption(o.input, "--lines: " + e.diagnostic().message);
  }
  const Program program = loadProgram(o.input, false, false);
  // One continuous piece of path: sections are not split by distance or at reversals here.
  SectionOptions options;
  options.distanceThreshold = 1e300;
  options.reversalAngleDeg = 180;
  const std::vector<PathSection> sections = collectSections(program, range.first, range.last, options);
  if (sections.empty()) badOption(o.input, "no cutting moves (G1, G2, G3) in lines " + o.lines);
  std::vector<Vec3> points;
  for (const PathSection& s : sections)  // pieces separated by rapids are joined end to end
    for (const Vec3& p : s.points) points.push_back(p);
  points = distinctPoints(points);
  if (points.size() < 2) badOption(o.input, "lines " + o.lines + " do not move the tool");

  IncrementalAkimaFitter fitter;
  for (const Vec3& p : points) fitter.add(p);
  fitter.finish();
  const PiecewiseCubicCurve curve(fitter.segments());
  const std::vector<Vec3> resampled = curve.resample(o.tolerance);
  double deviation = 0;
  for (const Vec3& p : points) deviation = std::max(deviation, distanceToPolyline(p, resampled));

  Json segments = Json::array();
  for (const CubicSegment& s : curve.segments())
    segments.push_back({{"start_mm", triple(s.a)}, {"length_mm", s.length}, {"tangent", triple(s.b)}});
  Json out;
  out["source"] = o.input;
  out["lines"] = {range.first, range.last};
  out["points"] = points.size();
  out["segments"] = segments;
  out["parameter_length_mm"] = curve.parameterLength();
  out["arc_length_mm"] = curve.arcLength();
  out["tolerance_mm"] = o.tolerance;
  out["resampled_points"] = resampled.size();
  out["max_point_deviation_mm"] = deviation;
  out["max_join_angle_deg"] = maxJoinAngleDeg(curve.segments());
  std::printf("%s\n", jsonText(out, 2).c_str());
  return kExitOk;
}

}  // namespace

Command fitCommand() {
  return Command{"fit", "Fit an Akima spline through the CL points of a line range and resample it (JSON)",
    [](CLI::App& sub) {
      auto o = std::make_shared<FitOptions>();
      sub.add_option("program", o->input, "G-code file")->required();
      sub.add_option("--lines", o->lines, "source lines A-B (1-based, inclusive)")->required();
      sub.add_option("--tolerance", o->tolerance, "chord tolerance of the resampled moves, mm")
          ->capture_default_str()
          ->check(numberFrom(0, 10, true));
      return [o] { return runFit(*o); };
    }};
}

}  // namespace isurface::cli
