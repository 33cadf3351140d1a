#include "isurface/io/output_transaction.h"

#include <fcntl.h>
#include <unistd.h>

#include <sys/stat.h>

#include <cerrno>
#include <deque>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <system_error>

#include "isurface/base/diagnostic.h"
#include "isurface/base/input_files.h"
#include "temporary_files.h"

namespace isurface {

struct OutputTransaction::Pending {
  struct Output {
    std::string temporary, destination, target;
    std::string identity;  // what makes two destinations the same file
    int slot = -1;  // of the signal-time removal
  };
  std::mutex mutex;
  std::deque<Output> outputs;  // a deque: the paths' storage stays put for the signal handler

  void removeAll() noexcept {
    for (Output& o : outputs) {
      ::unlink(o.temporary.c_str());
      detail::forgetTemporary(o.slot);
    }
    outputs.clear();
  }
};

namespace {

std::mutex g_openMutex;
OutputTransaction::Pending* g_open = nullptr;

// The file a destination names: the absolute path with `.`, `..` and links resolved, and for a
// file that exists its device and inode too (another hard link to it).
std::string identityOf(const std::string& destination) {
  std::error_code error;
  std::string identity = std::filesystem::weakly_canonical(std::filesystem::absolute(destination, error), error)
                             .lexically_normal()
                             .string();
  if (error) identity = destination;
  struct stat st {};
  if (::stat(destination.c_str(), &st) == 0)
    identity = "inode " + std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
  return identity;
}

}  // namespace

OutputTransaction::OutputTransaction() : pending_(std::make_unique<Pending>()) {
  const std::lock_guard<std::mutex> lock(g_openMutex);
  if (g_open) throw std::logic_error("an output transaction is already open");
  g_open = pending_.get();
}

OutputTransaction::~OutputTransaction() {
  {
    const std::lock_guard<std::mutex> lock(g_openMutex);
    g_open = nullptr;
  }
  pending_->removeAll();
}

void OutputTransaction::publish() {
  {
    const std::lock_guard<std::mutex> lock(g_openMutex);
    g_open = nullptr;  // files committed from now on are renamed at once
  }
  Pending& p = *pending_;
  while (!p.outputs.empty()) {
    Pending::Output& o = p.outputs.front();
    // Checked again at the last moment: an input may have been read after its output was made.
    const int error = isProtectedInputFile(o.destination) ? EEXIST
                      : ::rename(o.temporary.c_str(), o.destination.c_str()) != 0 ? errno
                                                                                   : 0;
    if (error != 0) {
      const std::string target = o.target;
      p.removeAll();
      throw InputError(Diagnostic{target, 0, 0,
                                  error == EEXIST ? "cannot write: it is an input of this command (give another output name)"
                                                  : "cannot write: " + std::error_code(error, std::generic_category()).message()});
    }
    detail::forgetTemporary(o.slot);
    p.outputs.pop_front();
  }
}

namespace detail {

bool deferRename(const std::string& temporary, const std::string& destination, const std::string& target) {
  const std::lock_guard<std::mutex> lock(g_openMutex);
  if (!g_open) return false;
  const std::lock_guard<std::mutex> pendingLock(g_open->mutex);
  // Two outputs of one command on one file: the second would replace the first unseen.
  const std::string identity = identityOf(destination);
  for (const OutputTransaction::Pending::Output& other : g_open->outputs)
    if (other.identity == identity)
      throw InputError(Diagnostic{target, 0, 0,
                                  "cannot write: this command writes '" + other.target +
                                      "' there already (two of its outputs would be one file; give each its own name)"});
  OutputTransaction::Pending::Output& o = g_open->outputs.emplace_back();
  o.identity = identity;
  o.temporary = temporary;
  o.destination = destination;
  o.target = target;
  o.slot = rememberTemporary(o.temporary.c_str());
  return true;
}

}  // namespace detail

}  // namespace isurface
