#include "output_options.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "isurface/base/diagnostic.h"
#include "isurface/io/output_path.h"

namespace isurface::cli {

namespace {

std::set<const CLI::Option*>& outputOptions() {
  static std::set<const CLI::Option*> options;
  return options;
}

// What makes two names the same file: its device and inode when it exists, else the absolute
// path with links (a dangling one too) and `.`/`..` resolved. Empty for a device or a pipe, which may be named twice.
std::string fileIdentity(const std::string& name) {
  const std::string path = outputDestination(name);
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0)
    return S_ISREG(st.st_mode) || S_ISDIR(st.st_mode)
               ? "inode " + std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino)
               : std::string();
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  if (error) return "path " + path;
  return "path " + std::filesystem::weakly_canonical(absolute, error).lexically_normal().string();
}

}  // namespace

CLI::Option* outputOption(CLI::Option* option) {
  outputOptions().insert(option);
  return option;
}

void refuseSharedOutputs(const CLI::App& sub) {
  struct Given {
    std::string option, path, identity;
  };
  std::vector<Given> given;
  for (const CLI::Option* option : sub.get_options()) {
    if (outputOptions().count(option) == 0 || option->count() == 0) continue;
    for (const std::string& path : option->results()) {
      if (path.empty()) continue;
      const std::string identity = fileIdentity(path);
      if (identity.empty()) continue;
      for (const Given& other : given)
        if (other.identity == identity)
          throw InputError(Diagnostic{path, 0, 0,
                                      other.option + " and " + option->get_name() + " name the same file ('" +
                                          other.path + "' and '" + path + "'): one would replace the other; "
                                          "give each output a name of its own"});
      given.push_back({option->get_name(), path, identity});
    }
  }
}

HeldStandardOutput::HeldStandardOutput() {
  std::fflush(stdout);
  memory_ = ::open_memstream(&buffer_, &size_);
  if (!memory_) return;  // no memory: printed as it comes
  real_ = stdout;
  stdout = memory_;  // glibc: stdout is a variable that may be set
}

HeldStandardOutput::~HeldStandardOutput() {
  restore();
  std::free(buffer_);
}

void HeldStandardOutput::restore() {
  if (!memory_) return;
  stdout = real_;
  std::fclose(memory_);  // sets buffer_ and size_ a last time
  memory_ = nullptr;
}

bool HeldStandardOutput::release() {
  if (memory_ && std::fflush(memory_) != 0) {
    restore();
    return false;
  }
  restore();
  errno = 0;
  if (size_ > 0 && std::fwrite(buffer_, 1, size_, stdout) != size_) return false;
  size_ = 0;
  return std::fflush(stdout) == 0 && !std::ferror(stdout);
}

}  // namespace isurface::cli
