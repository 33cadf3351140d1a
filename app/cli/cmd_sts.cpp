// isurface-cli sts: slow tool servo turning tool path for a surface z = f(x, y): NC program with
// PVT data and a JSON report of the discrete and interpolation errors; or, with --paper-tables,
// the comparison with the figures of the STS tool path paper.
#include <cmath>
#include <cstdio>
#include <memory>

#include "command.h"
#include "output_options.h"
#include "isurface/io/atomic_file.h"
#include "isurface/base/diagnostic.h"
#include "isurface/base/units.h"
#include "isurface/sts/sts_report.h"
#include "isurface/sts/sts_samples.h"
#include "isurface/map/quality_map.h"
#include "isurface/vis/quality_scene.h"
#include "isurface/vis/offscreen_render.h"
#include "isurface/io/trajectory_writing.h"
#include "number_options.h"
#include "isurface/base/json_text.h"

namespace isurface::cli {
namespace {

struct StsOptions {
  std::string surface = "toric", discretise = "height", nodes = "nonuniform", interp = "spline";
  std::string output, report, biip, png, color = "interpolation";
  bool paperTables = false;
  double radius = 0, feed = 0, angleStepDeg = 0, arcStep = 0, heightStep = 0, toolRadius = 0;
  double rhoMax = 0, spindleRpm = 10;
  int maxInserted = 4, samples = 8;
  std::size_t uniformNodes = 0;
  // Options the user gave; the others keep the paper's value for the surface.
  CLI::Option *radiusOpt = nullptr, *feedOpt = nullptr, *angleOpt = nullptr, *arcOpt = nullptr,
              *heightOpt = nullptr, *toolOpt = nullptr;
};

[[noreturn]] void usage(const std::string& message) { throw InputError({"sts", 0, 0, message}); }

int runPaperTables() {
  const std::vector<StsPaperComparison> rows = {compareWithPaper(paperToricCase()),
                                                compareWithPaper(paperSinusoidCase())};
  std::printf("%s", formatStsPaperTable(rows).c_str());
  return kExitOk;
}

int runSts(const StsOptions& o) {
  if (o.paperTables) return runPaperTables();
  if (o.output.empty() && o.report.empty() && o.biip.empty() && o.png.empty())
    usage("give -o PATH.nc, --report REPORT.json, --biip OUT.biip or --png MAP.png (or --paper-tables)");
  if (o.color != "discrete" && o.color != "interpolation")
    usage("--color is discrete or interpolation (error)");
  StsJobOptions job;
  job.discretisation = parseStsDiscretisation(o.discretise);
  job.nodes = parseStsNodes(o.nodes);
  job.interpolation = parseStsInterpolation(o.interp);
  job.rhoMax = o.rhoMax;
  job.maxInserted = o.maxInserted;
  job.uniformNodeCount = o.uniformNodes;
  job.spindleRpm = o.spindleRpm;
  job.samplesPerSegment = o.samples;
  if (o.uniformNodes == 1) usage("--uniform-nodes: at least 2 nodes (or 0 for one per CCP)");

  const std::unique_ptr<StsSurface> surface = makeStsSurface(o.surface);
  SpiralParameters p = (o.surface == "sinusoid" ? paperSinusoidCase() : paperToricCase()).spiral;
  if (*o.radiusOpt) p.workpieceRadius = o.radius;
  if (*o.feedOpt) p.feedPerRev = o.feed;
  if (*o.angleOpt) p.angleStep = o.angleStepDeg / kDegreesPerRadian;
  if (*o.arcOpt) p.arcStep = o.arcStep;
  if (*o.heightOpt) p.heightStep = o.heightStep;
  if (*o.toolOpt) p.toolRadius = o.toolRadius;

  const StsJobResult r = runStsJob(*surface, p, job);
  if (!std::isfinite(r.discrete.max) || !std::isfinite(r.interpolation.max))
    usage("the surface is not finite along the tool path (check the expression's domain)");
  const std::string program = formatStsNcProgram(*surface, p, job, r);
  if (!o.output.empty()) writeFileAtomically(o.output, program);
  if (!o.biip.empty() || !o.png.empty()) {
    const Trajectory samples = stsTrajectory(r, job, program, o.output.empty() ? surface->name() : o.output);
    if (!o.biip.empty()) writeTrajectoryBiip(samples, o.biip);
    if (!o.png.empty()) {
      vis::QualityMapRequest request;
      request.channel = o.color + "_error_um";
      request.view = vis::ViewDirection::Iso;
      request.caption = surface->name() + ": " + o.discretise + " discretisation, " + o.nodes + " " + o.interp;
      vis::QualityMap map = vis::buildQualityMap(samples, nullptr, request);
      vis::QualityScene scene(map.data, map.style);
      vis::renderSceneToPng(scene, 1600, 1000, o.png);
    }
  }
  if (!o.report.empty()) writeFileAtomically(o.report, jsonText(stsReportJson(*surface, p, job, r), 2) + "\n");
  std::printf("%s: %zu CCPs (%s), %zu nodes (%s, %s); max discrete error %.4g um, "
              "max interpolation error %.4g um\n",
              surface->name().c_str(), r.contactPoints.size(), o.discretise.c_str(), r.nodes.size(),
              o.nodes.c_str(), o.interp.c_str(), r.discrete.max * 1000, r.interpolation.max * 1000);
  return kExitOk;
}

}  // namespace

Command stsCommand() {
  return Command{"sts", "Slow tool servo turning tool path (spiral, nose compensation, PVT) and its errors",
    [](CLI::App& sub) {
      auto o = std::make_shared<StsOptions>();
      sub.add_option("--surface", o->surface,
                     "toric, sinusoid (the paper's Tables 1 and 2) or an expression z = f(x, y) in mm");
      sub.add_option("--discretise", o->discretise, "angle, arc or height");
      sub.add_option("--nodes", o->nodes, "uniform or nonuniform interpolation nodes");
      sub.add_option("--interp", o->interp, "hermite, spline (three-slope) or spline-moment");
      outputOption(sub.add_option("-o,--output", o->output, "NC program to write"));
      outputOption(sub.add_option("--report", o->report, "JSON error report to write"));
      outputOption(sub.add_option("--biip", o->biip, "the tool path as a Biip dump (one sample a node, errors as channels)"));
      outputOption(sub.add_option("--png", o->png, "render the tool path's surface coloured by an error"));
      sub.add_option("--color", o->color, "discrete or interpolation (error) for --png")->capture_default_str();
      sub.add_flag("--paper-tables", o->paperTables, "compare with the paper's reported reductions");
      o->radiusOpt = sub.add_option("--radius", o->radius, "workpiece radius R, mm");
      o->feedOpt = sub.add_option("--feed", o->feed, "feed per revolution a_f, mm/rev");
      o->angleOpt = sub.add_option("--angle-step", o->angleStepDeg, "allowable discrete angle, deg");
      o->arcOpt = sub.add_option("--arc-step", o->arcStep, "allowable discrete arc length, mm");
      o->heightOpt = sub.add_option("--height-step", o->heightStep, "allowable height difference, mm");
      o->toolOpt = sub.add_option("--tool-radius", o->toolRadius, "tool nose radius R_t, mm");
      sub.add_option("--rho-max", o->rhoMax, "curvature above which nodes are added, 1/mm (0: mean)")
          ->check(numberFrom(0, 1e9));
      sub.add_option("--max-inserted", o->maxInserted, "most nodes added inside one CCP segment");
      sub.add_option("--uniform-nodes", o->uniformNodes, "uniform node count (0: one per CCP)");
      sub.add_option("--spindle-rpm", o->spindleRpm, "spindle speed, rev/min (PVT times)")
          ->check(numberFrom(kSlowestSpindleRpm, kFastestSpindleRpm));
      sub.add_option("--samples", o->samples, "error samples inside each segment");
      return [o] { return runSts(*o); };
    }};
}

}  // namespace isurface::cli
