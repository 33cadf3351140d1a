#include "isurface/map/quality_map.h"
#include "isurface/map/tool_axes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <future>

#include <fmt/format.h>

#include "isurface/base/diagnostic.h"
#include "isurface/base/units.h"
#include "isurface/gcode/path_segment.h"
#include "isurface/surface/coarse_mesh.h"

namespace isurface::vis {

namespace {

// An end of a range within a rounding error of zero (an inconsistency of 3e-6 mm/min between
// passes that run alike) is the zero it stands for, and is shown so.
ValueRange endsNearZeroAsZero(ValueRange r) {
  const double near = 1e-6 * (r.hi - r.lo);
  if (std::fabs(r.lo) < near) r.lo = 0;
  if (std::fabs(r.hi) < near) r.hi = 0;
  return r;
}

std::string rangeText(const ValueRange& r) {
  return fmt::format("{:.4g} .. {:.4g}", r.lo, r.hi);
}

// A channel's unit from its name's suffix, as the Biip channel names spell them.
std::string channelUnit(const std::string& channel) {
  for (const char* unit : {"um", "mm", "s", "deg", "mm_min", "mm_s2", "mm_s3"}) {
    const std::string suffix = std::string("_") + unit;
    if (channel.size() > suffix.size() && channel.compare(channel.size() - suffix.size(), suffix.size(), suffix) == 0)
      return std::strcmp(unit, "um") == 0 ? "\u00b5m" : unit;  // shown as people write it
  }
  return "";
}

// The inch unit of a length or a rate of one ("" for any other unit).
std::string inchUnitOf(const std::string& mmUnit) {
  if (mmUnit == "mm") return "in";
  if (mmUnit == "mm/min") return "in/min";
  if (mmUnit == "mm/s^2") return "in/s^2";
  if (mmUnit == "mm/s^3") return "in/s^3";
  return "";
}

std::vector<float> scalarsFor(const QualityMapRequest& request, const Trajectory& samples, const SurfaceMesh& mesh) {
  if (request.sampleValues) {
    const std::vector<float>& values = *request.sampleValues;
    if (values.size() != samples.size())
      throw InputError(Diagnostic{samples.source, 0, 0, "per-sample values do not match the samples"});
    std::vector<float> out(mesh.vertexSample.size());
    for (std::size_t v = 0; v < out.size(); ++v) out[v] = values[mesh.vertexSample[v]];
    return out;
  }
  if (request.channel.empty()) return vertexQuantity(request.quantity, samples, mesh);
  auto values = vertexExtraChannel(samples, mesh, request.channel);
  if (!values) throw InputError(Diagnostic{samples.source, 0, 0, "the samples have no channel '" + request.channel + "'"});
  return std::move(*values);
}

// The request's values are lengths or rates of them that it asks to see in inches.
bool shownInInch(const QualityMapRequest& request) {
  if (!request.inch || request.sampleValues) return false;
  const std::string unit = request.channel.empty() ? quantityInfo(request.quantity).unit : channelUnit(request.channel);
  return !inchUnitOf(unit).empty();
}

void toInch(std::vector<float>& values) {
  for (float& v : values) v = static_cast<float>(v / kMmPerInch);
}

}  // namespace

std::shared_ptr<const SurfaceMesh> figuresMesh(const Trajectory& samples, const QualityMap& map) {
  const std::size_t stride = strideWithin(map.passes, kFiguresVertices);
  if (map.mesh && strideWithin(map.passes, map.request.maxVertices) <= stride) return map.mesh;
  MeshOptions options;
  options.feedback = map.request.feedbackSurface;
  options.gapLimit = map.request.gapLimit;
  options.stride = stride;
  return std::make_shared<const SurfaceMesh>(buildSurfaceMesh(samples, map.passes, options));
}

std::vector<float> vertexValuesShown(const QualityMapRequest& request, const Trajectory& samples, const SurfaceMesh& mesh) {
  std::vector<float> values = scalarsFor(request, samples, mesh);
  if (shownInInch(request)) toInch(values);
  return values;
}

std::vector<std::vector<Vec3>> programPolylines(const Program& program) {
  std::vector<std::vector<Vec3>> lines;
  std::vector<Vec3> current;
  auto flush = [&] {
    if (current.size() >= 2) lines.push_back(std::move(current));
    current.clear();
  };
  for (std::size_t i = 0; i < program.moves.size(); ++i) {
    const Move& move = program.moves[i];
    if (!move.isMotion()) continue;
    if (move.kind == MoveKind::Rapid) {
      flush();
      continue;
    }
    const PathSegment seg = PathSegment::from(program, i);
    if (current.empty()) current.push_back(seg.start);
    if (seg.arc && seg.length > 0) {
      // Chord sag r (1 - cos(da / 2)) <= 0.01 mm.
      const double radius = std::max(seg.arcGeometry.startRadius, seg.arcGeometry.endRadius);
      const double step = radius > 0.01 ? 2.0 * std::acos(1.0 - 0.01 / radius) : 0.5;
      const int pieces = std::clamp(static_cast<int>(std::ceil(std::abs(seg.arcGeometry.sweep) / step)), 1, 4096);
      for (int k = 1; k <= pieces; ++k) current.push_back(seg.arcGeometry.at(static_cast<double>(k) / pieces));
    } else {
      current.push_back(seg.end);
    }
  }
  flush();
  return lines;
}

bool needsFeedback(const QualityMapRequest& request) {
  return request.feedbackSurface ||
         (request.channel.empty() && !request.sampleValues && quantityInfo(request.quantity).needsFeedback);
}

std::vector<std::string> surfaceNotes(const Trajectory& samples, const QualityMap& map, const std::string& remedy) {
  std::vector<std::string> notes;
  if (!map.mesh) return notes;
  if (std::string notJoined = passesNotJoined(samples, map.passes, *map.mesh); !notJoined.empty())
    notes.push_back(std::move(notJoined));
  const double share = map.mesh->joinedShare();
  // Once a pattern is chosen, the gap is what is left to try.
  const bool found = map.request.pattern == PathPattern::Auto;
  if (share < kLittleSurfaceShare)
    notes.push_back(fmt::format("only {:.0f} % {} ({} passes, {}{}): {}raise the gap ({})", 100 * share,
                                kLittleSurfaceNote, map.passes.passes.size(), pathPatternName(map.passes.pattern),
                                found ? " as found" : " as chosen",
                                found ? "if the program is a raster or waterlines, choose its pass pattern, or " : "",
                                remedy));
  return notes;
}

QualityMap buildQualityMap(const Trajectory& samples, const Program* program, const QualityMapRequest& request) {
  const QuantityInfo& info = quantityInfo(request.quantity);
  if (needsFeedback(request) && !samples.hasFeedback())
    throw InputError(Diagnostic{samples.source, 0, 0,
                                std::string("no feedback channels (fb_x fb_y fb_z): cannot show ") +
                                    (request.feedbackSurface ? "the feedback surface" : info.label)});
  QualityMap map;
  map.request = request;
  PassOptions passOptions;
  passOptions.program = program;
  passOptions.pattern = request.pattern;
  map.passes = splitPasses(samples, passOptions);
  std::size_t cutting = 0;
  for (const Pass& pass : map.passes.passes) cutting += pass.size();
  if (cutting == 0) throw InputError(Diagnostic{samples.source, 0, 0, kNoCuttingPasses});
  const std::size_t stride = strideWithin(map.passes, request.maxVertices);

  MeshOptions meshOptions;
  meshOptions.feedback = request.feedbackSurface;
  meshOptions.gapLimit = request.gapLimit;
  meshOptions.stride = stride;
  map.mesh = std::make_unique<SurfaceMesh>(buildSurfaceMesh(samples, map.passes, meshOptions));
  if (map.mesh->triangles.empty())
    throw InputError(Diagnostic{samples.source, 0, 0,
                                whyNoTriangles(map.passes, request.gapLimit, map.mesh->foldedStrips())});

  map.data.positions = meshPositions(samples, *map.mesh, request.feedbackSurface);
  map.data.mesh = map.mesh.get();
  map.data.scalars = scalarsFor(request, samples, *map.mesh);
  // The range is taken on the values at the figures' resolution, not the picture's: a map thinned
  // for a small window had another 1-99 % range than the same map in a large one, a report or
  // an export (210 against 225 mm/min on the transition sample).
  std::vector<float> rangeValues;
  const std::size_t figuresStride = strideWithin(map.passes, kFiguresVertices);
  if (!request.fixedRange && stride > figuresStride) {
    MeshOptions figures = meshOptions;
    figures.stride = figuresStride;
    rangeValues = scalarsFor(request, samples, buildSurfaceMesh(samples, map.passes, figures));
  }
  // The picking index is built on a second thread while the rest of the map is made; it reads
  // only the positions and the mesh, which nothing below changes.
  std::future<std::shared_ptr<const SurfaceRayIndex>> rayIndex;
  if (request.pickable)
    rayIndex = std::async(std::launch::async, [&positions = map.data.positions, mesh = map.mesh] {
      return std::shared_ptr<const SurfaceRayIndex>(std::make_shared<SurfaceRayIndex>(positions, mesh));
    });
  if (request.coarseVertices > 0 && cutting > 2 * request.coarseVertices) {
    map.coarseMesh = std::make_unique<SurfaceMesh>(buildCoarseSurfaceMesh(samples, map.passes, meshOptions, request.coarseVertices));
    map.data.coarsePositions = meshPositions(samples, *map.coarseMesh, request.feedbackSurface);
    map.data.coarseMesh = map.coarseMesh.get();
    map.data.coarseScalars = scalarsFor(request, samples, *map.coarseMesh);
  }
  if (request.showToolpath && request.colorToolpath) {
    // The passes as sampled, through the surface's own vertices and values.
    for (std::size_t pass = 0; pass + 1 < map.mesh->passFirstVertex.size(); ++pass) {
      std::vector<Vec3> line;
      std::vector<float> values;
      for (std::size_t v = map.mesh->passFirstVertex[pass]; v < map.mesh->passFirstVertex[pass + 1]; ++v) {
        line.push_back(map.data.positions[v]);
        values.push_back(map.data.scalars[v]);
      }
      map.data.toolpath.push_back(std::move(line));
      map.data.toolpathScalars.push_back(std::move(values));
    }
  } else if (program && request.showToolpath) {
    map.data.toolpath = programPolylines(*program);
  }
  if (request.toolAxes && hasToolAxes(samples)) {
    // A stroke every 1/80 of the surface's size, 1/25 of it long: seen, and the surface between.
    Vec3 lower = Vec3::Constant(INFINITY), upper = Vec3::Constant(-INFINITY);
    for (const Vec3& p : map.data.positions) lower = lower.cwiseMin(p), upper = upper.cwiseMax(p);
    const double size = map.data.positions.empty() ? 1.0 : std::max((upper - lower).norm(), 1e-3);
    map.data.toolAxes = toolAxisMarks(samples, map.passes, size / 80, size / 25);
  }
  if (request.highlightLine) {
    samples.line.forEachRun([&](std::uint32_t line, std::size_t begin, std::size_t end) {
      if (line != *request.highlightLine) return;
      for (std::size_t i = begin; i < end; ++i) {
        const Vec3 p = request.feedbackSurface ? samples.feedback(i) : samples.commanded(i);
        if (p.allFinite()) map.data.highlight.push_back(p);
      }
    });
  }

  MapStyle& style = map.style;
  style.quantityLabel = request.sampleValues ? request.valuesLabel : request.channel.empty() ? info.label : request.channel;
  style.unit = request.sampleValues ? request.valuesUnit : request.channel.empty() ? info.unit : channelUnit(request.channel);
  if (shownInInch(request)) {
    // Before the range is taken: a fixed range is given in the units shown.
    toInch(map.data.scalars);
    toInch(rangeValues);
    toInch(map.data.coarseScalars);
    for (std::vector<float>& values : map.data.toolpathScalars) toInch(values);
    style.unit = inchUnitOf(style.unit);
  }
  const bool signedValues = !request.sampleValues && request.channel.empty() && isSignedQuantity(request.quantity);
  style.colorMap = resolveColorMap(request.colorMap, signedValues);
  const std::vector<float>& ranged = rangeValues.empty() ? map.data.scalars : rangeValues;
  if (request.fixedRange) style.range = *request.fixedRange;
  else if (request.lowPercent <= 0 && request.highPercent >= 100) style.range = fullRange(ranged);
  else style.range = percentileRange(ranged, request.lowPercent, request.highPercent);
  if (!request.fixedRange) style.range = endsNearZeroAsZero(style.range);
  // The diverging map "auto" chose has its middle colour at zero: the range is made symmetric.
  if (!request.fixedRange && request.colorMap == kAutoColorMap && signedValues) {
    const double reach = std::max(std::fabs(style.range.lo), std::fabs(style.range.hi));
    if (reach > 0 && std::isfinite(reach)) style.range = ValueRange{-reach, reach};
  }
  style.view = request.view;
  style.showToolpath = request.showToolpath;
  style.passWires = request.passWires;
  style.showToolAxes = request.toolAxes;
  style.isoBands = request.isoBands;
  // A range too narrow for colours (see isNarrowRange) would only trace rounding noise with
  // iso-lines: a 100 M-sample raster at a constant F600 came out in stripes along the passes.
  if (!request.fixedRange && isNarrowRange(style.range)) {
    style.range = widenNarrowRange(style.range);
    style.isoBands = 0;
  }
  std::string rangeKind = request.fixedRange ? "fixed" : (request.lowPercent <= 0 && request.highPercent >= 100)
                                                             ? "full"
                                                             : fmt::format("{:g}-{:g}%", request.lowPercent, request.highPercent);
  style.caption = fmt::format("{}{}{} [{}] on the {} surface\nrange {} ({}), {} {} passes",
                              request.caption, request.caption.empty() ? "" : "\n", style.quantityLabel, style.unit,
                              request.feedbackSurface ? "feedback" : "commanded", rangeText(style.range), rangeKind,
                              map.passes.passes.size(), pathPatternName(map.passes.pattern));
  if (request.highlightLine)
    style.caption += fmt::format("\nline {}: {} samples", *request.highlightLine, map.data.highlight.size());
  if (rayIndex.valid()) map.rayIndex = rayIndex.get();
  return map;
}

}  // namespace isurface::vis
