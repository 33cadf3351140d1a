#include "isurface/app_model/open_dialog.h"

#include <filesystem>

namespace isurface::app_model {

void OpenDialog::open() {
  opening = true;
  std::error_code error;
  const std::filesystem::path typed(path);
  const std::filesystem::path folder = typed.empty() ? std::filesystem::current_path(error)
                                       : std::filesystem::is_directory(typed, error) ? typed
                                                                                     : typed.parent_path();
  relist(folder.string(), true);
}

void OpenDialog::relist(const std::string& folder, bool force) {
  if (!force && listing.folder == folder && listedWith_ == filter) return;
  listing = listFolder(folder, filter);
  listedWith_ = filter;
}

void OpenDialog::enter(const std::string& folder) {
  relist(folder);
  path = listing.folder + "/";
}

void OpenDialog::up() { enter(std::filesystem::path(listing.folder).parent_path().string()); }

std::optional<std::string> OpenDialog::submit() {
  if (path.empty()) return std::nullopt;
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    enter(path);
    return std::nullopt;
  }
  return path;
}

}  // namespace isurface::app_model
