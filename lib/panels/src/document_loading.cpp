// Loading a document on a background thread: program text, the program and its samples (one
// workflow call: read and joined, or simulated), the quality map and its scene, the curves.
#include <atomic>
#include <algorithm>
#include <filesystem>
#include <future>

#include "inspector_state.h"
#include "isurface/vis/quality_scene.h"
#include "isurface/workflow/run_inputs.h"

namespace isurface::panels {

// The curves read their values from the samples as a view needs them (nothing copied per
// curve but its coarse pyramid).
Curve curveOf(Quantity q, std::shared_ptr<const Trajectory> samples) {
  const QuantityInfo& info = quantityInfo(q);
  const std::size_t n = samples->size();
  return Curve{info.label, info.unit,
               app_model::SignalPyramid(n, [q, samples](std::size_t first, std::size_t last, float* out) {
                 sampleQuantityRange(q, *samples, first, last, out);
               })};
}

namespace {

Curve channelCurve(const std::string& name, std::shared_ptr<const Trajectory> samples) {
  const std::vector<double>* values = samples->extraChannel(name);
  return Curve{name, "",
               app_model::SignalPyramid(values->size(), [values, samples](std::size_t first, std::size_t last, float* out) {
                 for (std::size_t i = first; i < last; ++i) out[i - first] = static_cast<float>((*values)[i]);
               })};
}

// A colouring remembered from another file that this one cannot show (a quantity that needs
// feedback) gives way to speed, with a word, rather than blocking the file.
vis::QualityMapRequest fitRequest(vis::QualityMapRequest request, const Trajectory& samples,
                                  std::vector<std::string>& warnings) {
  if (!request.channel.empty() && !samples.extraChannel(request.channel)) request.channel.clear();
  if (request.channel.empty() && quantityInfo(request.quantity).needsFeedback && !samples.hasFeedback()) {
    warnings.push_back(std::string("coloured by speed: ") + quantityInfo(request.quantity).label +
                       " needs feedback, which this file has none of");
    request.quantity = Quantity::Speed;
  }
  if (request.feedbackSurface && !samples.hasFeedback()) request.feedbackSurface = false;
  return request;
}

}  // namespace

Document::Document() {
  static std::atomic<std::uint64_t> made{0};  // documents are made on the jobs' threads
  serial = ++made;
}

std::string machineCaption(const Machine& machine, bool known) {
  return known ? "machine: " + machine.name : std::string("machine: not named by the dump");
}

std::string mapCaption(const Document& doc) {
  std::string caption = machineCaption(doc.machine, doc.machineKnown);
  if (doc.samples && doc.samples->thinning > 1)
    caption += ", 1 sample in " + std::to_string(doc.samples->thinning) + " of the dump";
  return caption;
}

void noteSurface(Document& doc) {
  auto& w = doc.warnings;
  w.erase(std::remove_if(w.begin(), w.end(),
                         [](const std::string& s) {
                           return s.find(kFoldedPassesNote) != std::string::npos ||
                                  s.find(vis::kLittleSurfaceNote) != std::string::npos;
                         }),
          w.end());
  doc.surfaceShare = doc.map.mesh ? doc.map.mesh->joinedShare() : 1.0;
  if (!doc.samples) return;
  for (std::string& note : vis::surfaceNotes(*doc.samples, doc.map, "the Colour panel's passes and gap"))
    w.push_back(std::move(note));
}

std::unique_ptr<Document> loadDocument(const std::string& programPath, const std::string& dumpPath,
                                       const vis::QualityMapRequest& request, const Machine& machine,
                                       bool unitsOfProgram, app_model::JobControl& control) {
  auto doc = std::make_unique<Document>();
  doc->programPath = programPath;
  doc->dumpPath = dumpPath;
  doc->viewDirection = request.view;
  // A program with a dump of its own (a recording) is named with it: the same program simulated
  // beside it is told apart.
  const auto fileName = [](const std::string& path) { return std::filesystem::path(path).filename().string(); };
  doc->name = programPath.empty() ? fileName(dumpPath)
              : dumpPath.empty()  ? fileName(programPath)
                                  : fileName(programPath) + " (" + fileName(dumpPath) + ")";
  if (!programPath.empty()) doc->text = std::make_unique<app_model::TextLines>(programPath);
  OpenRunRequest open;
  open.files = {programPath, dumpPath};
  open.machine = machine;
  // The quantity too when a channel is chosen: the channel gives way to it on a file without it.
  open.channels.feedback = needsFeedback(request) || quantityInfo(request.quantity).needsFeedback;
  open.thinToFit = true;  // a dump larger than the memory is seen whole, thinned, with a word
  OpenedRun run = openRun(open, [&control](double f) { control.progress(0.5 * f); });
  doc->program = std::move(run.program);
  doc->samples = std::move(run.samples);
  doc->machine = run.machine;
  doc->machineKnown = run.machineKnown;
  doc->warnings = std::move(run.warnings);
  doc->feedbackSupply = std::move(run.feedbackSupply);
  doc->thinnedDump = std::move(run.thinnedDump);
  if (!doc->samples || doc->samples->size() == 0) return doc;
  control.progress(0.55);
  // The curves' pyramids need only the samples: built on a second thread beside the map.
  std::future<std::vector<Curve>> curves = std::async(std::launch::async, [samples = doc->samples] {
    std::vector<Curve> made;
    for (Quantity q : {Quantity::Speed, Quantity::Acceleration, Quantity::Jerk}) made.push_back(curveOf(q, samples));
    for (const auto& channel : samples->extra) made.push_back(channelCurve(channel.first, samples));
    return made;
  });
  doc->lineTimes = app_model::LineTimes(*doc->samples);
  vis::QualityMapRequest fitted = fitRequest(request, *doc->samples, doc->warnings);
  fitted.caption = mapCaption(*doc);
  if (unitsOfProgram) fitted.inch = doc->program && doc->program->inch;
  // Samples with no surface to map (a drilling program, a trace cut short) still open: their
  // curves and rows are there, and the reason stands beside the file's own warnings.
  try {
    doc->map = vis::buildQualityMap(*doc->samples, doc->program.get(), fitted);
    noteSurface(*doc);
    control.progress(0.75);
    doc->scene = std::make_shared<vis::QualityScene>(doc->map.data, doc->map.style);
  } catch (const InputError& e) {
    doc->warnings.push_back(std::string("no map: ") + e.what());
  }
  control.progress(0.85);
  doc->curves = curves.get();
  control.progress(1.0);
  return doc;
}

}  // namespace isurface::panels
