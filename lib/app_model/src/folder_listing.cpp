#include "isurface/app_model/folder_listing.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "isurface/base/diagnostic.h"

namespace isurface::app_model {

namespace {

// What is read of each file listed to tell its kind: enough for any header, little enough that
// a folder of thousands of files lists at once.
constexpr std::size_t kListingHeadBytes = 4096;

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool passes(FileFilter filter, const std::optional<FileKind>& kind) {
  switch (filter) {
    case FileFilter::All: return true;
    case FileFilter::Openable: return kind.has_value();
    case FileFilter::Programs: return kind == FileKind::Program;
    case FileFilter::Dumps: return kind == FileKind::Dump;
    case FileFilter::Traces: return kind && isTrace(*kind);
  }
  return false;
}

}  // namespace

const char* fileFilterName(FileFilter filter) {
  switch (filter) {
    case FileFilter::Openable: return "programs, dumps and traces";
    case FileFilter::Programs: return "G-code programs";
    case FileFilter::Dumps: return "Biip dumps";
    case FileFilter::Traces: return "traces (halsampler, CSV)";
    case FileFilter::All: return "all files";
  }
  return "";
}

FolderListing listFolder(const std::string& folder, FileFilter filter, std::size_t limit) {
  FolderListing out;
  std::error_code error;
  const std::filesystem::path path = std::filesystem::absolute(folder.empty() ? "." : folder, error);
  out.folder = path.lexically_normal().string();
  while (out.folder.size() > 1 && out.folder.back() == '/') out.folder.pop_back();
  std::filesystem::directory_iterator it(path, error);
  if (error) {
    out.error = out.folder + ": " + error.message();
    return out;
  }
  // Stepped with an error code: an entry that vanishes or cannot be read ends nothing.
  for (; it != std::filesystem::directory_iterator(); it.increment(error)) {
    if (error) {
      out.error = out.folder + ": " + error.message();
      break;
    }
    const std::filesystem::directory_entry& entry = *it;
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    if (out.entries.size() >= limit) {
      out.cut = true;
      break;
    }
    std::error_code kindError;
    if (entry.is_directory(kindError)) {
      out.entries.push_back({name, true, std::nullopt});
      continue;
    }
    if (!entry.is_regular_file(kindError)) continue;
    std::optional<FileKind> kind;
    try {
      kind = fileKind(entry.path().string(), kListingHeadBytes);
    } catch (const InputError&) {
      // Neither a program, a dump nor a trace: listed only under "all files".
    }
    if (passes(filter, kind)) out.entries.push_back({name, false, kind});
  }
  std::sort(out.entries.begin(), out.entries.end(), [](const FolderEntry& a, const FolderEntry& b) {
    if (a.folder != b.folder) return a.folder;
    const std::string la = lowerCase(a.name), lb = lowerCase(b.name);
    return la != lb ? la < lb : a.name < b.name;
  });
  return out;
}

}  // namespace isurface::app_model
