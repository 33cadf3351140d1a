#pragma once
// A folder as the Open dialog lists it: its folders first, then its files, each sorted by name
// (letter case aside), files told apart by their content and filtered by kind.
#include <optional>
#include <string>
#include <vector>

#include "isurface/workflow/file_kinds.h"

namespace isurface::app_model {

enum class FileFilter { Openable, Programs, Dumps, Traces, All };

struct FolderEntry {
  std::string name;                 // file or folder name, without the folder
  bool folder = false;
  std::optional<FileKind> kind;     // files: what they are; nothing for a file that is none of them
};

struct FolderListing {
  std::string folder;               // as listed (absolute)
  std::vector<FolderEntry> entries;
  std::string error;                // why the folder could not be read, if it could not
  bool cut = false;                 // more entries than are listed
};

// Lists `folder`, at most `limit` entries. Hidden entries (a leading '.') are left out.
FolderListing listFolder(const std::string& folder, FileFilter filter, std::size_t limit = 2000);

const char* fileFilterName(FileFilter filter);

}  // namespace isurface::app_model
