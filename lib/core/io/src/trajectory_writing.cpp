#include "isurface/io/trajectory_writing.h"

#include <nlohmann/json.hpp>
#include <vector>

#include "isurface/io/biip.h"

namespace isurface {

void writeTrajectoryBiip(const Trajectory& samples, const std::string& path) {
  std::vector<std::pair<std::string, BiipType>> names = {
      {"line", BiipType::U32}, {"x", BiipType::F64}, {"y", BiipType::F64}, {"z", BiipType::F64}};
  std::vector<const std::vector<double>*> values = {&samples.x, &samples.y, &samples.z};
  // Times the source recorded are written as they are; a regular cycle is the header's.
  if (!samples.time.empty()) names.emplace_back("t", BiipType::F64), values.push_back(&samples.time);
  if (samples.hasFeedback())
    for (const auto& [name, v] : {std::pair{"fb_x", &samples.fbX}, {"fb_y", &samples.fbY}, {"fb_z", &samples.fbZ}})
      names.emplace_back(name, BiipType::F64), values.push_back(v);
  for (const auto& [name, v] : samples.extra) names.emplace_back(name, BiipType::F64), values.push_back(&v);
  if (samples.hasFeed()) names.emplace_back("feed", BiipType::F64);  // the last channel
  const std::vector<BiipChannel> channels = BiipWriter::layout(names);
  const nlohmann::json meta = {{"source", samples.source}, {"units", "mm"}, {"writer", "isurface-cli"},
                               {"coordinates", "workpiece"}};
  BiipWriter writer(path, channels, samples.cycle > 0 ? samples.cycle : 0.001, meta.dump(), samples.startTime);
  std::vector<unsigned char> record(writer.recordBytes());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    std::fill(record.begin(), record.end(), 0);
    biipStore(record.data(), channels[0], i < samples.line.size() ? samples.line[i] : 0);
    for (std::size_t c = 0; c < values.size(); ++c) biipStore(record.data(), channels[c + 1], (*values[c])[i]);
    if (samples.hasFeed()) biipStore(record.data(), channels.back(), double(samples.feed[i]));
    writer.append(record.data());
  }
  writer.commit();
}

}  // namespace isurface
