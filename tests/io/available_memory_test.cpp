// A dump too large for the machine is refused with a message, not killed halfway by the kernel.
#include "isurface/base/available_memory.h"

#include <gtest/gtest.h>

#include "isurface/base/diagnostic.h"

namespace isurface {
namespace {

TEST(availableMemory, MemoryAndSwapFreeAreAddedUp) {
  const std::string meminfo =
      "MemTotal:       24000000 kB\n"
      "MemFree:         1000000 kB\n"
      "MemAvailable:   12000000 kB\n"
      "Buffers:           20000 kB\n"
      "SwapTotal:       2000000 kB\n"
      "SwapFree:        1500000 kB\n"
      "HugePages_Total:       0\n";
  EXPECT_EQ(availableMemoryIn(meminfo), std::optional<std::uint64_t>((12000000ull + 1500000ull) * 1024));
  EXPECT_EQ(availableMemoryIn("MemTotal: 5 kB\n"), std::nullopt);
  EXPECT_EQ(availableMemoryIn("SwapFree: 0 kB\n"), std::nullopt);  // swap alone says nothing of the memory
  EXPECT_EQ(availableMemoryIn(""), std::nullopt);
  // This machine's own figure is there and is not nothing.
  const std::optional<std::uint64_t> here = availableMemory();
  ASSERT_TRUE(here.has_value());
  EXPECT_GT(*here, 0u);
}

TEST(availableMemory, AContainersLimitBinds) {
  EXPECT_EQ(cgroupRoomIn("8589934592\n", "1073741824\n"), std::optional<std::uint64_t>(7516192768ull));
  EXPECT_EQ(cgroupRoomIn("1000\n", "2000\n"), std::optional<std::uint64_t>(0));
  EXPECT_EQ(cgroupRoomIn("max\n", "1073741824\n"), std::nullopt);
  EXPECT_EQ(cgroupRoomIn("", ""), std::nullopt);
}

TEST(availableMemory, TooLittleIsRefusedNamingTheFileAndTheSizes) {
  EXPECT_NO_THROW(requireMemory("run.biip", "its 10 samples", 360, 1000));
  EXPECT_NO_THROW(requireMemory("run.biip", "its 10 samples", 360, std::nullopt));
  try {
    requireMemory("huge.biip", "its 940000000 samples", 33'840'000'000ull, 20'500'000'000ull);
    FAIL() << "not refused";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("huge.biip"), std::string::npos) << message;
    EXPECT_NE(message.find("its 940000000 samples need 33.8 GB"), std::string::npos) << message;
    EXPECT_NE(message.find("20.5 GB free"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace isurface
