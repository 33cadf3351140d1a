#pragma once
// What `analyze --png` draws: the map of speed inconsistency with the worst line glowing.
#include <string>

#include "isurface/analysis/quality_regions.h"
#include "isurface/map/quality_map.h"

namespace isurface::cli {

struct AnalysisPicture {
  vis::QualityMap& map;
  const Trajectory& samples;
  const QualityReport& report;
  std::string png;
};

// Renders the picture to its PNG (VTK and OSMesa: isurface-cli-all).
void paintAnalysis(const AnalysisPicture& picture);

}  // namespace isurface::cli
