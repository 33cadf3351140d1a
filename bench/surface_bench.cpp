// From a Biip dump to a coloured surface: loadTrajectory + splitPasses + buildSurfaceMesh +
// vertexQuantity(speed) on 1 and 10 million samples of a raster finishing program.
//
// The dumps are simulated once into /tmp (kept for later runs). Each measurement runs in a
// child process so that its peak resident memory is its own (the mapped dump's pages count).
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "isurface/io/biip.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/surface/passes.h"
#include "isurface/analysis/quantities.h"
#include "isurface/nc/simulator.h"
#include "isurface/surface/surface_mesh.h"
#include "isurface/io/trajectory_loading.h"
#include "isurface/workflow/simulation_dump.h"

using namespace isurface;

namespace {

// A zig-zag raster over a wavy surface: passes of `length` mm in 1 mm G1 moves, 0.5 mm apart,
// at F3000 (about 20 samples per mm at 1 ms).
std::string rasterGcode(int passes, int length) {
  std::string text = "G21 G90 G17\nG0 Z10\nG0 X0 Y0\nG1 Z0 F600\nF3000\n";
  char move[96];
  for (int k = 0; k < passes; ++k) {
    const double y = 0.5 * k;
    for (int i = 0; i <= length; ++i) {
      const double x = k % 2 == 0 ? i : length - i;
      const double z = 2.0 * std::sin(x * 0.05) * std::cos(y * 0.05);
      std::snprintf(move, sizeof move, "G1 X%.4f Y%.4f Z%.4f\n", x, y, z);
      text += move;
    }
  }
  text += "G0 Z10\nM30\n";
  return text;
}

// The dump of about `samples` samples, simulated when it is not there yet.
std::string dumpOf(std::size_t samples) {
  const int length = 200;
  const int passes = static_cast<int>(samples / (20.0 * length)) + 1;
  const std::string path = "/tmp/isurface-surface-bench-" + std::to_string(samples / 1000000) + "M.biip";
  if (std::filesystem::exists(path)) return path;
  const InterpretResult program = interpretGcode(rasterGcode(passes, length), "raster.nc");
  if (!program.ok()) throw std::runtime_error(program.errors.front().str());
  simulateToBiip(program.program, defaultMachine(), path);
  return path;
}

struct Timings {
  double load = 0, split = 0, mesh = 0, quantity = 0;  // s
  double samples = 0, vertices = 0, triangles = 0, passes = 0;
};

double since(std::chrono::steady_clock::time_point& start) {
  const auto now = std::chrono::steady_clock::now();
  const double s = std::chrono::duration<double>(now - start).count();
  start = now;
  return s;
}

Timings pipeline(const std::string& path) {
  Timings t;
  auto clock = std::chrono::steady_clock::now();
  const BiipReader reader(path);
  const Trajectory samples = loadTrajectory(reader);
  t.load = since(clock);
  const PassSet passes = splitPasses(samples);
  t.split = since(clock);
  const SurfaceMesh mesh = buildSurfaceMesh(samples, passes);
  t.mesh = since(clock);
  const std::vector<float> speed = vertexQuantity(Quantity::Speed, samples, mesh);
  t.quantity = since(clock);
  benchmark::DoNotOptimize(speed.data());
  t.samples = double(samples.size());
  t.vertices = double(mesh.vertexSample.size());
  t.triangles = double(mesh.triangles.size());
  t.passes = double(passes.passes.size());
  return t;
}

// Runs the pipeline in a child; returns its timings and peak resident memory (MB).
bool runInChild(const std::string& path, Timings& t, double& peakMB) {
  int fds[2];
  if (pipe(fds) != 0) return false;
  const pid_t child = fork();
  if (child < 0) return false;
  if (child == 0) {
    close(fds[0]);
    const Timings mine = pipeline(path);
    const bool written = write(fds[1], &mine, sizeof mine) == static_cast<ssize_t>(sizeof mine);
    _exit(written ? 0 : 1);
  }
  close(fds[1]);
  const bool read_ = read(fds[0], &t, sizeof t) == static_cast<ssize_t>(sizeof t);
  close(fds[0]);
  int status = 0;
  struct rusage usage {};
  wait4(child, &status, 0, &usage);
  peakMB = double(usage.ru_maxrss) / 1024.0;  // kB on Linux
  return read_ && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

void BM_SurfaceFromDump(benchmark::State& state) {
  const std::string path = dumpOf(static_cast<std::size_t>(state.range(0)));
  Timings t;
  double peakMB = 0;
  for (auto _ : state) {
    if (!runInChild(path, t, peakMB)) {
      state.SkipWithError("the measuring child failed");
      return;
    }
    state.SetIterationTime(t.load + t.split + t.mesh + t.quantity);
  }
  const double total = t.load + t.split + t.mesh + t.quantity;
  state.counters["samples"] = t.samples;
  state.counters["samples_per_s"] = t.samples / total;
  state.counters["load_s"] = t.load;
  state.counters["split_s"] = t.split;
  state.counters["mesh_s"] = t.mesh;
  state.counters["speed_s"] = t.quantity;
  state.counters["passes"] = t.passes;
  state.counters["triangles"] = t.triangles;
  state.counters["peak_rss_MB"] = peakMB;
}
BENCHMARK(BM_SurfaceFromDump)->Arg(1000000)->Arg(10000000)->Iterations(2)->UseManualTime()->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
