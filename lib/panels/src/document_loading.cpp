// Loading a document on a background thread: program text, interpretation, samples (read or
// simulated), the quality map and its scene, and the signal curves.
#include <filesystem>

#include "inspector_state.h"
#include "isurface/io/biip.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/nc/simulator.h"
#include "isurface/vis/quality_scene.h"
#include "isurface/io/trajectory_loading.h"
#include "isurface/nc/sample_trajectory.h"

namespace isurface::panels {

namespace {

// Maps a part of the job's progress to one stage.
struct Stage {
  app_model::JobControl& control;
  double from, to;
  void operator()(double f) const { control.progress(from + (to - from) * f); }
};

Curve curveOf(Quantity q, const Trajectory& samples) {
  const QuantityInfo& info = quantityInfo(q);
  const std::vector<double> values = sampleQuantity(q, samples);
  return Curve{info.label, info.unit, app_model::SignalPyramid(std::vector<float>(values.begin(), values.end()))};
}

}  // namespace

std::unique_ptr<Document> loadDocument(const std::string& programPath, const std::string& dumpPath,
                                       const vis::QualityMapRequest& request, app_model::JobControl& control) {
  auto doc = std::make_unique<Document>();
  doc->programPath = programPath;
  doc->dumpPath = dumpPath;
  doc->name = std::filesystem::path(programPath.empty() ? dumpPath : programPath).filename().string();
  if (!programPath.empty()) {
    doc->text = std::make_unique<app_model::TextLines>(programPath);
    InterpreterOptions options;
    options.progress = Stage{control, 0.0, 0.15};
    InterpretResult r = interpretGcodeFile(programPath, options);
    if (!r.ok()) throw InputError(r.errors.front());
    for (const Diagnostic& w : r.program.warnings) doc->warnings.push_back(w.str());
    doc->program = std::make_shared<const Program>(std::move(r.program));
  }
  if (!dumpPath.empty()) {
    const BiipReader reader(dumpPath);
    for (const std::string& w : reader.warnings()) doc->warnings.push_back(dumpPath + ": " + w);
    doc->samples = std::make_shared<const Trajectory>(loadTrajectory(reader, Stage{control, 0.15, 0.5}));
  } else if (doc->program) {
    SampleBuffer buffer;
    const Machine machine = defaultMachine();
    simulate(*doc->program, machine, buffer, Stage{control, 0.15, 0.5});
    doc->samples = std::make_shared<const Trajectory>(trajectoryFromSamples(buffer.data, machine.cycle, programPath));
  }
  if (!doc->samples || doc->samples->size() == 0) return doc;
  control.progress(0.55);
  doc->map = vis::buildQualityMap(*doc->samples, doc->program.get(), request);
  control.progress(0.75);
  doc->scene = std::make_shared<vis::QualityScene>(doc->map.data, doc->map.style);
  control.progress(0.85);
  for (Quantity q : {Quantity::Speed, Quantity::Acceleration, Quantity::Jerk}) doc->curves.push_back(curveOf(q, *doc->samples));
  for (const auto& [name, values] : doc->samples->extra)
    doc->curves.push_back(Curve{name, "", app_model::SignalPyramid(std::vector<float>(values.begin(), values.end()))});
  control.progress(1.0);
  return doc;
}

}  // namespace isurface::panels
