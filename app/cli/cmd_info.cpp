// isurface-cli info FILE.biip: what a Biip file holds, as JSON on stdout.
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "command.h"
#include "output_options.h"
#include "json_output.h"
#include "isurface/base/units.h"
#include "isurface/io/atomic_file.h"
#include "isurface/io/biip.h"
#include "isurface/analysis/kinematics.h"
#include "progress.h"
#include "isurface/base/json_text.h"

namespace isurface::cli {

namespace {


nlohmann::ordered_json describe(const BiipReader& reader) {
  const BiipHeader& h = reader.header();
  const std::size_t n = reader.recordCount();
  nlohmann::ordered_json out;
  out["file"] = reader.path();
  out["version"] = std::to_string(h.versionMajor) + "." + std::to_string(h.versionMinor);
  out["record_count"] = n;
  out["cycle_s"] = h.cycleSeconds;
  out["t0_s"] = h.t0Seconds;
  out["duration_s"] = n > 1 ? numberOrNull(reader.timeAt(n - 1) - reader.timeAt(0)) : nlohmann::ordered_json(0.0);
  auto& channels = out["channels"] = nlohmann::ordered_json::array();
  for (const auto& c : h.channels) channels.push_back({{"name", c.name}, {"type", biipTypeName(c.type)}, {"offset", c.offset}});
  out["metadata"] = h.metadataJson.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json::parse(h.metadataJson);

  const BiipChannelView x = reader.channel("x"), y = reader.channel("y"), z = reader.channel("z");
  const BiipChannelView t = reader.channel("t"), line = reader.channel("line");
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
  std::uint64_t firstLine = 0, lastLine = 0, minLine = 0, maxLine = 0;
  KinematicsAccumulator kinematics(h.cycleSeconds, t.valid());
  ProgressLine progress("info");
  for (std::size_t i = 0; i < n; ++i) {
    const double p[3] = {x[i], y[i], z[i]};
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) {
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
      }
    }
    if (t.valid()) requireTimeAdvances(t, i, reader.path());
    kinematics.push(p[0], p[1], p[2], t.valid() ? t[i] : 0.0);
    if (line.valid()) {
      const std::uint64_t l = countAt(line, i, reader.path(), "line");
      if (l != 0) {
        if (firstLine == 0) firstLine = minLine = maxLine = l;
        lastLine = l;
        minLine = std::min(minLine, l);
        maxLine = std::max(maxLine, l);
      }
    }
    if ((i & 0xffff) == 0) progress.update(double(i) / double(n));
  }
  progress.finish();
  const KinematicsSummary k = kinematics.finish();

  if (lo[0] <= hi[0]) {
    out["bounding_box"] = {{"min", {lo[0], lo[1], lo[2]}}, {"max", {hi[0], hi[1], hi[2]}}};
  } else {
    out["bounding_box"] = nullptr;
  }
  if (line.valid() && firstLine != 0) {
    out["line_range"] = {{"first", firstLine}, {"last", lastLine}, {"min", minLine}, {"max", maxLine}};
  } else {
    out["line_range"] = nullptr;
  }
  const bool derived = k.finiteSamples > 0;
  const auto value = [&](double v) { return derived ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr); };
  out["max_speed_mm_min"] = value(mmPerSToMmPerMin(k.maxSpeed));
  out["max_accel_mm_s2"] = value(k.maxAccel);
  out["max_jerk_mm_s3"] = value(k.maxJerk);
  const char* names[3] = {"x", "y", "z"};
  auto& axes = out["axes"] = nlohmann::ordered_json::object();
  for (int a = 0; a < 3; ++a) {
    axes[names[a]] = {{"max_speed_mm_min", value(mmPerSToMmPerMin(k.axis[a].speed))},
                      {"max_accel_mm_s2", value(k.axis[a].accel)},
                      {"max_jerk_mm_s3", value(k.axis[a].jerk)}};
  }
  // Where each path maximum occurs, traced back to its source line when there is one.
  const auto where = [&](std::size_t i) {
    nlohmann::ordered_json at = {{"sample", i}, {"time_s", numberOrNull(reader.timeAt(i))}};
    at["line"] = line.valid() ? nlohmann::ordered_json(countAt(line, i, reader.path(), "line")) : nlohmann::ordered_json(nullptr);
    return at;
  };
  if (derived) {
    out["maxima_at"] = {{"speed", where(k.maxSpeedIndex)}, {"accel", where(k.maxAccelIndex)}, {"jerk", where(k.maxJerkIndex)}};
  } else {
    out["maxima_at"] = nullptr;
  }
  out["non_finite_samples"] = reader.nonFiniteSampleCount();
  out["warnings"] = reader.warnings();
  return out;
}

}  // namespace

Command infoCommand() {
  return Command{"info", "Describe a Biip file: header, channels, extent, line range, speed/acceleration/jerk maxima",
    [](CLI::App& sub) -> std::function<int()> {
      auto file = std::make_shared<std::string>();
      auto output = std::make_shared<std::string>();
      sub.add_option("file", *file, "Biip file (Biip.dat or *.biip)")->required();
      outputOption(sub.add_option("-o,--output", *output, "write the JSON to this file instead of stdout"));
      return [file, output]() {
        const BiipReader reader(*file);
        for (const auto& w : reader.warnings()) std::fprintf(stderr, "warning: %s: %s\n", file->c_str(), w.c_str());
        const std::string text = jsonText(describe(reader), 2) + "\n";
        if (output->empty()) {
          std::fwrite(text.data(), 1, text.size(), stdout);
          if (std::fflush(stdout) != 0) {
            std::fprintf(stderr, "error: cannot write the output\n");
            return kExitFailure;
          }
        } else {
          writeFileAtomically(*output, text);
        }
        return kExitOk;
      };
    }};
}


}  // namespace isurface::cli
