// The shared selection: every change bumps the generation so that each panel, polling it once
// a frame, scrolls to the selection even when the same sample is picked again.
#include "isurface/app_model/selection.h"

#include <algorithm>

#include "isurface/analysis/locate.h"

namespace isurface::app_model {

namespace {

// The line a sample was produced by; none when the dump has no line channel or the line is
// unknown (0).
std::optional<std::uint32_t> lineOfSample(const Trajectory& samples, std::size_t sample) {
  if (!samples.hasLine || sample >= samples.line.size()) return std::nullopt;
  const std::uint32_t line = samples.line[sample];
  if (line == 0) return std::nullopt;
  return line;
}

}  // namespace

void SelectionModel::setTrajectory(const Trajectory* samples) {
  firstSampleByLine_.clear();
  firstSampleByLine_.shrink_to_fit();
  lineIndexBuilt_ = false;
  lineIndexSampleCount_ = 0;
  const bool sameSamples = samples == samples_;
  samples_ = samples;
  // The same trajectory may have been refilled in place: its sample stays only if it still exists.
  const bool sampleStillValid = sameSamples && samples_ && selection_.sample && *selection_.sample < samples_->size();
  if (selection_.sample && !sampleStillValid) {
    selection_.sample.reset();
    bump();
  }
}

bool SelectionModel::selectSample(std::size_t sample) {
  if (!samples_ || sample >= samples_->size()) return false;
  selection_.sample = sample;
  selection_.line = lineOfSample(*samples_, sample);
  bump();
  return true;
}

std::optional<std::size_t> SelectionModel::firstSampleOfLineCached(std::uint32_t line) {
  const Trajectory& samples = *samples_;
  // Without a line channel every line entry is a placeholder 0: nothing to index.
  if (!samples.hasLine || samples.line.empty()) return firstSampleOfLine(samples, line);
  if (!lineIndexBuilt_ || lineIndexSampleCount_ != samples.line.size()) {
    // Only where the line changes can a line begin; consecutive samples mostly share one, so
    // the index holds about one entry per G-code line, not per sample.
    firstSampleByLine_.clear();
    const RunChannel<std::uint32_t>& lines = samples.line;
    for (std::size_t r = 0; r < lines.runCount(); ++r) firstSampleByLine_.emplace_back(lines.runValue(r), lines.runBegin(r));
    // Stable by line then sample: the first entry of each line is its earliest sample.
    std::sort(firstSampleByLine_.begin(), firstSampleByLine_.end());
    const auto sameLine = [](const auto& a, const auto& b) { return a.first == b.first; };
    firstSampleByLine_.erase(std::unique(firstSampleByLine_.begin(), firstSampleByLine_.end(), sameLine),
                             firstSampleByLine_.end());
    firstSampleByLine_.shrink_to_fit();
    lineIndexBuilt_ = true;
    lineIndexSampleCount_ = lines.size();
  }
  const auto it = std::lower_bound(firstSampleByLine_.begin(), firstSampleByLine_.end(), line,
                                   [](const auto& entry, std::uint32_t value) { return entry.first < value; });
  if (it == firstSampleByLine_.end() || it->first != line) return std::nullopt;
  return it->second;
}

bool SelectionModel::selectLine(std::uint32_t line) {
  std::optional<std::size_t> sample;
  if (samples_) sample = firstSampleOfLineCached(line);
  selection_.line = line;
  selection_.sample = sample;
  bump();
  return sample.has_value();
}

bool SelectionModel::selectNearest(const Vec3& point) {
  if (!samples_) return false;
  const std::optional<std::size_t> sample = nearestSample(*samples_, point);
  if (!sample) return false;
  selectSample(*sample);
  return true;
}

void SelectionModel::clear() {
  selection_.sample.reset();
  selection_.line.reset();
  bump();
}

}  // namespace isurface::app_model
