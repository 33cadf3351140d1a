// Files another process cuts short while they are mapped and read: a clear error naming the
// file, never a SIGBUS that kills the process (and leaves its temporary output behind).
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "isurface/base/shrink_guard.h"
#include "isurface/gcode/gcode_stream.h"
#include "isurface/io/biip.h"
#include "isurface/io/trajectory_loading.h"
#include "isurface/machine/machine.h"
#include "isurface/workflow/simulation_dump.h"
#include "scratch_files.h"
#include "test_support.h"

using namespace isurface;
using isurface::test::writeScratch;

namespace {

std::string rasterProgram(int lines) {
  std::string text = "G21 G90 G1 F3000\n";
  for (int i = 0; i < lines; ++i) text += "X" + std::to_string(i % 2 ? 0 : 50) + " Y" + std::to_string(i * 0.5) + "\n";
  return text + "M2\n";
}

// Cuts the file to `keep` bytes the first time moves arrive, as another program would.
class TruncatingSink : public MoveSink {
 public:
  TruncatingSink(std::string path, off_t keep) : path_(std::move(path)), keep_(keep) {}
  void consume(const Move*, std::size_t, std::uint64_t) override {
    if (!done_) {
      ASSERT_EQ(::truncate(path_.c_str(), keep_), 0);
    }
    done_ = true;
  }

 private:
  std::string path_;
  off_t keep_;
  bool done_ = false;
};

}  // namespace

TEST(ShrinkGuard, APageCutAwayReadsAsZerosAndIsReported) {
  const long page = ::sysconf(_SC_PAGESIZE);
  const std::string path = writeScratch("shrinking.bin", std::string(3 * page, 'x'));
  const int fd = ::open(path.c_str(), O_RDONLY);
  ASSERT_GE(fd, 0);
  void* map = ::mmap(nullptr, 3 * page, PROT_READ, MAP_PRIVATE, fd, 0);
  ::close(fd);
  ASSERT_NE(map, MAP_FAILED);
  {
    const ShrinkGuard guard(map, 3 * page);
    EXPECT_EQ(static_cast<const volatile char*>(map)[2 * page], 'x');
    EXPECT_FALSE(guard.shrank());
    ASSERT_EQ(::truncate(path.c_str(), page), 0);
    EXPECT_EQ(static_cast<const volatile char*>(map)[page + 10], 0);  // a SIGBUS without the guard
    EXPECT_EQ(static_cast<const volatile char*>(map)[0], 'x');
    EXPECT_TRUE(guard.shrank());
  }
  ::munmap(map, 3 * page);
}

TEST(FileCutShort, GcodeReadWhileAnotherProgramTruncatesItIsAnError) {
  const std::string path = writeScratch("cut-short.nc", rasterProgram(400000));
  TruncatingSink sink(path, 4096);
  const StreamedInterpretation r = interpretGcodeFileStream(path, sink, InterpreterOptions{}, 1024);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_NE(r.errors.front().message.find("cut short while it was read"), std::string::npos) << r.errors.front().str();
  EXPECT_EQ(r.errors.front().file, path);
}

TEST(FileCutShort, DumpTruncatedAfterOpeningIsRefusedWhenLoaded) {
  const std::string program = writeScratch("dump-source.nc", rasterProgram(200));
  const std::string dump = (isurface::test::scratchDir() / "cut-short.biip").string();
  ASSERT_TRUE(simulateGcodeFileToBiip(program, defaultMachine(), dump, InterpreterOptions{}).interpretation.ok());
  const BiipReader reader(dump);
  ASSERT_EQ(::truncate(dump.c_str(), static_cast<off_t>(reader.header().headerBytes) + 4096), 0);
  try {
    loadTrajectory(reader);
    FAIL() << "a dump cut short was loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cut short while it was read"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cut-short.biip"), std::string::npos) << e.what();
  }
}
