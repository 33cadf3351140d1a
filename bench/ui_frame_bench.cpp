// Interactivity of the application on this machine's software renderer: whole-window frame
// times with a 1,000,000-sample surface at rest and while the camera is dragged (the coarse
// surface shows), and the time from a click on the surface to every panel updated.
// ISURFACE_BENCH_PROGRAM=FILE measures FILE (G-code, simulated on opening, or a dump) instead.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>

#include "isurface/panels/headless_ui.h"

using namespace isurface;

namespace {

constexpr int kWidth = 1600, kHeight = 1000;

// A raster over a wavy surface, 1 mm moves at F3000: about 1,000,000 samples at 1 ms.
std::string writeRaster() {
  const std::string path = "/tmp/isurface-ui-bench-raster.nc";
  std::ofstream out(path);
  out << "G21 G90 G17 G94\nG0 Z5\nG0 X0 Y0\nG1 Z0 F1000\nF3000\n";
  for (int pass = 0; pass < 330; ++pass) {
    const double y = pass * 0.5;
    for (int i = 0; i <= 150; ++i) {
      const double x = pass % 2 == 0 ? i : 150 - i;
      out << "G1 X" << x << " Y" << y << " Z" << 3.0 * std::sin(x * 0.04) * std::cos(y * 0.03) << "\n";
    }
  }
  out << "G0 Z5\nM30\n";
  return path;
}

panels::HeadlessUi& app() {
  static std::unique_ptr<panels::HeadlessUi> ui = [] {
    auto made = std::make_unique<panels::HeadlessUi>(kWidth, kHeight, app_model::Settings{});
    made->frame();  // laid out first, as the window is: the map is made for the view's size
    const char* given = std::getenv("ISURFACE_BENCH_PROGRAM");
    made->inspector().open(given && *given ? std::string(given) : writeRaster());
    made->inspector().waitUntilIdle();
    std::printf("%s\n", made->inspector().statusText().c_str());
    for (int i = 0; i < 3; ++i) made->frame();
    return made;
  }();
  return *ui;
}

// The middle of the 3D view in the fixed layout.
constexpr float kViewX = kWidth * 0.44f, kViewY = kHeight * 0.35f;

void BM_FrameAtRest(benchmark::State& state) {
  panels::HeadlessUi& ui = app();
  ui.mouse(5, kHeight - 5, false);
  for (auto _ : state) ui.frame();
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FrameAtRest)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3);

void BM_FrameWhileRotating(benchmark::State& state) {
  panels::HeadlessUi& ui = app();
  ui.mouse(kViewX, kViewY, false);
  ui.frame();
  ui.mouse(kViewX, kViewY, true);
  ui.frame();
  float dx = 0;
  for (auto _ : state) {
    dx += 3;
    ui.mouse(kViewX + std::fmod(dx, 200.0f), kViewY + 0.3f * std::fmod(dx, 120.0f), true);
    ui.frame();
  }
  ui.mouse(kViewX, kViewY, false);
  ui.frame();
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FrameWhileRotating)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3);

// Press and release without moving: the pick happens on release, and that frame shows the new
// selection in every panel (the 3D scene's glow of the line follows in the next frame).
void BM_PickUpdatesEveryPanel(benchmark::State& state) {
  panels::HeadlessUi& ui = app();
  float offset = 0;
  for (auto _ : state) {
    state.PauseTiming();
    offset = std::fmod(offset + 17, 160);
    ui.mouse(kViewX - 80 + offset, kViewY, false);
    ui.frame();
    ui.mouse(kViewX - 80 + offset, kViewY, true);
    ui.frame();
    state.ResumeTiming();
    ui.mouse(kViewX - 80 + offset, kViewY, false);
    ui.frame();
    state.PauseTiming();
    ui.frame();  // the glow
    state.ResumeTiming();
  }
}
BENCHMARK(BM_PickUpdatesEveryPanel)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3);

}  // namespace

BENCHMARK_MAIN();
