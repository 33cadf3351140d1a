// isurface-cli ui-snapshot: the whole application window (panels and 3D view) drawn through
// OSMesa with no X server, for tests and documentation.
#include <cstdio>
#include <cstring>
#include <memory>

#include "command.h"
#include "inputs.h"
#include "output_options.h"
#include "isurface/workflow/run_inputs.h"
#include "isurface/io/atomic_file.h"
#include "isurface/fitting/constant_speed_intervals.h"
#include "isurface/base/diagnostic.h"
#include "isurface/panels/inspector.h"
#include "isurface/panels/headless_ui.h"
#include "isurface/vis/offscreen_render.h"
#include "number_options.h"

namespace isurface::cli {
namespace {

struct SnapshotOptions {
  std::vector<std::string> files;
  std::string output, size = "1600x1000", color = "speed";
  long pickLine = -1, pickSample = -1;
  std::string optimizeLines, optimizeView = "side-by-side";
  std::string machine;
  bool showMachine = false, showWarnings = false, showRegions = false;
};

// The window's RGBA rows, top row first, as a PNG file.
void writePng(const std::vector<unsigned char>& rgbaTopFirst, int width, int height, const std::string& path) {
  std::vector<unsigned char> rgb(static_cast<std::size_t>(width) * height * 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      std::memcpy(&rgb[3 * (static_cast<std::size_t>(height - 1 - y) * width + x)],
                  &rgbaTopFirst[4 * (static_cast<std::size_t>(y) * width + x)], 3);
  writeFileAtomically(path, vis::pngOfRgb(rgb.data(), width, height));
}

int runSnapshot(const SnapshotOptions& o) {
  int width = 0, height = 0;
  char extra = 0;
  if (std::sscanf(o.size.c_str(), "%dx%d%c", &width, &height, &extra) != 2 || width < 320 || height < 240 ||
      width > 8192 || height > 8192)
    throw InputError(Diagnostic{"", 0, 0, "bad --size '" + o.size + "': expected WxH, at least 320x240"});
  if (o.pickLine >= 0 && o.pickSample >= 0)
    throw InputError(Diagnostic{"", 0, 0, "give --pick-line or --pick-sample, not both"});
  int status = kExitOk;
  // Snapshots do not read or change the user's settings: the same inputs give the same picture.
  panels::HeadlessUi ui(width, height, app_model::Settings{});
  panels::Inspector& inspector = ui.inspector();
  if (!o.machine.empty()) inspector.useMachine(loadMachine(o.machine), o.machine);
  ui.frame();  // laid out first: a map is made for the view's size
  for (const RunFiles& run : pairRunFiles(o.files)) {
    std::vector<std::string> files;
    for (const std::string& f : {run.program, run.dump})
      if (!f.empty()) files.push_back(f);
    inspector.open(files);
    inspector.waitUntilIdle();
    ui.frame();
    // As every command: a dump that is not the program's own is refused (the window opens
    // them apart).
    const std::string text = inspector.statusText();
    if (text.rfind("error:", 0) == 0 || text.find("not joined:") != std::string::npos) {
      std::fprintf(stderr, "%s\n", text.c_str());
      status = kExitInputError;
    }
  }
  if (o.color != "speed") {
    inspector.colourBy(o.color);
    inspector.waitUntilIdle();
  }
  if (!o.optimizeLines.empty()) {
    const LineRange range = parseLineRange(o.optimizeLines);
    inspector.optimise(range.first, range.last);
    inspector.waitUntilIdle();
    inspector.showOptimisedDifference(o.optimizeView == "difference");
    if (inspector.statusText().rfind("error:", 0) == 0) {
      std::fprintf(stderr, "%s\n", inspector.statusText().c_str());
      status = kExitInputError;
    }
  }
  if (o.pickLine >= 0 && !inspector.selectLine(static_cast<std::uint32_t>(o.pickLine))) {
    std::fprintf(stderr, "error: line %ld produced no samples\n", o.pickLine);
    status = kExitInputError;
  }
  if (o.pickSample >= 0 && !inspector.selectSample(static_cast<std::size_t>(o.pickSample))) {
    std::fprintf(stderr, "error: sample %ld is out of range\n", o.pickSample);
    status = kExitInputError;
  }
  if (o.showMachine) inspector.showMachineWindow();
  if (o.showWarnings) inspector.showWarningsWindow();
  if (o.showRegions) inspector.showRegionsWindow();
  // ImGui settles its layout over a few frames (window sizes, scrolling to the selection).
  for (int frame = 0; frame < 4; ++frame) ui.frame();
  if (status == kExitOk) writePng(ui.pixels(), width, height, o.output);
  std::printf("%s: %s\n", o.output.c_str(), inspector.statusText().c_str());
  return status;
}

}  // namespace

Command uiSnapshotCommand() {
  return Command{"ui-snapshot", "Draw the whole application window headless (OSMesa) to a PNG", [](CLI::App& sub) {
      auto o = std::make_shared<SnapshotOptions>();
      sub.add_option("files", o->files, "G-code programs and Biip dumps to open");
      outputOption(sub.add_option("-o,--output", o->output, "PNG file to write"))->required();
      sub.add_option("--size", o->size, "window size WxH")->capture_default_str();
      sub.add_option("--color", o->color, "quantity to colour the map by")->capture_default_str();
      sub.add_option("--pick-line", o->pickLine, "select the first sample of this G-code line")
          ->check(wholeNumberFrom(0, 4294967295.0));
      sub.add_option("--pick-sample", o->pickSample, "select this sample (0 is the first)")
          ->check(wholeNumberFrom(0, 1e15));
      CLI::Option* optimize =
          sub.add_option("--optimize-lines", o->optimizeLines, "re-optimise the lines A-B and show both maps");
      sub.add_option("--optimize-view", o->optimizeView,
                     "beside the map: the new map (side-by-side) or the speed difference after - before (difference)")
          ->check(CLI::IsMember({"side-by-side", "difference"}))
          ->needs(optimize)
          ->capture_default_str();
      sub.add_option("--machine", o->machine, "machine description (JSON) programs are simulated with");
      sub.add_flag("--show-machine", o->showMachine, "draw the machine window open");
      sub.add_flag("--show-warnings", o->showWarnings, "draw the warnings window open");
      sub.add_flag("--show-regions", o->showRegions, "draw the worst regions window open");
      return [o] { return runSnapshot(*o); };
    }};
}

}  // namespace isurface::cli
