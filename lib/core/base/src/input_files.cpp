#include "isurface/base/input_files.h"

#include <sys/stat.h>

#include <mutex>
#include <set>
#include <utility>

namespace isurface {

namespace {

std::mutex g_mutex;
std::set<std::pair<dev_t, ino_t>> g_inputs;
bool g_protected = false;

}  // namespace

void noteInputFile(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) return;
  const std::lock_guard<std::mutex> lock(g_mutex);
  g_inputs.emplace(st.st_dev, st.st_ino);
}

void noteInputFile(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;
  const std::lock_guard<std::mutex> lock(g_mutex);
  g_inputs.emplace(st.st_dev, st.st_ino);
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
