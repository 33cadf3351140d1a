// Simulation throughput: output samples per second of planning + interpolation + servo,
// on one core, into a counting sink and into a Biip file.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>

#include "isurface/nc/simulator.h"
#include "isurface/workflow/simulation_dump.h"

using namespace isurface;

namespace {

// A raster finishing program: passes of 1 mm G1 moves over a wavy surface with arcs at the
// ends of the passes, like CAM output of the paper's parts.
Program rasterProgram(int passes, int movesPerPass) {
  Program p;
  p.source = "raster";
  std::uint32_t line = 1;
  for (int pass = 0; pass < passes; ++pass) {
    const double y = pass * 0.5;
    for (int i = 0; i <= movesPerPass; ++i) {
      const double x = (pass % 2 == 0) ? i : movesPerPass - i;
      Move m;
      m.kind = MoveKind::Linear;
      m.end = Vec3(x, y, 2.0 * std::sin(x * 0.05) * std::cos(y * 0.05));
      m.feed = 3000;
      m.line = line++;
      p.moves.push_back(m);
    }
  }
  return p;
}

class CountingSink : public SampleSink {
 public:
  void consume(const SimSample* samples, std::size_t count) override {
    checksum += samples[count - 1].x;
    total += count;
  }
  double checksum = 0;
  std::uint64_t total = 0;
};

void BM_SimulateToMemory(benchmark::State& state) {
  const Program program = rasterProgram(40, 200);
  const Machine machine = defaultMachine();
  std::uint64_t samples = 0;
  for (auto _ : state) {
    CountingSink sink;
    simulate(program, machine, sink);
    benchmark::DoNotOptimize(sink.checksum);
    samples += sink.total;
  }
  state.counters["samples_per_s"] = benchmark::Counter(static_cast<double>(samples), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimulateToMemory)->Unit(benchmark::kMillisecond);

void BM_SimulateToBiipFile(benchmark::State& state) {
  const Program program = rasterProgram(40, 200);
  const Machine machine = defaultMachine();
  const std::string path = "/tmp/isurface-bench-sim.biip";
  std::uint64_t samples = 0;
  for (auto _ : state) samples += simulateToBiip(program, machine, path).samples;
  std::remove(path.c_str());
  state.counters["samples_per_s"] = benchmark::Counter(static_cast<double>(samples), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimulateToBiipFile)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
