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
#include <vector>

#include "isurface/gcode/program.h"
#include "isurface/machine/machine.h"
#include "isurface/analysis/quantities.h"
#include "isurface/analysis/run_comparison.h"
#include "isurface/base/trajectory.h"
#include "isurface/panels/inspector.h"
#include "isurface/panels/scene_view.h"
#include "isurface/app_model/background_job.h"
#include "isurface/app_model/box_selection.h"
#include "isurface/app_model/folder_listing.h"
#include "isurface/app_model/signal_pyramid.h"
#include "isurface/app_model/text_lines.h"
#include "isurface/vis/quality_map.h"
#include "isurface/workflow/run_inputs.h"
#include "display_units.h"
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
};

// One program and its interpolation samples (simulated or read from a dump).
struct Document {
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
  bool showProgram = true, showSurface = true, showToolpath = true, showPoints = false;
  // The servo's positions are loaded when first needed (12 bytes a sample): from here.
  FeedbackSupply feedbackSupply;
  std::shared_ptr<const BiipReader> thinnedDump;  // a thinned run's dump, for its close-ups
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
  RunComparison result;                     // B against the document's samples (A)
  vis::QualityMap map, differenceMap;
  std::shared_ptr<vis::QualityScene> scene, differenceScene;
  bool showDifference = false;
  std::string summary;
};

// What a background job hands over to the UI thread when it ends.
struct JobResult {
  std::shared_ptr<Comparison> comparison;   // a re-optimised region
  bool optimisation = false;                 // the job re-optimises a region (even if it ends in nothing)
  std::shared_ptr<RunComparisonView> runComparison;  // a second run compared
  std::unique_ptr<Document> document;        // a newly loaded document
  std::size_t replaces = ~std::size_t(0);    // the document it takes the place of (a dump joining its program)
  std::string programAlone;                  // a program whose dump was refused, to open by itself next
  std::shared_ptr<vis::QualityScene> scene;  // or a new colouring of a document
  // The samples of the document a colouring, a re-optimisation or a comparison was made for:
  // another may be shown by the time it ends.
  std::shared_ptr<const Trajectory> madeFor;
  vis::QualityMap map;
  std::string mapRefused;                    // why that colouring made no map
  std::string reportPath, report;            // or a report to save (File > Export)
  // or the feedback of a document's samples, and what was waiting for it
  std::optional<FeedbackOffsets> feedback;
  std::shared_ptr<const Trajectory> feedbackFor;
  std::function<void()> afterFeedback;
};

// The label of the report's job begins so.
inline constexpr const char* kReportJob = "report on ";

// A file the user asked to save, waiting for "replace?" when it exists.
struct PendingSave {
  std::string path, content, what;
};

struct Inspector::State {
  explicit State(GlHooks hooks) : view(hooks), afterView(hooks) {}

  SceneView view;
  ViewRefinement refinement;                    // of `view`'s surface where the camera looks
  SceneView afterView;                          // the re-optimised map beside it
  std::shared_ptr<Comparison> comparison;       // of the active document
  std::shared_ptr<RunComparisonView> runComparison;  // of the active document
  bool compareDialog = false;
  char comparePath[1024] = "";
  bool optimiseDialog = false, optimiseDialogOpen = false;
  int optimiseFirst = 1, optimiseLast = 1;
  int optimiseObjective = 0;
  std::string optimiseProblem;  // why the open dialog cannot optimise, if it cannot
  std::string optimiseNotice;   // why the region asked for in the dialog was not chosen
  // The rectangle last dragged over the view to choose the region, and what it holds; shown
  // while the dialog is open, and the region's figures are taken inside it.
  std::optional<app_model::BoxSelection> optimiseBox;
  app_model::ScreenRectangle optimiseBoxOnView;
  std::string optimiseProgram;  // the program whose lines and box the dialog holds
  char savePath[1024] = "";
  // The path suggested for the last result and its program: a path typed over the suggestion
  // stays for the next result of the same program.
  std::string suggestedSavePath, savePathProgram;
  std::optional<PendingSave> overwriteQuestion;
  // Where the named controls were drawn last (window pixels: x0, y0, x1, y1), for tests and
  // scripts that drive the window.
  std::map<std::string, std::array<float, 4>> controls;
  std::string lastSaved;  // the file the window wrote last
  std::string statusShown;  // the status as the bar shows it: cut with "..." when too wide
  // Measuring: the next two picks on the surface are the ends of a distance (mm).
  bool measuring = false;
  std::optional<Vec3> measureA, measureB;
  bool helpOpen = false;
  bool escapeTaken = false;  // this frame's Esc was used (a window, measuring): it cancels no job
  // The scale bar last drawn: its length in display units, the unit, its pixels.
  struct ScaleBar {
    double length = 0;
    std::string unit;
    float pixels = 0;
  } scaleBar;
  // The export dialog: what (0 view PNG, 1 map figures JSON, 2 samples of lines CSV, 3 report
  // HTML), where.
  bool exportDialog = false;
  int exportKind = 0, exportWidth = 1920, exportHeight = 1080, exportFirst = 1, exportLast = 1;
  int exportRegions = 5;
  char exportPath[1024] = "";
  // The sample under the resting pointer, and for how many frames the pointer has rested.
  std::optional<std::size_t> hoverSample;
  int hoverRestFrames = 0;
  // The machine programs are simulated with, where it came from, and the machine window's copy
  // being edited (applied by its "Simulate with this machine").
  Machine machine = defaultMachine();
  std::string machineSource = "built-in default";
  Machine machineEdit = defaultMachine();
  bool machineOpen = false, machineAppearing = false;
  char machineLoadPath[1024] = "", machineSavePath[1024] = "";
  std::string machineMessage;  // why the last request of the machine window failed
  std::vector<std::unique_ptr<Document>> documents;
  std::deque<RunFiles> queuedRuns;  // files opened together, loaded one run after another
  std::string joinNotice;           // why a dump was not joined, shown when its program opens
  std::string noticeProgram;        // that program
  std::size_t active = 0;
  app_model::SelectionModel selection;
  std::uint64_t shownGeneration = ~std::uint64_t(0);  // the selection the scene's glow shows
  std::uint64_t glowDeferred = ~std::uint64_t(0);     // the selection whose glow comes next frame
  ViewSettings settings;
  app_model::Settings persistent;
  app_model::BackgroundJob job;
  std::shared_ptr<JobResult> pending;  // written by the job, taken on the UI thread
  std::string status = "Open a G-code program or a Biip dump (File > Open, or drop it on the window).";
  bool quit = false;
  bool openDialog = false, locateDialog = false;
  char openPath[1024] = "";
  app_model::FolderListing browse;  // the Open dialog's folder
  int browseFilter = 0, browseFilterListed = -1;  // an app_model::FileFilter
  std::size_t curveFirst = 0, curveLast = 0;  // the samples the curves span
  bool rectangleZoom = false;
  bool boxSelect = false;  // the next drag in the view chooses the region to optimise
  // Mouse in the 3D view: where the press began (screen pixels) and whether it began there.
  float pressX = 0, pressY = 0;
  bool pressedInView = false;
  int extraCurve = 0;
  int locateSample = 0, locateLine = 1;  // the locate window's fields
  bool locateOpen = false;
  bool warningsOpen = false;  // the warnings window (W)
  bool menuOpen = false;      // a menu of the bar is open (last frame)
  std::string locateMessage;  // why the last request went nowhere  // which extra channel the fourth curve shows
  std::uint64_t gcodeScrolledFor = ~std::uint64_t(0), dataScrolledFor = ~std::uint64_t(0);
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
  bool showDocumentOf(const JobResult& result);
  // How lengths are shown: the user's choice, or as the active program is written.
  DisplayUnits units() const {
    if (persistent.units != "auto") return DisplayUnits{persistent.units == "inch"};
    const bool inch = active < documents.size() && documents[active]->program && documents[active]->program->inch;
    return DisplayUnits{inch};
  }
  vis::QualityMapRequest mapRequest() const;
  void startLoad(const std::string& programPath, const std::string& dumpPath, std::size_t replaces = ~std::size_t(0));
  void startRecolour();
  // When the active document's feedback is not loaded but can be: starts loading it, runs
  // `then` once it is in (if that document is still the active one) and returns true. False
  // when there is nothing to load: the caller goes on at once.
  bool loadFeedbackFirst(std::function<void()> then);
  // The loaded feedback joins its document's samples (on the UI thread, no job running).
  void attachLoadedFeedback(JobResult& result);
  // Simulates the active document's program again with `machine`: in its place, or, when it
  // holds a dump (a recording), as a new document beside it.
  void simulateAgain();
  // Opens the machine window with the machine in use; an open one keeps its edits.
  void openMachineWindow() {
    if (!machineOpen) machineOpen = machineAppearing = true;
  }
  // Esc pressed this frame and not yet used by anything else: it is now.
  bool takeEscape() {
    if (escapeTaken || !ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) return false;
    return escapeTaken = true;
  }
  // Closes the active document; the one after it (or before, at the end) becomes active.
  void closeActive();
  // Writes `content` to `path` (atomically), or asks first when the file exists.
  void save(const std::string& path, std::string content, const std::string& what);
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
  bool recolourWaiting = false;  // a colouring asked for while a report was being made
  // The view beside the main one shows run B's map or the difference map.
  void showRunDifference(bool difference);
  void takeJobResult();
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

// Why the Optimise dialog's lines cannot be optimised as typed, or nothing when they can.
inline std::string optimiseRangeProblem(int first, int last) {
  if (first < 1) return "the first line is line 1 or after";
  if (last < first) return "the last line is before the first: no lines to optimise";
  return {};
}
// What the Optimise dialog says when a new result would replace a kept one not saved, or nothing.
std::string unsavedResultReplaced(const Inspector::State& s);
// The Optimise dialog's lines and box belong to one program: another program active, they are
// forgotten (a range of its own lines would mean other moves).
void forgetTheRegionOfAnotherProgram(Inspector::State& s);
// A scale bar at a view's lower right (see panel_view.cpp); what it shows.
Inspector::State::ScaleBar scaleBarFor(const DisplayUnits& u, double mmPerPixel, float width);  // its length and pixels
Inspector::State::ScaleBar drawScaleBar(const DisplayUnits& u, double mmPerPixel, ImDrawList* draw, ImVec2 origin, ImVec2 size);
// What the 3D view says where no map stands.
std::string emptyViewText(const Inspector::State& s);

// Frames the pointer rests before the value under it is shown.
constexpr int kHoverRestFrames = 5;

// Remembers where the last item drawn stands, under `name` (Inspector::controlRect).
void noteControl(Inspector::State& s, const std::string& name);

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
void drawWarningsWindow(Inspector::State& s);
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
// The document's warning of passes not joined as they fold over each other, as its map now has
// them (a map made again with another gap may fold elsewhere).
void noteFoldedPasses(Document& doc);

}  // namespace isurface::panels
