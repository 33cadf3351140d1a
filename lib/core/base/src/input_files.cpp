#include "isurface/base/input_files.h"

#include <sys/stat.h>
#include <unistd.h>

#include <map>
#include <mutex>
#include <utility>

#include "isurface/base/diagnostic.h"

namespace isurface {

namespace {

using FileId = std::pair<dev_t, ino_t>;

std::mutex g_mutex;
std::map<FileId, std::string> g_inputs;  // the name each was first read by
bool g_protected = false;

// Standard output, when it is a regular file.
bool standardOutputId(FileId& id) {
  struct stat st {};
  if (::fstat(STDOUT_FILENO, &st) != 0 || !S_ISREG(st.st_mode)) return false;
  id = {st.st_dev, st.st_ino};
  return true;
}

void note(const struct stat& st, const std::string& path) {
  if (!S_ISREG(st.st_mode)) return;
  const FileId id{st.st_dev, st.st_ino};
  bool isStandardOutput = false;
  {
    const std::lock_guard<std::mutex> lock(g_mutex);
    g_inputs.emplace(id, path);
    FileId out;
    isStandardOutput = g_protected && standardOutputId(out) && out == id;
  }
  if (isStandardOutput)
    throw InputError(Diagnostic{path, 0, 0,
                                "standard output is this file, an input of this command: what is printed would "
                                "be written into it (redirect the output to another file)"});
}

}  // namespace

void noteInputFile(int fd, const std::string& path) {
  struct stat st {};
  if (::fstat(fd, &st) == 0) note(st, path);
}

void noteInputFile(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) note(st, path);
}

std::string standardOutputInput() {
  FileId out;
  const std::lock_guard<std::mutex> lock(g_mutex);
  if (!g_protected || !standardOutputId(out)) return "";
  const auto it = g_inputs.find(out);
  return it == g_inputs.end() ? "" : it->second;
}

void protectInputFiles(bool on) {
  const std::lock_guard<std::mutex> lock(g_mutex);
  g_protected = on;
}

bool isProtectedInputFile(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  const std::lock_guard<std::mutex> lock(g_mutex);
  return g_protected && g_inputs.count({st.st_dev, st.st_ino}) > 0;
}

}  // namespace isurface
