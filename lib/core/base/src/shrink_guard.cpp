#include "isurface/base/shrink_guard.h"

#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <mutex>

namespace isurface {

namespace {

// Lock-free, so that the signal handler may read it: a slot is claimed by swapping its begin
// from 0, and its range is set before it is published.
struct GuardSlot {
  std::atomic<std::uintptr_t> begin{0};
  std::atomic<std::uintptr_t> end{0};
  std::atomic<bool> published{false};
  std::atomic<bool> shrank{false};
};

GuardSlot g_slots[ShrinkGuard::kMaxGuards];
std::atomic<long> g_pageBytes{4096};

void onBusError(int signal, siginfo_t* info, void*) {
  const auto address = reinterpret_cast<std::uintptr_t>(info->si_addr);
  for (GuardSlot& slot : g_slots) {
    if (!slot.published.load(std::memory_order_acquire)) continue;
    if (address < slot.begin.load(std::memory_order_relaxed) || address >= slot.end.load(std::memory_order_relaxed))
      continue;
    const std::uintptr_t page = address & ~static_cast<std::uintptr_t>(g_pageBytes.load() - 1);
    // mmap is a plain system call here; the faulting read is retried on the zero page.
    if (::mmap(reinterpret_cast<void*>(page), static_cast<std::size_t>(g_pageBytes.load()), PROT_READ,
               MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) != MAP_FAILED) {
      slot.shrank.store(true, std::memory_order_relaxed);
      return;
    }
    break;
  }
  // Not a guarded mapping: the fault is a real one. The default action ends the process as
  // it would have without the handler.
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

void installHandler() {
  static std::once_flag once;
  std::call_once(once, [] {
    g_pageBytes.store(::sysconf(_SC_PAGESIZE));
    struct sigaction action {};
    action.sa_sigaction = onBusError;
    action.sa_flags = SA_SIGINFO | SA_NODEFER;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGBUS, &action, nullptr);
  });
}

}  // namespace

ShrinkGuard::ShrinkGuard(const void* data, std::size_t bytes) {
  if (!data || bytes == 0) return;
  installHandler();
  for (int i = 0; i < kMaxGuards; ++i) {
    std::uintptr_t free = 0;
    if (!g_slots[i].begin.compare_exchange_strong(free, reinterpret_cast<std::uintptr_t>(data))) continue;
    g_slots[i].end.store(reinterpret_cast<std::uintptr_t>(data) + bytes);
    g_slots[i].shrank.store(false);
    g_slots[i].published.store(true, std::memory_order_release);
    slot_ = i;
    return;
  }
}

ShrinkGuard::~ShrinkGuard() {
  if (slot_ < 0) return;
  g_slots[slot_].published.store(false, std::memory_order_release);
  g_slots[slot_].end.store(0);
  g_slots[slot_].begin.store(0);
}

bool ShrinkGuard::shrank() const { return slot_ >= 0 && g_slots[slot_].shrank.load(std::memory_order_relaxed); }

}  // namespace isurface
