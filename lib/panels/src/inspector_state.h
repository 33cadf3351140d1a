#pragma once
// What the inspector's panels share: the open documents, the selection, the view settings and
// the background job. Internal to the panels library.
#include <imgui.h>

#include <array>
#include <map>
#include <memory>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "isurface/gcode/program.h"
#include "isurface/machine/machine.h"
#include "isurface/analysis/quality_regions.h"
#include "isurface/analysis/quantities.h"
#include "isurface/analysis/run_comparison.h"
#include "isurface/base/trajectory.h"
#include "isurface/panels/inspector.h"
#include "isurface/panels/scene_view.h"
#include "isurface/app_model/background_job.h"
#include "isurface/app_model/box_selection.h"
#include "isurface/app_model/export_dialog.h"
#include "isurface/app_model/line_times.h"
#include "isurface/app_model/open_dialog.h"
#include "isurface/app_model/optimise_dialog.h"
#include "isurface/app_model/playback.h"
#include "isurface/app_model/locate_window.h"
#include "isurface/app_model/machine_window.h"
#include "isurface/app_model/signal_pyramid.h"
#include "isurface/app_model/text_lines.h"
#include "isurface/map/quality_map.h"
#include "isurface/vis/quality_scene.h"
#include "isurface/workflow/run_inputs.h"
#include "display_units.h"
#include "text_input.h"
#include "view_refinement.h"

namespace isurface::panels {

// The signal curves under the 3D view.
struct Curve {
  std::string label, unit;
  app_model::SignalPyramid values;
  // What the signals panel last drew of it: the envelope and the range of samples [first,
  // last) over `columns`, mm and s units. Reading a derived quantity sample by sample costs
  // milliseconds a curve, too much to spend again on every frame of a camera drag.
  struct Shown {
    std::size_t first = 0, last = 0;
    int columns = 0;
    app_model::Envelope envelope;
    std::pair<float, float> range;
  };
  std::optional<Shown> shown = std::nullopt;
  std::optional<std::pair<float, float>> wholeRun;  // lowest and highest of every sample
};

// One program and its interpolation samples (simulated or read from a dump).
struct Comparison;
struct RunComparisonView;

struct Document {
  Document();
  std::uint64_t serial;  // unique in the process: what its panes' scroll is kept under
  std::string name;
  std::string programPath, dumpPath;
  std::unique_ptr<app_model::TextLines> text;
  std::shared_ptr<const Program> program;
  std::shared_ptr<const Trajectory> samples;
  vis::QualityMap map;
  std::shared_ptr<vis::QualityScene> scene;
  std::vector<Curve> curves;  // speed, acceleration, jerk, then any extra channel
  Machine machine;            // what made the samples: the dump's own, else the simulation's
  bool machineKnown = true;   // false: a dump that names no machine (the default stands in)
  std::vector<std::string> warnings;
  double surfaceShare = 1;  // of the map's vertices, the share on its surface (SurfaceMesh::joinedShare)
  bool showProgram = true, showSurface = true, showToolpath = true, showPoints = false, showToolAxes = false;
  vis::ViewDirection viewDirection = vis::ViewDirection::Iso;  // the direction it was last seen from
  // The servo's positions are loaded when first needed (12 bytes a sample): from here.
  FeedbackSupply feedbackSupply;
  std::shared_ptr<const BiipReader> thinnedDump;  // a thinned run's dump, for its close-ups
  app_model::LineTimes lineTimes;                  // each line's time, for the G-code pane
  // The worst regions of its map (found when first asked for), and the map's mesh they belong to:
  // a map made again (another gap, another pass pattern) finds them again.
  std::shared_ptr<const QualityReport> regions;
  std::shared_ptr<const SurfaceMesh> regionsOfMap;
  // Its re-optimisation or second run shown beside it, kept while another document is shown.
  std::shared_ptr<Comparison> besideOptimised;
  std::shared_ptr<RunComparisonView> besideRun;
  bool feedbackAvailable() const { return samples && (samples->hasFeedback() || feedbackSupply.available()); }
};

struct ViewSettings {
  Quantity quantity = Quantity::Speed;
  std::string channel;  // when not empty: colour by this channel of the samples instead
  std::string colorMap = "auto";
  int rangeMode = 0;  // 0 percentile 1-99 %, 1 full extent, 2 fixed
  float fixedLow = 0, fixedHigh = 3000;
  vis::ViewDirection view = vis::ViewDirection::Iso;
  bool feedbackSurface = false;  // the surface of the encoder positions instead of the commanded
  // mm: passes further apart get no triangles between them (a roughing program's step-over of
  // 4 mm needs more than the 2 mm a finishing program's holes are told by).
  double gapLimit = vis::QualityMapRequest{}.gapLimit;
  PathPattern pattern = PathPattern::Auto;  // how the samples split into passes
};

// A region re-optimised: the new program, its simulation and map, and the comparison.
struct Comparison {
  std::string text;                         // the new program
  std::shared_ptr<const Program> program;
  std::shared_ptr<const Trajectory> samples;
  vis::QualityMap map;
  std::shared_ptr<vis::QualityScene> scene;
  std::uint32_t first = 0, last = 0;        // the region's lines in the old program
  double timeBefore = 0, timeAfter = 0;     // s
  std::string summary;                      // the region's figures before and after
  bool kept = true;                         // false: worse than the old program, not to be saved
  bool saved = false;                       // written to a file since it was made
  bool discardQuestion = false;             // Close asked of a kept program not saved: sure?
  // The new run aligned to the old one pass by pass, and the speed difference (after - before)
  // on the old surface, shown in place of the new map on request.
  RunComparison difference;
  vis::QualityMap differenceMap;
  std::shared_ptr<vis::QualityScene> differenceScene;
  bool showDifference = false;
  // Set when a later re-optimisation was cancelled or failed: this one is still shown, and says
  // it is the earlier result, not what was last asked for.
  std::string supersededBy;
};

// A second run of the active document's program (a Biip dump: another simulation, a machine's
// recording) compared with the document's own: its map beside the document's, or the
// difference map on the document's surface.
struct RunComparisonView {
  std::string path;                         // run B's dump
  std::shared_ptr<const Trajectory> samples;
  std::optional<Curve> speed;               // run B's path speed, over A's on one time axis
  RunComparison result;                     // B against the document's samples (A)
  vis::QualityMap map, differenceMap;
  std::shared_ptr<vis::QualityScene> scene, differenceScene;
  bool showDifference = false;
  std::string summary;
};

// What a background job hands over to the UI thread when it ends: one kind for each job, each
// taken by its own handler (Inspector::State::take). Written by the job, read once it has ended.
struct LoadedDocument {
  std::unique_ptr<Document> document;
  std::size_t replaces = ~std::size_t(0);  // the document it takes the place of (a dump joining its program)
  std::string programAlone;                // a program whose dump was refused, to open by itself next
};
// A new colouring of the document holding `madeFor` (another may be shown by the time it ends).
struct Recolouring {
  std::shared_ptr<const Trajectory> madeFor;
  vis::QualityMap map;
  std::shared_ptr<vis::QualityScene> scene;
  std::string mapRefused;  // why it made no map
};
struct OptimisedRegion {
  std::shared_ptr<const Trajectory> madeFor;
  std::shared_ptr<Comparison> comparison;  // none when it ended in nothing
};
struct ComparedRun {
  std::shared_ptr<const Trajectory> madeFor;
  std::shared_ptr<RunComparisonView> view;
};
struct WrittenReport {
  std::string path, html;  // a report to save (File > Export)
};
// The feedback of a document's samples, and what was waiting for it.
struct LoadedFeedback {
  std::shared_ptr<const Trajectory> madeFor;
  std::optional<FeedbackOffsets> feedback;
  std::function<void()> then;
};
// The worst regions of a document's map, as the report ranks them.
struct FoundRegions {
  std::shared_ptr<const Trajectory> madeFor;
  std::shared_ptr<const SurfaceMesh> ofMap;  // the map's mesh they were found on
  std::shared_ptr<const QualityReport> report;
};
using JobResult =
    std::variant<LoadedDocument, Recolouring, OptimisedRegion, ComparedRun, WrittenReport, LoadedFeedback, FoundRegions>;

// The machine in use came from the settings, remembered for the program named after this.
inline constexpr const char* kRememberedFor = "remembered for ";

// The label of the report's job begins so.
inline constexpr const char* kReportJob = "report on ";

// A file the user asked to save, waiting for "replace?" when it exists.
struct PendingSave {
  std::string path, content, what;
  std::function<void(const std::string& path)> write;  // writes the file itself, in place of `content`
  std::function<void()> ifKept;  // the file is not replaced: back to what asked (a dialog opens again)
};

// The scale bar last drawn: its length in display units, the unit, its pixels.
struct ScaleBar {
  double length = 0;
  std::string unit;
  float pixels = 0;
};

// The pointer over the 3D view: the press of a drag, what the next drag does, the sample it
// rests on, a distance being measured, the scale bar drawn under it.
struct ViewPointer {
  float pressX = 0, pressY = 0;  // where the press began (screen pixels)
  bool pressedInView = false;    // and whether it began in the view
  bool rectangleZoom = false;    // the next drag zooms to its rectangle
  bool boxSelect = false;        // the next drag chooses the region to optimise
  std::optional<std::size_t> hoverSample;  // the sample under the resting pointer
  int hoverRestFrames = 0;                 // for how many frames it has rested
  // Measuring: the next two picks on the surface are the ends of a distance (mm).
  bool measuring = false;
  std::optional<Vec3> measureA, measureB;
  ScaleBar scaleBar;
};

// The dialogs and windows over the layout, each with its own state.
struct Dialogs {
  app_model::OpenDialog open;
  TypeAhead openTyping;     // the Open dialog's path, typed before it has the keyboard
  char openedByKey = 0;     // 'O' when the O key opened it: its own character is not typed
  app_model::LocateWindow locate;
  app_model::ExportDialog exportTo;
  app_model::OptimiseDialog optimise;
  app_model::MachineWindow machine;  // and the machine programs are simulated with
  struct Compare {
    bool opening = false;
    std::string path;  // run B's dump
  } compare;
  std::optional<PendingSave> overwriteQuestion;
  bool helpOpen = false;
  bool warningsOpen = false;  // the warnings window (W)
  bool regionsOpen = false;   // the worst regions window (Ctrl+R)
  // The G-code pane's search field (Ctrl+F): what is looked for, and why nothing was found.
  struct GcodeSearch {
    std::string text, message;
    bool focus = false;  // Ctrl+F: the field takes the keyboard on the next frame
    TypeAhead typing;    // what is typed before it has it
  } gcodeSearch;
};

// The window around the panels: the status line, the menu, the keys taken this frame, where the
// controls were drawn.
struct WindowChrome {
  std::string statusShown;  // the status as the bar shows it: cut with "..." when too wide
  bool menuOpen = false;    // a menu of the bar is open (last frame)
  bool escapeTaken = false; // this frame's Esc was used (a window, measuring): it cancels no job
  bool quit = false;
  std::string lastSaved;    // the file the window wrote last
  // Where the named controls were drawn last (window pixels: x0, y0, x1, y1), for tests and
  // scripts that drive the window.
  std::map<std::string, std::array<float, 4>> controls;
};

// How the panes follow the selection and the view: what each last scrolled or glowed for.
struct PaneFollow {
  std::uint64_t shownGeneration = ~std::uint64_t(0);  // the selection the scene's glow shows
  std::uint64_t glowDeferred = ~std::uint64_t(0);     // the selection whose glow comes next frame
  std::uint64_t gcodeScrolledFor = ~std::uint64_t(0), dataScrolledFor = ~std::uint64_t(0);
  std::size_t gcodeTopLine = 1;  // the first line the G-code pane showed last
  std::size_t curveFirst = 0, curveLast = 0;  // the samples the curves span
  int extraCurve = 0;                         // which extra channel the fourth curve shows
  app_model::Playback playback;               // the selection played along the run
};

// Files opened together, loaded one run after another, and why a dump was not joined to its
// program (said when that program opens).
struct RunQueue {
  std::deque<RunFiles> runs;
  std::string joinNotice, noticeProgram;
};

struct Inspector::State {
  explicit State(GlHooks hooks) : view(hooks), afterView(hooks) {}

  SceneView view;
  ViewRefinement refinement;                    // of `view`'s surface where the camera looks
  SceneView afterView;                          // the re-optimised map beside it
  std::shared_ptr<Comparison> comparison;       // of the active document
  std::shared_ptr<RunComparisonView> runComparison;  // of the active document
  std::vector<std::unique_ptr<Document>> documents;
  std::size_t active = 0;
  RunQueue queue;
  app_model::SelectionModel selection;
  ViewSettings settings;
  app_model::Settings persistent;
  app_model::BackgroundJob job;
  std::shared_ptr<JobResult> pending;  // written by the job, taken on the UI thread
  bool recolourWaiting = false;        // a colouring asked for while a report was being made
  std::string status = "Open a G-code program or a Biip dump (File > Open, or drop it on the window).";
  Dialogs dialogs;
  ViewPointer pointer;
  WindowChrome chrome;
  PaneFollow follow;

  // Opens a program or a dump: a dump joins the active program when that has none yet.
  void openFile(const std::string& path);
  // Opens files named together (a command line, a drop): a dump after its program joins it.
  void openFiles(const std::vector<std::string>& paths);
  // When no job runs: the colouring that waited for a report, else the next run of files waiting.
  void startQueuedLoad();

  Document* activeDocument() { return active < documents.size() ? documents[active].get() : nullptr; }
  // The index of the document holding these samples; documents.size() when none does.
  std::size_t documentOf(const std::shared_ptr<const Trajectory>& samples) const;
  // Shows the document a finished job was made for, if another is shown; false when it is gone.
  bool showDocumentOf(const std::shared_ptr<const Trajectory>& madeFor);
  // How lengths are shown: the user's choice, or as the active program is written.
  DisplayUnits units() const {
    if (persistent.units != "auto") return DisplayUnits{persistent.units == "inch"};
    const bool inch = active < documents.size() && documents[active]->program && documents[active]->program->inch;
    return DisplayUnits{inch};
  }
  vis::QualityMapRequest mapRequest() const;
  void startLoad(const std::string& programPath, const std::string& dumpPath, std::size_t replaces = ~std::size_t(0));
  // A program to be simulated is simulated with the machine remembered for it, if any; a machine
  // remembered for another program gives way to the default.
  void useTheMachineRememberedFor(const std::string& programPath, const std::string& dumpPath);
  void startRecolour();
  // When the active document's feedback is not loaded but can be: starts loading it, runs
  // `then` once it is in (if that document is still the active one) and returns true. False
  // when there is nothing to load: the caller goes on at once.
  bool loadFeedbackFirst(std::function<void()> then);
  // The loaded feedback joins its document's samples (on the UI thread, no job running).
  void attachLoadedFeedback(LoadedFeedback& result);
  // Simulates the active document's program again with `machine`: in its place, or, when it
  // holds a dump (a recording), as a new document beside it.
  void simulateAgain();
  // Opens the machine window with the machine in use; an open one keeps its edits.
  void openMachineWindow() { dialogs.machine.show(); }
  // Esc pressed this frame and not yet used by anything else: it is now.
  bool takeEscape() {
    if (chrome.escapeTaken || !ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) return false;
    return chrome.escapeTaken = true;
  }
  // Closes the active document; the one after it (or before, at the end) becomes active.
  void closeActive();
  // Writes `content` to `path` (atomically), or asks first when the file exists.
  // `ifKept`: what to do when the user keeps the file (the dialog that asked opens again).
  void save(const std::string& path, std::string content, const std::string& what, std::function<void()> ifKept = {});
  // As save(), for a file written by `write` (atomically, as a dump writer does) and not held whole.
  void saveWith(const std::string& path, std::function<void(const std::string&)> write, const std::string& what,
                std::function<void()> ifKept = {});
  // `measuredBox`: where the region's figures are taken (XY, mm); else where the path was re-fitted.
  void startOptimise(std::uint32_t first, std::uint32_t last,
                     std::optional<std::pair<Vec3, Vec3>> measuredBox = std::nullopt);
  // The view beside the main one shows the new map or the difference map.
  void showOptimisedDifference(bool difference);
  void startRunComparison(const std::string& dumpPath);
  // Writes the active document's report (isurface-cli report, beside the window) to `path`.
  void startReport(const std::string& path, int regions);
  bool reportRunning() const { return job.running() && job.label().rfind(kReportJob, 0) == 0; }
  // A job started now would cancel the report being made: `what` is refused, and the status
  // says so (true); false when no report is being made.
  bool refusedDuringReport(const std::string& what) {
    if (!reportRunning()) return false;
    status = "wait for the report being made (or cancel it) to " + what;
    return true;
  }
  // The view beside the main one shows run B's map or the difference map.
  void showRunDifference(bool difference);
  void takeJobResult();
  // The ended job's result, one handler for each kind (`notice`: why a dump was not joined).
  void take(LoadedDocument& result, const std::string& notice);
  void take(Recolouring& result, const std::string& notice);
  void take(OptimisedRegion& result, const std::string& notice);
  void take(ComparedRun& result, const std::string& notice);
  void take(WrittenReport& result, const std::string& notice);
  void take(LoadedFeedback& result, const std::string& notice);
  void take(FoundRegions& result, const std::string& notice);
  // Finds the active document's worst regions in the background, unless they are known for its map.
  void startFindingRegions();
  // A job cancelled or failed: what its result leaves to say or to do.
  void jobEndedWithout(JobResult* result);
  void activate(std::size_t index);
  void syncHighlight();
};

// Draws a 3D view's frame (VTK's colour texture) at the cursor: flipped, as VTK's frames are
// bottom-up, and without blending, since where VTK blended translucent glow its alpha is
// below one and the panel behind must not show through.
void drawViewFrame(unsigned int texture, ImVec2 size);
// Whether Esc, pressed in a dialog while no field is being typed in, closes it (Esc in a field
// first lets the field go, as ImGui does).
inline bool escapeCloses(Inspector::State& s) { return !ImGui::GetIO().WantTextInput && s.takeEscape(); }

// What the Optimise dialog says when a new result would replace a kept one not saved, or nothing.
std::string unsavedResultReplaced(const Inspector::State& s);
// A scale bar at a view's lower right (see panel_view.cpp); what it shows.
ScaleBar scaleBarFor(const DisplayUnits& u, double mmPerPixel, float width);  // its length and pixels
ScaleBar drawScaleBar(const DisplayUnits& u, double mmPerPixel, ImDrawList* draw, ImVec2 origin, ImVec2 size);
// What the 3D view says where no map stands.
std::string emptyViewText(const Inspector::State& s);

// Frames the pointer rests before the value under it is shown.
constexpr int kHoverRestFrames = 5;

// Remembers where the last item drawn stands, under `name` (Inspector::controlRect).
void noteControl(Inspector::State& s, const std::string& name);

// Opens a modal dialog (ImGui::BeginPopupModal), sized to its content but never larger than
// the application's window: on a small one it scrolls instead of running past the edges.
bool beginDialog(const char* title);

// Opens one window of the fixed layout at its place (ImGui::End() closes it).
void beginPanel(const char* name, float x, float y, float w, float h, int extraFlags = 0);

// The panels, each drawing one window of the layout.
void drawMenuAndToolbar(Inspector::State& s, float toolbarTop, float width);
void drawNavigationTree(Inspector::State& s, float x, float y, float w, float h);
void drawColourControls(Inspector::State& s, float x, float y, float w, float h);
void drawSceneView(Inspector::State& s, float x, float y, float w, float h);
// Before the main view is drawn at this size: a close-up where the camera has come to rest,
// taken away when the camera looks beyond it (view_refinement.h).
void refineWhereTheCameraLooks(Inspector::State& s, int viewWidth, int viewHeight);
void drawSignalCurves(Inspector::State& s, float x, float y, float w, float h);
void drawGcodePane(Inspector::State& s, float x, float y, float w, float h);
void drawDataBar(Inspector::State& s, float x, float y, float w, float h);
void drawStatusBar(Inspector::State& s, float y, float width);
void drawDialogs(Inspector::State& s);
// A window of a list over the layout, centred, opaque (the map behind would make it hard to
// read); ImGui::End() closes it.
bool beginListWindow(const char* name, bool* open, float heightShare);
void drawWarningsWindow(Inspector::State& s);
void drawRegionsWindow(Inspector::State& s);
// The share of the document's samples (its run's time) on the lines first..last; none without samples.
std::optional<double> linesTimeShare(const Document& doc, int first, int last);
// The line of the document's program a warning names ("PROGRAM:LINE:..."), if any.
std::optional<std::uint32_t> warningLine(const Document& doc, const std::string& warning);
void drawOptimiseDialog(Inspector::State& s);
void drawComparisonView(Inspector::State& s, float x, float y, float w, float h);
void drawCompareDialog(Inspector::State& s);
void drawOverwriteQuestion(Inspector::State& s);
void drawMachineWindow(Inspector::State& s);
void drawExportDialog(Inspector::State& s);
// What a file kept rather than replaced goes back to: the Export dialog, opened again.
std::function<void()> backToTheDialog(Inspector::State& s);
void drawOpenDialog(Inspector::State& s);
void drawHelpWindow(Inspector::State& s);
// The panel beside the 3D view: its figures on top (begin), then the view beside the main one
// (afterView) with the main view's camera in the rest of it (end). `close`: the panel's Close
// button was pressed; the view is emptied and true returned.
void beginBesidePanel(const char* name, const std::string& summary, float x, float y, float w, float h);
bool endBesidePanel(Inspector::State& s, bool close);
// Radio buttons over a view beside the main one: "Side by side" or the difference; returns the
// choice when it changed.
std::optional<bool> drawDifferenceToggle(bool showingDifference, const char* differenceLabel);
// A difference map on run A's surface, seen like the map the request `like` is for, and its scene.
void buildDifferenceView(vis::QualityMapRequest request, const vis::QualityMapRequest& like, const Trajectory& a,
                         const Program* program, vis::QualityMap& map, std::shared_ptr<vis::QualityScene>& scene);
void drawRunComparisonView(Inspector::State& s, float x, float y, float w, float h);

// A curve of a quantity of the samples, read from them as a view needs it.
Curve curveOf(Quantity q, std::shared_ptr<const Trajectory> samples);
// Loads a document on the job's thread.
// `machine`: what a program without a dump is simulated with. `unitsOfProgram`: the map's
// values in inches when the program is written in inches (else as `request` says).
std::unique_ptr<Document> loadDocument(const std::string& programPath, const std::string& dumpPath,
                                       const vis::QualityMapRequest& request, const Machine& machine,
                                       bool unitsOfProgram, app_model::JobControl& control);
// The first line of a map's caption: the machine its samples were made with.
std::string machineCaption(const Machine& machine, bool known);
// "sample i", and for thinned samples the dump's record it is: "sample i (record i*k)".
inline std::string sampleName(const Trajectory& samples, std::size_t i) {
  std::string name = "sample " + std::to_string(i);
  if (samples.thinning > 1) name += " (record " + std::to_string(i * samples.thinning) + ")";
  return name;
}

// The first line of a document's map captions: its machine, and its thinning if it is thinned.
std::string mapCaption(const Document& doc);
// The document's warnings of its surface (passes not joined, a surface on little of the path)
// as its map now has it: a map made again with another gap or pattern may have other ones.
void noteSurface(Document& doc);

}  // namespace isurface::panels
