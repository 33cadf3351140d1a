// isurface-cli locate BIIP (--line N | --sample K | --point X,Y,Z): one sample and its motion,
// as JSON. Reads the dump in place: a query on a dump of any size answers at once.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "command.h"
#include "json_output.h"
#include "isurface/base/units.h"
#include "inputs.h"
#include "isurface/io/biip.h"
#include "isurface/analysis/locate.h"
#include "isurface/workflow/locate_in_dump.h"
#include "isurface/base/json_text.h"

namespace isurface::cli {

namespace {


struct LocateOptions {
  std::string file;
  std::optional<std::uint32_t> line;
  std::optional<std::string> sample;  // as typed: a number too large for any type is reported as it was given
  std::optional<std::string> point;
};

[[noreturn]] void inputError(const std::string& message) {
  std::fprintf(stderr, "error: %s\n", message.c_str());
  throw CommandExit{kExitInputError};
}



// "X,Y,Z" in mm.
Vec3 parsePoint(const std::string& text) {
  Vec3 p;
  std::istringstream in(text);
  for (int a = 0; a < 3; ++a) {
    std::string part;
    if (!std::getline(in, part, a < 2 ? ',' : '\n')) inputError("--point needs X,Y,Z in mm, got '" + text + "'");
    std::size_t used = 0;
    try {
      p[a] = std::stod(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    while (used < part.size() && std::isspace(static_cast<unsigned char>(part[used]))) ++used;
    if (used == 0 || used != part.size() || !std::isfinite(p[a]))
      inputError("--point needs X,Y,Z in mm, got '" + text + "'");
  }
  if (in.peek() != EOF) inputError("--point needs X,Y,Z in mm, got '" + text + "'");
  // Far enough for any machine, near enough that distances to it are finite numbers.
  constexpr double kFarthest = 1e9;  // mm, a thousand kilometres
  if (p.cwiseAbs().maxCoeff() > kFarthest)
    inputError(fmt::format("--point {} is out of range: each coordinate must be within {:g} mm of the origin", text,
                           kFarthest));
  return p;
}

Json describeSample(const BiipReader& reader, std::size_t i) {
  const BiipChannelView x = reader.channel("x"), y = reader.channel("y"), z = reader.channel("z");
  const BiipChannelView line = reader.channel("line"), feed = reader.channel("feed");
  const BiipChannelView fx = reader.channel("fb_x"), fy = reader.channel("fb_y"), fz = reader.channel("fb_z");
  const bool feedback = fx.valid() && fy.valid() && fz.valid();
  const Vec3 position(x[i], y[i], z[i]);
  const SampleMotion m = motionAtSample(reader, i);

  Json out;
  out["file"] = reader.path();
  out["sample"] = i;
  out["line"] = line.valid() ? Json(countAt(line, i, reader.path(), "line")) : Json(nullptr);
  out["time_s"] = numberOrNull(reader.timeAt(i));
  out["position"] = triple(position);
  const Vec3 measured = feedback ? Vec3(fx[i], fy[i], fz[i]) : Vec3::Zero();
  out["feedback"] = feedback ? triple(measured) : Json(nullptr);
  out["feed_mm_min"] = feed.valid() ? numberOrNull(feed[i]) : Json(nullptr);
  out["speed_mm_min"] = numberOrNull(mmPerSToMmPerMin(m.speed));
  out["accel_mm_s2"] = numberOrNull(m.accel);
  out["jerk_mm_s3"] = numberOrNull(m.jerk);
  out["velocity_mm_min"] = triple(m.velocity.unaryExpr([](double v) { return mmPerSToMmPerMin(v); }));
  out["acceleration_mm_s2"] = triple(m.acceleration);
  out["jerk_axes_mm_s3"] = triple(m.jerkAxes);
  out["following_error_um"] = feedback ? numberOrNull(1000.0 * (measured - position).norm()) : Json(nullptr);
  return out;
}

int runLocate(const LocateOptions& o) {
  const int given = int(o.line.has_value()) + int(o.sample.has_value()) + int(o.point.has_value());
  if (given != 1) inputError("locate needs exactly one of --line N, --sample K or --point X,Y,Z");
  const std::optional<Vec3> point = o.point ? std::optional<Vec3>(parsePoint(*o.point)) : std::nullopt;
  const BiipReader reader(o.file);
  for (const auto& w : reader.warnings()) std::fprintf(stderr, "warning: %s: %s\n", o.file.c_str(), w.c_str());
  const std::size_t n = reader.recordCount();

  std::size_t sample = 0;
  std::optional<double> distance;
  if (o.sample) {
    const std::string range = n > 0 ? "0.." + std::to_string(n - 1) : std::string("none");
    unsigned long long index = 0;
    const char* first = o.sample->data();
    const char* last = first + o.sample->size();
    const bool negative = first != last && *first == '-';  // a whole number, out of range
    const auto parsed = std::from_chars(first + (negative ? 1 : 0), last, index);
    if (parsed.ec == std::errc::invalid_argument || parsed.ptr != last)
      inputError("--sample '" + *o.sample + "' is not a sample number: " + o.file + " has " + std::to_string(n) +
                 " samples (" + range + ")");
    if (negative || parsed.ec == std::errc::result_out_of_range || index >= n)
      inputError("sample " + *o.sample + " is out of range: " + o.file + " has " + std::to_string(n) + " samples (" +
                 range + ")");
    sample = static_cast<std::size_t>(index);
  } else if (o.line) {
    if (*o.line == 0) inputError("--line 0: G-code lines are numbered from 1");
    if (!reader.hasChannel("line")) inputError(o.file + " has no line channel: samples cannot be traced to lines");
    const auto found = firstSampleOfLine(reader, *o.line);
    if (!found) inputError(o.file + ": line " + std::to_string(*o.line) + " produced no samples");
    sample = *found;
  } else {
    const auto found = nearestSample(reader, *point);
    if (!found) inputError(o.file + " has no sample with a finite position");
    sample = *found;
    const Vec3 at(reader.channel("x")[sample], reader.channel("y")[sample], reader.channel("z")[sample]);
    distance = (at - *point).norm();
  }
  Json out = describeSample(reader, sample);
  if (distance) out["distance_mm"] = *distance;
  const std::string text = jsonText(out, 2) + "\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  if (std::fflush(stdout) != 0) {
    std::fprintf(stderr, "error: cannot write the output\n");
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

Command locateCommand() {
  return Command{"locate", "Find a sample by G-code line, index or nearest point and print its motion as JSON",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<LocateOptions>();
      sub.add_option("file", o->file, "Biip file (Biip.dat or *.biip)")->required();
      sub.add_option("--line", o->line, "the first sample of this G-code line (1-based)");
      sub.add_option("--sample", o->sample, "this sample (0-based)");
      sub.add_option("--point", o->point, "the sample nearest this point, X,Y,Z in mm");
      return [o] { return runLocate(*o); };
    }};
}


}  // namespace isurface::cli
