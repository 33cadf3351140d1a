// Interpreter speed and memory on a 1,000,000-line raster program (`G1 X.. Y.. Z..` lines).
//
// The program is generated once into /tmp. Figures: items_per_second = lines per second,
// bytes_per_second = input bytes per second; BM_GcodeMemoryPerMove reports the moves' storage
// (capacity * sizeof(Move) / moves) and the process's resident memory growth per move.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "isurface/gcode/gcode_interpreter.h"

namespace {

constexpr int kLines = 1000000;

// /tmp/isurface-gcode-bench-1M.ngc: a header line, then a zig-zag raster of G1 moves.
const std::string& rasterFile() {
  static const std::string path = [] {
    const std::string target = "/tmp/isurface-gcode-bench-1M.ngc";
    std::error_code ec;
    if (std::filesystem::exists(target, ec) && std::filesystem::file_size(target, ec) > 20000000)
      return target;
    const std::string temp = target + ".tmp" + std::to_string(::getpid());
    {
      std::FILE* f = std::fopen(temp.c_str(), "wb");
      if (!f) return target;
      std::fputs("G21 G90 G17 G94 F1200\n", f);
      for (int i = 1; i < kLines; ++i) {
        const int row = i / 1000, col = i % 1000;
        const double x = 10.0 + 0.089 * (row % 2 ? 999 - col : col);
        const double y = -99.0 + 0.089 * (row % 1000);
        const double z = -1.0 - 0.001 * static_cast<double>((i * 7919LL) % 8999);
        std::fprintf(f, "G1 X%.3f Y%.3f Z%.3f\n", x, y, z);
      }
      std::fclose(f);
    }
    std::filesystem::rename(temp, target, ec);
    return target;
  }();
  return path;
}

long residentBytes() {
  long pages = 0, resident = 0;
  if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
    std::fclose(f);
  }
  return resident * ::sysconf(_SC_PAGESIZE);
}

void BM_GcodeInterpretFile(benchmark::State& state) {
  const std::string& path = rasterFile();
  const auto bytes = static_cast<std::int64_t>(std::filesystem::file_size(path));
  std::size_t moves = 0;
  for (auto _ : state) {
    isurface::InterpretResult r = isurface::interpretGcodeFile(path);
    if (!r.ok()) {
      state.SkipWithError(r.errors[0].str().c_str());
      break;
    }
    moves = r.program.moves.size();
    benchmark::DoNotOptimize(r.program.moves.data());
  }
  state.SetItemsProcessed(state.iterations() * kLines);
  state.SetBytesProcessed(state.iterations() * bytes);
  state.counters["moves"] = static_cast<double>(moves);
  state.counters["s_per_1M_lines"] = benchmark::Counter(
      static_cast<double>(kLines) / 1e6, benchmark::Counter::kIsIterationInvariantRate |
                                             benchmark::Counter::kInvert);
}
BENCHMARK(BM_GcodeInterpretFile)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

void BM_GcodeMemoryPerMove(benchmark::State& state) {
  const std::string& path = rasterFile();
  double storagePerMove = 0, rssPerMove = 0;
  for (auto _ : state) {
    const long before = residentBytes();
    isurface::InterpretResult r = isurface::interpretGcodeFile(path);
    const long after = residentBytes();
    const auto n = static_cast<double>(r.program.moves.size());
    if (n == 0) {
      state.SkipWithError("no moves");
      break;
    }
    storagePerMove = static_cast<double>(r.program.moves.capacity() * sizeof(isurface::Move)) / n;
    rssPerMove = static_cast<double>(after - before) / n;
  }
  state.counters["storage_bytes_per_move"] = storagePerMove;
  state.counters["rss_bytes_per_move"] = rssPerMove;
}
BENCHMARK(BM_GcodeMemoryPerMove)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
