#include "isurface/io/trajectory_writing.h"

#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

#include "isurface/io/biip.h"
#include "isurface/base/json_text.h"

namespace isurface {

void writeTrajectoryBiip(const Trajectory& samples, const std::string& path, const std::string& machineJson) {
  using Value = std::function<double(std::size_t)>;
  std::vector<std::pair<std::string, Value>> written;
  const auto channel = [&](const std::string& name, Value value) { written.emplace_back(name, std::move(value)); };
  channel("x", [&](std::size_t i) { return samples.x[i]; });
  channel("y", [&](std::size_t i) { return samples.y[i]; });
  channel("z", [&](std::size_t i) { return samples.z[i]; });
  // Times the source recorded are written as they are; a regular cycle is the header's.
  if (!samples.time.empty()) channel("t", [&](std::size_t i) { return samples.time[i]; });
  if (samples.hasFeedback()) {
    channel("fb_x", [&](std::size_t i) { return samples.feedback(i).x(); });
    channel("fb_y", [&](std::size_t i) { return samples.feedback(i).y(); });
    channel("fb_z", [&](std::size_t i) { return samples.feedback(i).z(); });
  }
  if (samples.hasFeed()) channel("feed", [feed = samples.feed.cursor()](std::size_t i) mutable { return double(feed[i]); });
  for (const auto& [name, v] : samples.extra) channel(name, [&v = v](std::size_t i) { return v[i]; });

  std::vector<std::pair<std::string, BiipType>> names = {{"line", BiipType::U32}};
  for (const auto& [name, value] : written) names.emplace_back(name, BiipType::F64);
  const std::vector<BiipChannel> channels = BiipWriter::layout(names);
  nlohmann::json meta = {{"source", samples.source}, {"units", "mm"}, {"writer", "isurface-cli"},
                         {"coordinates", "workpiece"}};
  if (!machineJson.empty()) meta["machine"] = nlohmann::json::parse(machineJson);
  BiipWriter writer(path, channels, samples.cycle > 0 ? samples.cycle : 0.001, jsonText(meta), samples.startTime);
  std::vector<unsigned char> record(writer.recordBytes());
  RunChannel<std::uint32_t>::Cursor lineOf = samples.line.cursor();
  for (std::size_t i = 0; i < samples.size(); ++i) {
    std::fill(record.begin(), record.end(), 0);
    biipStore(record.data(), channels[0], i < samples.line.size() ? lineOf[i] : 0);
    for (std::size_t c = 0; c < written.size(); ++c) biipStore(record.data(), channels[c + 1], written[c].second(i));
    writer.append(record.data());
  }
  writer.commit();
}

}  // namespace isurface
