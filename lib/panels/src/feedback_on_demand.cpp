// The servo's positions of a document, loaded the first time something needs them: a colouring
// by following error or deviation, the feedback surface, the data bar's feedback columns, an
// export, a comparison or an optimisation judged on the predicted deviation. Until then they
// cost nothing (1.2 GB of a 100 million-sample run).
#include <fmt/format.h>

#include "inspector_state.h"

namespace isurface::panels {

bool Inspector::State::loadFeedbackFirst(std::function<void()> then) {
  Document* doc = activeDocument();
  if (!doc || !doc->samples || doc->samples->hasFeedback() || !doc->feedbackSupply.available()) return false;
  if (refusedDuringReport("load the feedback")) return true;
  if (job.running()) {  // starting a job would cancel it
    status = "wait until " + job.label() + " ends (or cancel it) to load the feedback";
    return true;
  }
  auto result = std::make_shared<JobResult>(LoadedFeedback{doc->samples, std::nullopt, std::move(then)});
  pending = result;
  const std::string label = "loading the feedback of " + doc->name;
  job.start(label, [result, supply = doc->feedbackSupply](app_model::JobControl& control) {
    LoadedFeedback& loaded = std::get<LoadedFeedback>(*result);
    loaded.feedback = loadFeedback(*loaded.madeFor, supply, [&control](double f) { control.progress(f); });
  });
  status = label;
  return true;
}

void Inspector::State::attachLoadedFeedback(LoadedFeedback& result) {
  for (std::size_t k = 0; k < documents.size(); ++k) {
    Document& doc = *documents[k];
    if (doc.samples != result.madeFor) continue;
    // Nothing else reads this document's feedback now: the one job has ended, and a close-up
    // being built (a map that shows no feedback) is waited for. The samples were made
    // non-const (openRun), so writing them through this pointer is defined.
    if (refinement.building.valid()) refinement.building.wait();
    const_cast<Trajectory&>(*doc.samples).attachFeedback(std::move(*result.feedback));
    doc.feedbackSupply = {};
    status = fmt::format("{}: feedback loaded ({} samples)", doc.name, doc.samples->size());
    // What waited for the feedback (a colouring, a re-optimisation) was asked of this
    // document: it is shown again for it, though another was chosen meanwhile.
    if (result.then) {
      if (k != active) activate(k);
      result.then();
    }
    return;
  }
  status = "the feedback was loaded for a document since closed";
}

}  // namespace isurface::panels
