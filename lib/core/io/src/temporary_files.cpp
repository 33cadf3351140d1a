#include "temporary_files.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <mutex>

namespace isurface::detail {

namespace {

constexpr int kSlots = 256;
std::atomic<const char*> g_temporaries[kSlots];
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

void removeTemporariesAndDie(int signal) {
  // unlink is async-signal-safe; a path is remembered as soon as its file is made.
  for (std::atomic<const char*>& slot : g_temporaries)
    if (const char* path = slot.load()) ::unlink(path);
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

void installHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int signal : kSignals) {
      struct sigaction old {};
      if (::sigaction(signal, nullptr, &old) != 0) continue;
      // A signal ignored (nohup, a background job) or already handled stays as it is.
      if (old.sa_handler != SIG_DFL || (old.sa_flags & SA_SIGINFO)) continue;
      struct sigaction action {};
      action.sa_handler = removeTemporariesAndDie;
      sigemptyset(&action.sa_mask);
      ::sigaction(signal, &action, nullptr);
    }
  });
}

}  // namespace

int rememberTemporary(const char* path) {
  installHandlers();
  for (int i = 0; i < kSlots; ++i) {
    const char* free = nullptr;
    if (g_temporaries[i].compare_exchange_strong(free, path)) return i;
  }
  return -1;
}

void forgetTemporary(int slot) {
  if (slot >= 0 && slot < kSlots) g_temporaries[slot].store(nullptr);
}

}  // namespace isurface::detail
