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

bool OptimiseDialog::boxed() const {
  return box && box->lines.first == static_cast<std::uint32_t>(first) &&
         box->lines.last == static_cast<std::uint32_t>(last);
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
