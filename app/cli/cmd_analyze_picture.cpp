// analyze --png: the map of speed inconsistency, the worst line of the worst region glowing.
#include "analysis_picture.h"

#include "isurface/vis/offscreen_render.h"
#include "isurface/vis/quality_scene.h"

namespace isurface::cli {

void paintAnalysis(const AnalysisPicture& picture) {
  const QualityReport& report = picture.report;
  const QualityRegion* worst = worstRegionInsidePasses(report);
  if (!worst && !report.regions.empty()) worst = &report.regions.front();
  vis::QualityMap& map = picture.map;
  if (worst) {
    // The worst line of the most severe region that re-fitting can improve glows.
    const std::uint32_t line = picture.samples.line[worst->worstSample];
    picture.samples.line.forEachRun([&](std::uint32_t l, std::size_t begin, std::size_t end) {
      if (l == line)
        for (std::size_t i = begin; i < end; ++i) map.data.highlight.push_back(picture.samples.commanded(i));
    });
  }
  vis::QualityScene scene(map.data, map.style);
  vis::renderSceneToPng(scene, 1600, 1000, picture.png);
}

}  // namespace isurface::cli
