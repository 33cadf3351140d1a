#pragma once
// The Open dialog's model: a folder listed with a filter, and a path typed or chosen from it.
#include <optional>
#include <string>

#include "isurface/app_model/folder_listing.h"

namespace isurface::app_model {

struct OpenDialog {
  bool opening = false;  // asked for: the window opens it on its next frame
  std::string path;      // typed or chosen: a file, or a folder ending in '/'
  FileFilter filter = FileFilter::Openable;
  FolderListing listing;

  // Opens it at the folder of the path (the working folder when there is none), listed afresh.
  void open();
  // Lists `folder` again when it or the filter changed since it was listed (or when `force`).
  void relist(const std::string& folder, bool force = false);
  // Lists `folder` and types it as the path.
  void enter(const std::string& folder);
  void up();
  // What Open (or Enter) does with the path: a folder is entered (nothing to open), a file is
  // returned to be opened.
  std::optional<std::string> submit();

 private:
  std::optional<FileFilter> listedWith_;
};

}  // namespace isurface::app_model
