#pragma once
// What the sections of a report share: map images of a fixed size, times as simulate prints
// them, and the table of the independent quality figures of two runs.
#include <optional>
#include <string>
#include <vector>

#include "isurface/analysis/quality_figures.h"
#include "isurface/report/html_document.h"
#include "isurface/map/quality_map.h"
#include "isurface/workflow/run_inputs.h"

namespace isurface::report {

constexpr int kMapWidth = 720, kMapHeight = 450;

// A map of the run as a PNG, its passes joined up to `gapLimit` mm apart; `box` (mm) frames a
// close-up of the surface in the view.
std::string renderMapPng(const OpenedRun& run, vis::QualityMapRequest request, double gapLimit,
                         const std::optional<std::pair<Vec3, Vec3>>& box = std::nullopt);

// "m:ss.mmm (s s)", as simulate prints a machining time.
std::string duration(double seconds);

// Rows of the figures (time, speed fluctuation, inconsistency, jerk, deviation) of a run
// `before` and `after`, with the change in per cent; the JSON of both.
void figuresTable(HtmlDocument& doc, const std::string& beforeName, const std::string& afterName, double timeBefore,
                  double timeAfter, const QualityFigures& before, const QualityFigures& after);
nlohmann::json figuresJson(double time, const QualityFigures& f);

}  // namespace isurface::report
