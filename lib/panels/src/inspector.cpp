#include "isurface/panels/inspector.h"

#include <filesystem>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <thread>
#include <utility>

#include "inspector_state.h"
#include "isurface/vis/color_map.h"
#include "isurface/panels/ui_look.h"
#include "isurface/vis/quality_scene.h"
#include "isurface/workflow/run_inputs.h"

namespace isurface::panels {

namespace {

}  // namespace

vis::QualityMapRequest Inspector::State::mapRequest() const {
  vis::QualityMapRequest r;
  r.quantity = settings.quantity;
  r.channel = settings.channel;
  r.colorMap = settings.colorMap;
  r.view = settings.view;
  r.feedbackSurface = settings.feedbackSurface;
  r.gapLimit = settings.gapLimit;
  r.pattern = settings.pattern;
  r.inch = units().inch;
  if (settings.rangeMode == 1) r.lowPercent = 0, r.highPercent = 100;
  if (settings.rangeMode == 2) r.fixedRange = ValueRange{settings.fixedLow, std::max(settings.fixedHigh, settings.fixedLow)};
  // A coarse surface keeps rotation interactive on large maps; the full one shows at rest.
  // llvmpipe spends about 0.5 ms a thousand triangles on this machine: 30,000 vertices (60,000
  // triangles, thinned along and across the passes) leave a drag frame under 67 ms.
  r.coarseVertices = 30'000;
  r.toolAxes = true;  // a five-axis run's, shown when asked for (Document::showToolAxes)
  // Half a vertex a pixel of the view, as it was last drawn; closer views are refined.
  if (refinement.vertexBudget > 0) r.maxVertices = refinement.vertexBudget;
  return r;
}

void Inspector::State::startLoad(const std::string& programPath, const std::string& dumpPath, std::size_t replaces) {
  vis::QualityMapRequest request = mapRequest();
  request.pickable = true;
  // The pass pattern and the view chosen are the active program's: another program's passes are
  // found anew, and it is first seen from the default direction.
  if (const Document* doc = activeDocument(); !doc || programPath.empty() || doc->programPath != programPath) {
    request.pattern = PathPattern::Auto;
    request.view = vis::QualityMapRequest{}.view;
  }
  // A new document's own units: as it is written, unless the user chose.
  request.inch = persistent.units == "inch";
  const bool unitsOfProgram = persistent.units == "auto";
  useTheMachineRememberedFor(programPath, dumpPath);
  auto result = std::make_shared<JobResult>(LoadedDocument{nullptr, replaces, {}});
  pending = result;
  const std::string label = "loading " + (programPath.empty() ? dumpPath : programPath);
  const bool programOpen = replaces < documents.size();
  job.start(label, [result, programPath, dumpPath, request, programOpen, unitsOfProgram,
                    machine = dialogs.machine.inUse](app_model::JobControl& control) {
    LoadedDocument& loaded = std::get<LoadedDocument>(*result);
    try {
      loaded.document = loadDocument(programPath, dumpPath, request, machine, unitsOfProgram, control);
    } catch (const DumpMismatchError& e) {
      // Not joined: the program stays (or opens) by itself, and the dump opens as a document
      // of its own, saying why; a dump that cannot stand alone says both.
      const std::string notJoined = std::string("not joined: ") + e.what();
      if (!programOpen) loaded.programAlone = programPath;
      loaded.replaces = ~std::size_t(0);
      try {
        loaded.document = loadDocument("", dumpPath, request, machine, unitsOfProgram, control);
      } catch (const InputError& alone) {
        throw InputError(Diagnostic{"", 0, 0, notJoined + "; by itself: " + alone.what()});
      }
      loaded.document->warnings.insert(loaded.document->warnings.begin(), notJoined);
    }
  });
  status = label;
}

void Inspector::State::useTheMachineRememberedFor(const std::string& programPath, const std::string& dumpPath) {
  if (programPath.empty() || !dumpPath.empty()) return;  // a dump has its own machine
  const std::string name = std::filesystem::path(programPath).filename().string();
  if (const std::string remembered = persistent.machineOf(programPath); !remembered.empty()) {
    if (remembered == machineDescriptionJson(dialogs.machine.inUse)) return;  // in use already ("edited")
    try {
      dialogs.machine.use(parseMachine(remembered, "settings"), kRememberedFor + name);
      return;
    } catch (const InputError&) {
      persistent.rememberMachine(programPath, "");  // no longer a machine: forgotten
    }
  }
  // Another program's machine, remembered or applied to it in the window, is that program's.
  const app_model::MachineWindow& m = dialogs.machine;
  if (m.source.rfind(kRememberedFor, 0) == 0 || (!m.appliedFor.empty() && m.appliedFor != programPath))
    dialogs.machine.use(defaultMachine(), "built-in default");
}

void Inspector::State::startRecolour() {
  Document* doc = activeDocument();
  if (!doc || !doc->samples) return;
  if (reportRunning()) {  // starting a job would cancel the report: the colouring comes after it
    recolourWaiting = true;
    status = "the new colouring comes once the report being made is written";
    return;
  }
  if (needsFeedback(mapRequest()) && loadFeedbackFirst([this] { startRecolour(); })) return;
  vis::QualityMapRequest request = mapRequest();
  request.pickable = true;
  request.caption = mapCaption(*doc);
  auto result = std::make_shared<JobResult>(Recolouring{doc->samples, {}, nullptr, {}});
  pending = result;
  std::shared_ptr<const Trajectory> samples = doc->samples;
  std::shared_ptr<const Program> program = doc->program;
  job.start("colouring by " + std::string(quantityInfo(request.quantity).label),
            [result, samples, program, request](app_model::JobControl& control) {
              Recolouring& colouring = std::get<Recolouring>(*result);
              control.progress(0.1);
              try {
                colouring.map = vis::buildQualityMap(*samples, program.get(), request);
              } catch (const InputError& e) {
                colouring.mapRefused = e.what();
                throw;
              }
              control.progress(0.7);
              colouring.scene = std::make_shared<vis::QualityScene>(colouring.map.data, colouring.map.style);
              control.progress(1.0);
            });
}

void Inspector::State::simulateAgain() {
  Document* doc = activeDocument();
  if (!doc || doc->programPath.empty()) {
    status = "Simulate needs a G-code program: open one first";
    return;
  }
  if (refusedDuringReport("simulate again")) return;
  // A document with a dump (a machine's recording, or a run simulated elsewhere) keeps it: the
  // simulation opens beside it, as a document of its own.
  const bool keepsDump = !doc->dumpPath.empty();
  startLoad(doc->programPath, "", keepsDump ? ~std::size_t(0) : active);
  status = "simulating " + doc->name + " with " + dialogs.machine.inUse.name + (keepsDump ? ", beside its dump" : "");
}

void Inspector::State::closeActive() {
  if (active >= documents.size()) return;
  if (job.running() || pending) {
    status = "wait until the running job ends (or cancel it) to close " + documents[active]->name;
    return;
  }
  const std::string name = documents[active]->name;
  documents.erase(documents.begin() + static_cast<std::ptrdiff_t>(active));
  pointer.measureA.reset();
  pointer.measureB.reset();
  pointer.hoverSample.reset();
  activate(std::min(active, documents.empty() ? 0 : documents.size() - 1));
  status = "closed " + name;
}

void Inspector::State::takeJobResult() {
  if (!job.takeFinished()) return;
  std::shared_ptr<JobResult> result = std::move(pending);
  // The reason a dump was not joined goes with the program that opens by itself next, and
  // with nothing else.
  const std::string notice = std::exchange(queue.joinNotice, std::string());
  if (job.wasCancelled() || !job.error().empty()) return jobEndedWithout(result.get());
  if (result) std::visit([&](auto& r) { take(r, notice); }, *result);
}

void Inspector::State::jobEndedWithout(JobResult* result) {
  if (result && std::holds_alternative<OptimisedRegion>(*result) && comparison)
    comparison->supersededBy = job.label() + (job.wasCancelled() ? " was cancelled" : " failed");
  if (job.wasCancelled()) {
    status = job.label() + ": cancelled";
    return;
  }
  status = "error: " + job.error();
  // A map made again with a new gap between passes failed: the gap is the map's that stays.
  if (const Document* doc = activeDocument(); doc && doc->scene) settings.gapLimit = doc->map.request.gapLimit;
  if (!result) return;
  if (const auto* loaded = std::get_if<LoadedDocument>(result); loaded && !loaded->programAlone.empty()) {
    queue.runs.push_front(RunFiles{loaded->programAlone, ""});
    queue.joinNotice = job.error();
    queue.noticeProgram = loaded->programAlone;
  }
  // A document still without a map: the view says why it has none now, at the gap typed.
  if (const auto* colouring = std::get_if<Recolouring>(result); colouring && !colouring->mapRefused.empty()) {
    const std::size_t k = documentOf(colouring->madeFor);
    if (k == documents.size() || documents[k]->scene) return;
    auto& w = documents[k]->warnings;
    w.erase(std::remove_if(w.begin(), w.end(), [](const std::string& s) { return s.rfind("no map: ", 0) == 0; }), w.end());
    w.push_back("no map: " + colouring->mapRefused);
  }
}

void Inspector::State::take(LoadedFeedback& result, const std::string&) { attachLoadedFeedback(result); }

void Inspector::State::take(WrittenReport& result, const std::string&) {
  save(result.path, std::move(result.html), "report", backToTheDialog(*this));
}

void Inspector::State::take(ComparedRun& result, const std::string&) {
  if (!showDocumentOf(result.madeFor)) return;
  comparison.reset();
  runComparison = result.view;
  showRunDifference(runComparison->showDifference);
  view.refit();  // the main view is half as wide now
  status = runComparison->summary;
}

void Inspector::State::take(OptimisedRegion& result, const std::string&) {
  if (!result.comparison || !showDocumentOf(result.madeFor)) return;
  runComparison.reset();
  comparison = result.comparison;
  showOptimisedDifference(comparison->showDifference);
  view.refit();
  if (Document* doc = activeDocument()) {
    // Where the user saved last, not the program's own folder (read-only, or someone else's).
    const std::string folder =
        chrome.lastSaved.empty() ? std::string() : std::filesystem::path(chrome.lastSaved).parent_path().string();
    dialogs.optimise.offerSavePath(doc->programPath, folder);
  }
  status = comparison->summary;
}

void Inspector::State::take(LoadedDocument& result, const std::string& notice) {
  if (!result.programAlone.empty()) queue.runs.push_front(RunFiles{result.programAlone, ""});
  Document& doc = *result.document;
  // The colouring gave way (see loadDocument): the controls say what the map shows.
  if (doc.samples && !doc.samples->hasFeedback() && settings.channel.empty() &&
      quantityInfo(settings.quantity).needsFeedback)
    settings.quantity = Quantity::Speed;
  status = doc.name + ": " + (doc.samples ? std::to_string(doc.samples->size()) + " samples" : "no samples");
  for (const std::string& w : doc.warnings) status += " | " + w;
  if (!notice.empty() && doc.dumpPath.empty() && doc.programPath == queue.noticeProgram) status += " | " + notice;
  if (!result.programAlone.empty()) {
    queue.joinNotice = doc.warnings.front();
    queue.noticeProgram = result.programAlone;
  }
  if (result.replaces < documents.size()) {
    // The program simulated again keeps the line the user was looking at.
    const bool shown = result.replaces == active;
    const std::optional<std::uint32_t> line = shown ? selection.current().line : std::nullopt;
    documents[result.replaces] = std::move(result.document);
    activate(result.replaces);
    if (line) selection.selectLine(*line);
  } else {
    documents.push_back(std::move(result.document));
    activate(documents.size() - 1);
  }
  view.refit();  // a new map fills the view it is shown in
}

void Inspector::State::take(Recolouring& result, const std::string&) {
  const std::size_t k = documentOf(result.madeFor);
  if (k == documents.size() || !result.scene) return;
  Document* doc = documents[k].get();
  const bool firstMap = !doc->scene;
  doc->map = std::move(result.map);
  doc->scene = result.scene;
  noteSurface(*doc);
  doc->scene->setVisibility(doc->showSurface, doc->showToolpath, doc->showPoints, doc->showToolAxes);
  status = doc->name + ": coloured by " +
           (settings.channel.empty() ? std::string(quantityInfo(settings.quantity).label) : settings.channel);
  if (k != active) return;  // shown when that document is chosen again
  view.setScene(doc->scene, doc->map.rayIndex);
  if (firstMap) view.refit();  // a map made after the gap between passes was raised
  follow.shownGeneration = ~std::uint64_t(0);
}

std::size_t Inspector::State::documentOf(const std::shared_ptr<const Trajectory>& samples) const {
  for (std::size_t k = 0; k < documents.size(); ++k)
    if (samples && documents[k]->samples == samples) return k;
  return documents.size();
}

bool Inspector::State::showDocumentOf(const std::shared_ptr<const Trajectory>& madeFor) {
  const std::size_t k = documentOf(madeFor);
  if (k == documents.size()) {
    status = "the result was made for a document since closed";
    return false;
  }
  if (k != active) activate(k);
  return true;
}

void Inspector::State::activate(std::size_t index) {
  // What stands beside the document left goes with it, and comes back when it is shown again.
  if (Document* leaving = activeDocument(); leaving && index != active) {
    leaving->besideOptimised = comparison;
    leaving->besideRun = runComparison;
  }
  active = index;
  comparison.reset();
  runComparison.reset();
  afterView.setScene(nullptr);
  Document* doc = activeDocument();
  if (doc && doc->besideOptimised) {
    comparison = std::move(doc->besideOptimised);
    showOptimisedDifference(comparison->showDifference);
  } else if (doc && doc->besideRun) {
    runComparison = std::move(doc->besideRun);
    showRunDifference(runComparison->showDifference);
  }
  if (doc) settings.view = doc->viewDirection;  // Reset (R) and its maps made again look from there
  selection.setTrajectory(doc ? doc->samples.get() : nullptr);
  selection.clear();
  view.setScene(doc ? doc->scene : nullptr, doc ? doc->map.rayIndex : nullptr);
  if (doc && doc->scene) doc->scene->setVisibility(doc->showSurface, doc->showToolpath, doc->showPoints, doc->showToolAxes);
  // The Colour panel shows what the map shown is coloured by, on which surface, at which gap:
  // a colouring made again, or a re-optimised map beside it, is made alike.
  if (doc && doc->scene) {
    settings.quantity = doc->map.request.quantity;
    settings.channel = doc->map.request.channel;
    settings.feedbackSurface = doc->map.request.feedbackSurface;
    settings.gapLimit = doc->map.request.gapLimit;
    settings.pattern = doc->map.request.pattern;
    // And its range: fixed, full or 1-99 %, as that map was made.
    if (const auto& fixed = doc->map.request.fixedRange) {
      settings.rangeMode = 2;
      settings.fixedLow = static_cast<float>(fixed->lo);
      settings.fixedHigh = static_cast<float>(fixed->hi);
    } else {
      settings.rangeMode = doc->map.request.lowPercent == 0 && doc->map.request.highPercent == 100 ? 1 : 0;
    }
  }
  view.invalidate();
  follow.curveFirst = 0;
  follow.curveLast = doc && doc->samples ? doc->samples->size() : 0;
  follow.shownGeneration = ~std::uint64_t(0);
}

void Inspector::State::syncHighlight() {
  Document* doc = activeDocument();
  const app_model::Selection& sel = selection.current();
  if (!doc || !doc->scene || !doc->samples || sel.generation == follow.shownGeneration) return;
  // The frame after a selection shows it in every panel at once (a marker over the view);
  // the glow of its line in the 3D scene, which costs a full render, follows a frame later.
  // While the run plays the selection moves every frame: the tool follows it at once, or it
  // would stand still until Pause.
  if (follow.glowDeferred != sel.generation && !follow.playback.playing) {
    follow.glowDeferred = sel.generation;
    return;
  }
  follow.shownGeneration = sel.generation;
  std::vector<Vec3> line, sample;
  const Trajectory& t = *doc->samples;
  if (sel.line) {
    t.line.forEachRun([&](std::uint32_t l, std::size_t begin, std::size_t end) {
      if (l != *sel.line) return;
      for (std::size_t i = begin; i < end; ++i)
        if (t.commanded(i).allFinite()) line.push_back(t.commanded(i));
    });
  }
  if (sel.sample && *sel.sample < t.size()) sample.push_back(t.commanded(*sel.sample));
  doc->scene->setHighlight(line, sample);
  // The tool stands where the selected sample puts it: picked, located or played to.
  // On a five-axis run it stands along the tool axis there.
  Vec3 axis = Vec3::UnitZ();
  const std::vector<double>* i = t.extraChannel("tool_i");
  const std::vector<double>* j = t.extraChannel("tool_j");
  const std::vector<double>* k = t.extraChannel("tool_k");
  if (sel.sample && *sel.sample < t.size() && i && j && k) {
    const Vec3 along((*i)[*sel.sample], (*j)[*sel.sample], (*k)[*sel.sample]);
    if (along.allFinite() && along.norm() > 1e-9) axis = along;
  }
  doc->scene->setTool(sample.empty() ? std::nullopt : std::optional<Vec3>(sample.front()), axis);
  view.invalidate();
}

Inspector::Inspector(GlHooks hooks, app_model::Settings settings) : state_(std::make_unique<State>(std::move(hooks))) {
  state_->persistent = std::move(settings);
  if (ImGui::GetCurrentContext()) applyTheme(state_->persistent.theme, state_->persistent.uiScale);
  // A remembered colouring that this version does not know is a note, never a blocked file.
  State& s = *state_;
  std::vector<std::string> notes;
  if (const auto q = parseQuantity(s.persistent.quantity)) s.settings.quantity = *q;
  else if (!s.persistent.quantity.empty()) notes.push_back("unknown quantity '" + s.persistent.quantity + "'");
  std::vector<std::string> maps = vis::colorMapNames();
  maps.push_back(vis::kAutoColorMap);
  if (std::find(maps.begin(), maps.end(), s.persistent.colorMap) != maps.end()) s.settings.colorMap = s.persistent.colorMap;
  else notes.push_back("unknown colour map '" + s.persistent.colorMap + "'");
  if (!notes.empty()) {
    s.status = "settings.json: ";
    for (std::size_t i = 0; i < notes.size(); ++i) s.status += (i ? ", " : "") + notes[i];
    s.status += "; using " + std::string(quantityInfo(s.settings.quantity).label) + " and " + s.settings.colorMap;
  }
}

Inspector::~Inspector() = default;

void Inspector::State::openFile(const std::string& path) { openFiles({path}); }

void Inspector::State::openFiles(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) persistent.addRecent(path);
  for (RunFiles& run : pairRunFiles(paths)) queue.runs.push_back(std::move(run));
  startQueuedLoad();
}

void Inspector::State::startQueuedLoad() {
  if (job.running() || pending) return;
  if (recolourWaiting) {
    recolourWaiting = false;
    startRecolour();
    return;
  }
  if (queue.runs.empty()) return;
  const RunFiles run = queue.runs.front();
  queue.runs.pop_front();
  // A dump alone joins the active program when that has no dump of its own yet.
  Document* doc = activeDocument();
  if (run.program.empty() && doc && doc->dumpPath.empty() && !doc->programPath.empty())
    startLoad(doc->programPath, run.dump, active);
  else
    startLoad(run.program, run.dump);
}

void Inspector::open(const std::string& path) { state_->openFile(path); }
void Inspector::open(const std::vector<std::string>& paths) { state_->openFiles(paths); }

void Inspector::frame() {
  State& s = *state_;
  s.chrome.escapeTaken = false;
  s.takeJobResult();
  s.startQueuedLoad();
  // Playing moves the selection before anything is drawn, so that the view's tool and every
  // panel show the same sample in a frame.
  s.follow.playback.advance(s.selection, ImGui::GetIO().DeltaTime);
  s.syncHighlight();
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float width = viewport->Size.x, height = viewport->Size.y;
  const float menuHeight = ImGui::GetFrameHeight();
  const float toolbarHeight = ImGui::GetFrameHeightWithSpacing() + 10;
  const float statusHeight = ImGui::GetFrameHeightWithSpacing() + 8;
  const float top = menuHeight + toolbarHeight, bottom = height - statusHeight;
  // The left column holds the Colour panel's controls whole (about 17 characters wide) on a
  // small window too, within a third of it.
  const float left = std::clamp(ImGui::GetFontSize() * 17.0f, width * 0.18f, width * 0.3f), right = width * 0.70f;
  const float middle = top + (bottom - top) * 0.64f;

  drawMenuAndToolbar(s, menuHeight, width);
  drawNavigationTree(s, 0, top, left, (bottom - top) * 0.5f);
  drawColourControls(s, 0, top + (bottom - top) * 0.5f, left, (bottom - top) * 0.5f);
  if (s.comparison || s.runComparison) {
    const float half = (right - left) * 0.5f;
    drawSceneView(s, left, top, half, middle - top);
    if (s.comparison) drawComparisonView(s, left + half, top, right - left - half, middle - top);
    else drawRunComparisonView(s, left + half, top, right - left - half, middle - top);
  } else {
    drawSceneView(s, left, top, right - left, middle - top);
  }
  drawSignalCurves(s, left, middle, right - left, bottom - middle);
  drawGcodePane(s, right, top, width - right, (bottom - top) * 0.45f);
  drawDataBar(s, right, top + (bottom - top) * 0.45f, width - right, (bottom - top) * 0.55f);
  drawStatusBar(s, bottom, width);
  drawDialogs(s);
  drawOptimiseDialog(s);
  drawCompareDialog(s);
  drawMachineWindow(s);
  drawExportDialog(s);
  drawHelpWindow(s);
  drawOverwriteQuestion(s);
  // Esc that nothing on screen used cancels the running job (not while a dialog is up).
  if (s.job.running() && !ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId) && s.takeEscape()) s.job.cancel();
}

// A job's result is taken, and queued files start loading, by the next frame: until then too.
bool Inspector::busy() const {
  return state_->job.running() || state_->job.finishedPending() || !state_->queue.runs.empty() ||
         state_->follow.playback.playing;
}
bool Inspector::refining() const { return state_->refinement.pending(); }
std::size_t Inspector::documentCount() const { return state_->documents.size(); }

void Inspector::showDocument(std::size_t index) {
  if (index < state_->documents.size() && index != state_->active) state_->activate(index);
}

void Inspector::waitUntilIdle() {
  do {
    while (state_->job.running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    state_->takeJobResult();
    state_->startQueuedLoad();
  } while (state_->job.running());
}

bool Inspector::selectSample(std::size_t sample) { return state_->selection.selectSample(sample); }
bool Inspector::selectLine(std::uint32_t line) { return state_->selection.selectLine(line); }

void Inspector::colourBy(const std::string& name) {
  State& s = *state_;
  if (const auto q = parseQuantity(name)) {
    s.settings.quantity = *q;
    s.settings.channel.clear();
    s.persistent.quantity = name;
  } else {
    const Document* doc = s.activeDocument();
    if (!doc || !doc->samples || !doc->samples->extraChannel(name))
      throw InputError(Diagnostic{"", 0, 0, "unknown quantity or channel '" + name + "'"});
    s.settings.channel = name;
  }
  s.startRecolour();
}

void Inspector::optimise(std::uint32_t firstLine, std::uint32_t lastLine) { state_->startOptimise(firstLine, lastLine); }
void Inspector::showOptimisedDifference(bool difference) { state_->showOptimisedDifference(difference); }
const RunComparison* Inspector::optimisedDifference() const {
  return state_->comparison ? &state_->comparison->difference : nullptr;
}

void Inspector::compareWith(const std::string& dumpPath) { state_->startRunComparison(dumpPath); }
void Inspector::showRunDifference(bool difference) { state_->showRunDifference(difference); }
const RunComparison* Inspector::runComparison() const {
  return state_->runComparison ? &state_->runComparison->result : nullptr;
}

void Inspector::useMachine(const Machine& machine, const std::string& source) {
  state_->dialogs.machine.use(machine, source);
}
const Machine& Inspector::machine() const { return state_->dialogs.machine.inUse; }
const Machine* Inspector::activeMachine() const {
  const Document* doc = state_->activeDocument();
  return doc && doc->samples ? &doc->machine : nullptr;
}
void Inspector::showMachineWindow() { state_->openMachineWindow(); }
void Inspector::showWarningsWindow() { state_->dialogs.warningsOpen = true; }
void Inspector::showRegionsWindow() {
  state_->dialogs.regionsOpen = true;
  state_->startFindingRegions();
}
void Inspector::simulateAgain() { state_->simulateAgain(); }

const app_model::Selection& Inspector::selection() const { return state_->selection.current(); }
std::string Inspector::statusText() const { return state_->status; }
app_model::Settings& Inspector::settings() { return state_->persistent; }
bool Inspector::quitRequested() const { return state_->chrome.quit; }

}  // namespace isurface::panels
