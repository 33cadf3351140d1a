#pragma once
// How much memory this machine can still give a process: checked before a dump's samples are
// copied, so that a dump too large for the machine is refused with a message instead of the
// process being killed by the kernel halfway through.
#include <cstdint>
#include <optional>
#include <string>

namespace isurface {

// MemAvailable plus SwapFree of a /proc/meminfo text, bytes; nullopt when it names neither.
std::optional<std::uint64_t> availableMemoryIn(const std::string& meminfo);

// The same for this machine now; nullopt where /proc/meminfo cannot be read.
std::optional<std::uint64_t> availableMemory();

// Throws InputError naming `file` when `bytes` (what `what` needs in memory) exceed `available`.
void requireMemory(const std::string& file, const std::string& what, std::uint64_t bytes,
                   std::optional<std::uint64_t> available);

}  // namespace isurface
