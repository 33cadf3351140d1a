#include "fuzz_support.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "isurface/io/biip.h"
#include "isurface/surface/passes.h"
#include "isurface/analysis/quantities.h"
#include "isurface/surface/surface_mesh.h"
#include "isurface/io/trajectory_writing.h"
#include "isurface/io/trajectory_loading.h"

namespace isurface::fuzz {
namespace {

std::string scratchDirectory() {
  const char* dir = std::getenv("TMPDIR");
  return dir && *dir ? dir : "/tmp";
}

// Removed at exit; a crash leaves them behind under a name that says where they came from.
// The name is never freed: the exit handler that removes the files runs after static strings
// are destroyed.
const std::string& scratchBase() {
  static const std::string* base = [] {
    auto* b = new std::string(scratchDirectory() + "/isurface-fuzz-" + std::to_string(::getpid()));
    std::atexit([] {
      for (const char* suffix : {".biip", ".txt", ".csv", ".out.biip", ".json"})
        std::remove((scratchBase() + suffix).c_str());
    });
    return b;
  }();
  return *base;
}

}  // namespace

const std::string& writeScratch(const std::uint8_t* data, std::size_t size, const char* suffix) {
  static std::string path;
  path = scratchBase() + suffix;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();  // the fuzzer cannot go on without its scratch file
  if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  return path;
}

void exerciseSamples(const Trajectory& samples) {
  const PassSet passes = splitPasses(samples);
  const SurfaceMesh mesh = buildSurfaceMesh(samples, passes);
  vertexQuantity(Quantity::SpeedInconsistency, samples, mesh);
  vertexQuantity(Quantity::Jerk, samples, mesh);
  if (samples.hasFeedback()) vertexQuantity(Quantity::Deviation, samples, mesh);
}

void roundTripThroughBiip(const Trajectory& samples) {
  const std::string path = scratchBase() + ".out.biip";
  writeTrajectoryBiip(samples, path);
  const BiipReader reader(path);
  loadTrajectory(reader);
}

}  // namespace isurface::fuzz
