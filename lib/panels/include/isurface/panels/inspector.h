#pragma once
// The inspection workflow of the paper's iSurface in Dear ImGui panels: a menu and toolbar, a
// navigation tree of open programs and their interpolation samples, the G-code text, the data
// bar of samples, the 3D quality map and the signal curves, all following one selection.
// The same object draws the interactive window and the headless UI snapshots.
#include <array>
#include <cstddef>
#include <optional>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "isurface/analysis/run_comparison.h"
#include "isurface/machine/machine.h"
#include "isurface/panels/scene_view.h"
#include "isurface/app_model/selection.h"
#include "isurface/app_model/settings.h"

namespace isurface::panels {

struct Document;

class Inspector {
 public:
  Inspector(GlHooks hooks, app_model::Settings settings);
  ~Inspector();

  // Opens a G-code program or a Biip dump (told apart by its first bytes). A dump joins the
  // open program it belongs to; a program alone is simulated. The work runs in the background.
  void open(const std::string& path);
  // Opens files named together (a command line, a drop), one after another: a dump right after
  // a program joins it (refused, with the reason in the status, when it is not that program's).
  void open(const std::vector<std::string>& paths);

  // Draws the whole window; call between ImGui::NewFrame() and ImGui::Render().
  void frame();

  bool busy() const;
  // The view waits to refine the surface where the camera rests, or is refining it: frames
  // are wanted though no input comes.
  bool refining() const;
  std::size_t documentCount() const;
  // Shows the open document `index` (0 the first opened), as a click on its name does.
  void showDocument(std::size_t index);
  // Lets background work finish and takes over its results (for snapshots and tests).
  void waitUntilIdle();

  bool selectSample(std::size_t sample);  // false when out of range
  bool selectLine(std::uint32_t line);
  void colourBy(const std::string& quantityName);  // "speed", "accel", ...
  // Re-optimises the G1 moves of the lines in the background; the new map then stands beside
  // the old one.
  void optimise(std::uint32_t firstLine, std::uint32_t lastLine);
  // Beside the document's map: the re-optimised map (false) or the speed difference, after
  // minus before, on the document's surface (true).
  void showOptimisedDifference(bool difference);
  // The re-optimised run aligned to the document's pass by pass; nullptr when there is none.
  const RunComparison* optimisedDifference() const;
  // Compares a second run of the active document's program (a Biip dump) with the document's
  // samples in the background; its map then stands beside the document's.
  void compareWith(const std::string& dumpPath);
  // Beside the document's map: run B's map (false) or the difference map (true).
  void showRunDifference(bool difference);
  // The comparison of the active document with a second run; nullptr when there is none.
  const RunComparison* runComparison() const;
  // The machine programs are simulated with from now on (`source`: its file, for the window).
  void useMachine(const Machine& machine, const std::string& source);
  const Machine& machine() const;
  // The machine that made the active document's samples; nullptr without samples.
  const Machine* activeMachine() const;
  // Opens the machine window (limits, servo, load, save, simulate again).
  void showMachineWindow();
  // Opens the warnings window (every warning of the open documents).
  void showWarningsWindow();
  // Opens the worst regions window; they are found in the background (waitUntilIdle).
  void showRegionsWindow();
  // Simulates the active document's program again with machine().
  void simulateAgain();

  const app_model::Selection& selection() const;
  std::string statusText() const;
  // Where a named control of the window was drawn last, in window pixels (x0, y0, x1, y1):
  // "view", "gcode", "machine.simulate", ... (see describe()).
  std::optional<std::array<float, 4>> controlRect(const std::string& name) const;
  // The window's state as JSON: documents, selection, machine, measure, open windows, the last
  // file saved, the status line and the named controls' places. What a script driving the
  // window checks.
  std::string describe() const;

  app_model::Settings& settings();
  bool quitRequested() const;

  struct State;  // shared by the panels' own sources

 private:
  std::unique_ptr<State> state_;
};

}  // namespace isurface::panels
