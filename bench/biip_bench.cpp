// Biip throughput: writing and reading 10 million records, and the kinematics summary over them.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "isurface/io/biip.h"
#include "isurface/analysis/kinematics.h"

namespace {

constexpr std::size_t kRecords = 10'000'000;

// line + x y z + fb_x fb_y fb_z + feed: 64-byte records.
const std::vector<isurface::BiipChannel>& channels() {
  static const auto c = isurface::BiipWriter::layout({{"line", isurface::BiipType::U32},
                                                      {"x", isurface::BiipType::F64},
                                                      {"y", isurface::BiipType::F64},
                                                      {"z", isurface::BiipType::F64},
                                                      {"fb_x", isurface::BiipType::F64},
                                                      {"fb_y", isurface::BiipType::F64},
                                                      {"fb_z", isurface::BiipType::F64},
                                                      {"feed", isurface::BiipType::F64}});
  return c;
}

const std::string& benchPath() {
  static const std::string path = "/tmp/isurface-biip-bench-" + std::to_string(::getpid()) + ".biip";
  return path;
}

struct Record {
  std::uint32_t line, pad;
  double x, y, z, fbX, fbY, fbZ, feed;
};
static_assert(sizeof(Record) == 64, "Record must match the channel layout");

// A circle of radius 40 mm at 1 ms, precomputed so that the benchmark times the writer only.
const std::vector<Record>& sampleRecords() {
  static const std::vector<Record> records = [] {
    std::vector<Record> out(1 << 16);
    for (std::size_t i = 0; i < out.size(); ++i) {
      Record& r = out[i];
      const double t = double(i) * 0.001;
      r.line = static_cast<std::uint32_t>(1 + i / 5000);
      r.pad = 0;
      r.x = 40 * std::cos(0.5 * t);
      r.y = 40 * std::sin(0.5 * t);
      r.z = -0.001 * double(i % 1000);
      r.fbX = r.x - 0.002;
      r.fbY = r.y + 0.001;
      r.fbZ = r.z;
      r.feed = 3000;
    }
    return out;
  }();
  return records;
}

void writeFile() {
  const std::vector<Record>& records = sampleRecords();
  isurface::BiipWriter w(benchPath(), channels(), 0.001, R"({"writer":"biip_bench"})");
  for (std::size_t i = 0; i < kRecords; ++i) w.append(&records[i & (records.size() - 1)]);
  w.commit();
}

void BM_BiipWrite(benchmark::State& state) {
  sampleRecords();
  for (auto _ : state) writeFile();
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRecords));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * kRecords * sizeof(Record)));
}
BENCHMARK(BM_BiipWrite)->Unit(benchmark::kMillisecond)->Iterations(2)->UseRealTime();

// The writer's own cost, without the file system: the same records to /dev/null.
void BM_BiipWriteToDevNull(benchmark::State& state) {
  const std::vector<Record>& records = sampleRecords();
  for (auto _ : state) {
    isurface::BiipWriter w("/dev/null", channels(), 0.001, "");
    for (std::size_t i = 0; i < kRecords; ++i) w.append(&records[i & (records.size() - 1)]);
    w.commit();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRecords));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * kRecords * sizeof(Record)));
}
BENCHMARK(BM_BiipWriteToDevNull)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

void BM_BiipReadSumX(benchmark::State& state) {
  if (::access(benchPath().c_str(), R_OK) != 0) writeFile();
  for (auto _ : state) {
    const isurface::BiipReader reader(benchPath());
    const auto x = reader.channel("x");
    double sum = 0;
    for (std::size_t i = 0; i < x.size(); ++i) sum += x[i];
    benchmark::DoNotOptimize(sum);
    if (x.size() != kRecords) state.SkipWithError("wrong record count");
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRecords));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * kRecords * sizeof(Record)));
}
BENCHMARK(BM_BiipReadSumX)->Unit(benchmark::kMillisecond)->Iterations(5)->UseRealTime();

void BM_KinematicsSummaryStreaming(benchmark::State& state) {
  if (::access(benchPath().c_str(), R_OK) != 0) writeFile();
  const isurface::BiipReader reader(benchPath());
  const auto x = reader.channel("x"), y = reader.channel("y"), z = reader.channel("z");
  for (auto _ : state) {
    isurface::KinematicsAccumulator acc(reader.header().cycleSeconds);
    for (std::size_t i = 0; i < x.size(); ++i) acc.push(x[i], y[i], z[i]);
    const auto s = acc.finish();
    benchmark::DoNotOptimize(s.maxJerk);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRecords));
}
BENCHMARK(BM_KinematicsSummaryStreaming)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

void BM_KinematicsSummaryArrays(benchmark::State& state) {
  std::vector<double> x(kRecords), y(kRecords), z(kRecords);
  for (std::size_t i = 0; i < kRecords; ++i) {
    const double t = double(i) * 0.001;
    x[i] = 40 * std::cos(0.5 * t);
    y[i] = 40 * std::sin(0.5 * t);
    z[i] = -0.001 * double(i % 1000);
  }
  for (auto _ : state) {
    const auto s = isurface::summarizeKinematics(x.data(), y.data(), z.data(), nullptr, kRecords, 0.001);
    benchmark::DoNotOptimize(s.maxJerk);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kRecords));
}
BENCHMARK(BM_KinematicsSummaryArrays)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::remove(benchPath().c_str());
  return 0;
}
