#include "isurface/io/output_path.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <system_error>
#include <vector>

#include "isurface/base/diagnostic.h"

namespace isurface {

namespace {

// As many links as the kernel follows before it reports a loop.
constexpr int kMostLinks = 40;

[[noreturn]] void refuse(const std::string& target, int error) {
  throw InputError(Diagnostic{target, 0, 0, "cannot write: " + std::error_code(error, std::generic_category()).message()});
}

}  // namespace

std::string outputDestination(const std::string& target) {
  std::string path = target;
  for (int links = 0;; ++links) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) {
      // Not there yet is what an output usually is; anything else (ENAMETOOLONG, ENOTDIR,
      // ELOOP in a folder of the path) would only fail later, after the work.
      if (errno != ENOENT) refuse(target, errno);
      return path;
    }
    if (!S_ISLNK(st.st_mode)) return path;
    if (links == kMostLinks) refuse(target, ELOOP);
    std::vector<char> buffer(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 4095) + 1);
    const ssize_t n = ::readlink(path.c_str(), buffer.data(), buffer.size());
    if (n < 0) refuse(target, errno);
    const std::filesystem::path linked(std::string(buffer.data(), static_cast<std::size_t>(n)));
    path = linked.is_absolute() ? linked.string() : (std::filesystem::path(path).parent_path() / linked).string();
  }
}

}  // namespace isurface
