// isurface-cli render: a quality map of a program (simulated, or from its Biip dump) as a PNG.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "command.h"
#include "output_options.h"
#include "inputs.h"
#include "isurface/io/biip.h"
#include "isurface/analysis/quantities.h"
#include "isurface/nc/simulator.h"
#include "isurface/vis/color_map.h"
#include "isurface/map/quality_map.h"
#include "isurface/map/tool_axes.h"
#include "isurface/vis/quality_scene.h"
#include "isurface/vis/offscreen_render.h"
#include "isurface/io/trajectory_loading.h"
#include "progress.h"
#include "isurface/workflow/run_inputs.h"
#include "trajectory_input.h"
#include "number_options.h"

namespace isurface::cli {
namespace {

struct RenderOptions {
  std::string gcode, biip, output;
  MachineOption machine;
  std::string color = "speed", view = "iso", size = "1600x1000", colorMap = "auto";
  std::string range, percentiles = "1:99", surface = "commanded", pattern = "auto";
  long highlightLine = -1;
  bool noToolpath = false, noPassWires = false, colorToolpath = false, toolAxes = false, force = false;
  int isoBands = 12;
  GapLimitOption gapLimit;
};

std::pair<int, int> parseSize(const std::string& text) {
  int w = 0, h = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &extra) != 2 || w < 16 || h < 16 || w > 8192 || h > 8192)
    throw InputError(Diagnostic{"", 0, 0, "bad --size '" + text + "': expected WxH, 16 to 8192 pixels each"});
  return {w, h};
}

vis::QualityMapRequest makeRequest(const RenderOptions& o) {
  vis::QualityMapRequest request;
  // A quantity iSurface derives, or else a channel of the dump by its name.
  if (const auto quantity = parseQuantity(o.color)) {
    request.quantity = *quantity;
  } else if (!o.biip.empty() || isBiipFile(o.gcode)) {
    request.channel = o.color;
  } else {
    std::string known;
    for (const QuantityInfo& q : quantityInfos()) known += std::string(known.empty() ? "" : ", ") + q.name;
    throw InputError(Diagnostic{"", 0, 0, "unknown --color '" + o.color + "' (known: " + known +
                                              ", or a channel of the Biip dump given)"});
  }
  const auto view = vis::parseView(o.view);
  if (!view) throw InputError(Diagnostic{"", 0, 0, "unknown --view '" + o.view + "' (iso, top, front, left)"});
  request.view = *view;
  if (o.surface != "commanded" && o.surface != "feedback")
    throw InputError(Diagnostic{"", 0, 0, "unknown --surface '" + o.surface + "' (commanded, feedback)"});
  request.feedbackSurface = o.surface == "feedback";
  request.colorMap = o.colorMap;
  vis::makeLookupTable(vis::resolveColorMap(o.colorMap, false), 0, 1);  // an unknown name fails here, before any work
  if (o.range == "full") {
    request.lowPercent = 0;
    request.highPercent = 100;
  } else if (!o.range.empty()) {
    request.fixedRange = parseRange(o.range);
  } else {
    const ValueRange p = parseRange(o.percentiles);
    if (p.lo < 0 || p.hi > 100)
      throw InputError(Diagnostic{"", 0, 0, "bad --percentiles '" + o.percentiles + "': expected LOW:HIGH within 0:100"});
    request.lowPercent = p.lo;
    request.highPercent = p.hi;
  }
  if (o.highlightLine >= 0) request.highlightLine = static_cast<std::uint32_t>(o.highlightLine);
  request.showToolpath = !o.noToolpath;
  request.colorToolpath = o.colorToolpath;
  request.passWires = !o.noPassWires;
  request.toolAxes = o.toolAxes;  // checked against the samples once they are read (toolAxesAsked)
  if (o.isoBands < 0 || o.isoBands > 100) throw InputError(Diagnostic{"", 0, 0, "--iso-bands must be 0 to 100"});
  request.isoBands = o.isoBands;
  request.gapLimit = o.gapLimit.checked();
  request.pattern = parsePathPattern(o.pattern);
  request.caption = std::filesystem::path(o.biip.empty() ? o.gcode : o.biip).filename().string();
  return request;
}

int runRender(const RenderOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const auto [width, height] = parseSize(o.size);
  vis::QualityMapRequest request = makeRequest(o);
  request.maxVertices = vis::vertexBudgetForPixels(std::size_t(width) * std::size_t(height));
  // A dump alone (no program: a slow tool servo path, a machine trace) is shown as it is.
  const bool dumpOnly = o.biip.empty() && isBiipFile(o.gcode);
  const std::string dump = dumpOnly ? o.gcode : o.biip;
  if (dumpOnly && !parseQuantity(o.color)) request.channel = o.color;
  // A map that shows no feedback and no other channel of the dump is built without copying
  // them: 24 bytes a sample less for a simulated dump.
  TrajectoryChannels channels;
  // A five-axis run's joints and tool axis are channels of the dump.
  channels.extra = !request.channel.empty() || quantityInfo(request.quantity).needsJoints || request.toolAxes;
  channels.feedback = channels.extra || request.feedbackSurface || quantityInfo(request.quantity).needsFeedback;
  const OpenedRun run = openRunOnTerminal({dumpOnly ? "" : o.gcode, dump}, o.machine, o.force, channels);
  const Trajectory& samples = *run.samples;
  ProgressLine building("building the surface");
  vis::QualityMap map = vis::buildQualityMap(samples, run.program.get(), request);
  if (request.toolAxes && !vis::hasToolAxes(samples))
    throw InputError(Diagnostic{samples.source, 0, 0,
                                "--tool-axis: the samples have no tool axis (tool_i tool_j tool_k channels): a five-axis "
                                "machine's simulation writes it (docs/five-axis.md)"});
  for (const std::string& note : surfaceNotes(samples, map, "--pattern or --gap-limit"))
    std::fprintf(stderr, "warning: %s: %s\n", samples.source.c_str(), note.c_str());
  map.style.fontSize = vis::fontSizeForHeight(height);
  building.finish();
  vis::QualityScene scene(map.data, map.style);
  const double renderSeconds = vis::renderSceneToPng(scene, width, height, o.output);
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: %s [%s] %.4g .. %.4g, %zu samples, %zu passes (%s), %zu triangles, render %.2f s, total %.2f s\n",
              o.output.c_str(), map.style.quantityLabel.c_str(), map.style.unit.c_str(),
              map.style.range.lo, map.style.range.hi, samples.size(), map.passes.passes.size(),
              pathPatternName(map.passes.pattern), map.mesh->triangles.size(), renderSeconds, total);
  return kExitOk;
}

}  // namespace

Command renderCommand() {
  return Command{"render", "Render a quality map of a program (simulated, or from its Biip dump) to a PNG, headless",
    [](CLI::App& sub) {
      auto o = std::make_shared<RenderOptions>();
      sub.add_option("gcode", o->gcode, "G-code program (or a Biip dump alone, shown without a program)")->required();
      sub.add_option("biip", o->biip, "Biip dump of the program (default: simulate it)");
      outputOption(sub.add_option("-o,--output", o->output, "PNG file to write"))->required();
      sub.add_option("--color", o->color, "quantity to colour by: speed, accel, jerk, vx.., ax.., jx.., "
                                          "following_error, line, time, feed, speed_inconsistency, "
                                          "accel_inconsistency, deviation")->capture_default_str();
      sub.add_option("--view", o->view, "iso, top, front or left")->capture_default_str();
      sub.add_option("--pattern", o->pattern, "how the map's passes are found: auto, direction-parallel, "
                                              "contour-parallel or no-boundary")->capture_default_str();
      sub.add_option("--size", o->size, "image size WxH in pixels")->capture_default_str();
      sub.add_option("--cmap", o->colorMap, "colour map: auto (rainbow, coolwarm for signed quantities), rainbow, viridis, turbo, coolwarm, grey")->capture_default_str();
      sub.add_option("--range", o->range, "colour range: A:B fixed, or 'full' for the values' extent");
      sub.add_option("--percentiles", o->percentiles, "percentile-clipped range LOW:HIGH (default)")->capture_default_str();
      sub.add_option("--highlight-line", o->highlightLine, "make the samples of this G-code line glow")
          ->check(wholeNumberFrom(1, 4294967295.0));
      sub.add_option("--surface", o->surface, "commanded or feedback")->capture_default_str();
      sub.add_flag("--no-toolpath", o->noToolpath, "leave the programmed tool path out");
      sub.add_flag("--color-toolpath", o->colorToolpath, "draw the sampled cutting path coloured by the quantity");
      sub.add_flag("--no-pass-wires", o->noPassWires, "leave the faint wire along each pass out");
      sub.add_flag("--tool-axis", o->toolAxes, "draw a five-axis run's tool axis along its passes");
      sub.add_option("--iso-bands", o->isoBands, "iso-lines across the colour range (0: none)")
          ->capture_default_str()
          ->check(wholeNumberFrom(0, 1000));
      o->machine.addTo(sub, "machine description for the simulation (JSON)");
      sub.add_flag("--force", o->force, "use the dump even if it does not look like the program's own");
      o->gapLimit.addTo(sub);
      return [o] { return runRender(*o); };
    }};
}

}  // namespace isurface::cli
