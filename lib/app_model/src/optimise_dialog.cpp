#include "isurface/app_model/optimise_dialog.h"

#include <filesystem>

namespace isurface::app_model {

void OptimiseDialog::forgetTheRegionOfAnotherProgram(const std::string& programPath) {
  if (programPath == program) return;
  program = programPath;
  box.reset();
  first = last = 1;
}

void OptimiseDialog::hold(LineRange lines, std::optional<BoxSelection> foundIn) {
  first = static_cast<int>(lines.first);
  last = static_cast<int>(lines.last);
  if (foundIn) box = std::move(foundIn);
  notice.clear();
}

namespace {

bool held(const OptimiseDialog& d, const LineRange& lines) {
  return lines.first == static_cast<std::uint32_t>(d.first) && lines.last == static_cast<std::uint32_t>(d.last);
}

}  // namespace

bool OptimiseDialog::boxed() const {
  return box && (held(*this, box->lines) || (box->ownPasses && held(*this, *box->ownPasses)));
}

std::optional<LineRange> OptimiseDialog::otherWidth() const {
  if (!boxed() || !box->ownPasses) return std::nullopt;
  const LineRange& own = *box->ownPasses;
  if (own.first == box->lines.first && own.last == box->lines.last) return std::nullopt;
  return held(*this, own) ? box->lines : own;
}

void OptimiseDialog::holdOtherWidth() {
  if (const std::optional<LineRange> other = otherWidth()) {
    first = static_cast<int>(other->first);
    last = static_cast<int>(other->last);
  }
}

std::string OptimiseDialog::rangeProblem() const {
  if (first < 1) return "the first line is line 1 or after";
  if (last < first) return "the last line is before the first: no lines to optimise";
  return {};
}

void OptimiseDialog::offerSavePath(const std::string& programPath, const std::string& folder) {
  const std::filesystem::path program(programPath);
  const std::filesystem::path where = folder.empty() ? std::filesystem::path(".") : std::filesystem::path(folder);
  const std::string offer = (where / (program.stem().string() + "-optimized.nc")).string();
  const bool typed = !savePath.empty() && savePath != offered_;
  if (!typed || offeredFor_ != programPath) savePath = offer;
  offered_ = offer;
  offeredFor_ = programPath;
}

}  // namespace isurface::app_model
