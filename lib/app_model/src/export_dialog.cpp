#include "isurface/app_model/export_dialog.h"

#include <fmt/format.h>

#include <array>

namespace isurface::app_model {

namespace {

constexpr std::array<const char*, 5> kExtensions = {".png", ".json", ".csv", ".html", ".biip"};
constexpr int kSmallestImage = 64, kLargestImage = 8192;
constexpr int kMostRegions = 50;

const char* extensionOf(ExportKind kind) { return kExtensions[static_cast<std::size_t>(kind)]; }

}  // namespace

void ExportDialog::show(std::optional<std::uint32_t> selectedLine) {
  opening = true;
  if (selectedLine) first = last = static_cast<int>(*selectedLine);
}

void ExportDialog::choose(ExportKind next) {
  if (next == kind) return;
  kind = next;
  for (const char* known : kExtensions) {
    const std::string extension = known;
    if (path.size() <= extension.size() || path.compare(path.size() - extension.size(), extension.size(), extension) != 0)
      continue;
    path = path.substr(0, path.size() - extension.size()) + extensionOf(kind);
    return;
  }
}

std::string ExportDialog::problem(const ExportSubject& subject) const {
  if (!subject.hasSamples) return "nothing to export: open a program or a dump first";
  const bool needsMap = kind != ExportKind::LineSamples && kind != ExportKind::RunDump;
  if (needsMap && !subject.hasMap) return "no map to export: " + subject.name + " has no surface";
  if ((kind == ExportKind::MapFigures || kind == ExportKind::LineSamples || kind == ExportKind::RunDump) &&
      subject.thinning > 1)
    return fmt::format("{} is shown thinned (1 sample in {}): its figures and samples need every sample", subject.name,
                       subject.thinning);
  if (kind == ExportKind::ViewPng &&
      (width < kSmallestImage || height < kSmallestImage || width > kLargestImage || height > kLargestImage))
    return fmt::format("the size must be {} to {} pixels each way", kSmallestImage, kLargestImage);
  if (kind == ExportKind::LineSamples && (first < 1 || last < first)) return "the lines must be first <= last, from 1";
  if (kind == ExportKind::Report && (regions < 0 || regions > kMostRegions))
    return fmt::format("the regions shown must be 0 to {}", kMostRegions);
  if (kind == ExportKind::Report && subject.jobRunning) return "wait for the work in progress (or cancel it) first";
  if (path.empty()) return "give the file to write";
  return {};
}

}  // namespace isurface::app_model
