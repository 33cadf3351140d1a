#pragma once
// The quality report of one program: a self-contained HTML document (summary, quality maps,
// the worst regions with a crop of the map, their G-code and the speed over them, how close
// each axis came to its limits; a second run or a re-optimisation beside it when asked) and
// its figures as JSON. The command line and the window's File > Export report both make it.
#include <cstddef>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "isurface/base/progress.h"
#include "isurface/optimise/region_optimizer.h"
#include "isurface/workflow/run_inputs.h"

namespace isurface::report {

enum class ReportOptimisation {
  None,
  WorstRegion,  // optimize --auto
  AllPasses,    // optimize --all
};

struct ReportOptions {
  int regions = 5;  // worst regions shown, 0 to kMostRegions
  // Another run of the same program (a second machine's dump, a trace): maps side by side, the
  // speed difference and the figures of both.
  std::optional<OpenedRun> compared;
  ReportOptimisation optimisation = ReportOptimisation::None;
  double chordTolerance = kDefaultChordTolerance;  // mm, of the re-fitted moves when optimising
  double gapLimit = MeshOptions{}.gapLimit;         // mm: passes further apart make no surface
};

constexpr int kMostRegions = 50;

struct ProgramReport {
  std::string html;
  nlohmann::json figures;  // summary, regions, axes (and comparison, optimisation)
  std::size_t maps = 0;    // quality maps drawn (crops and plots not counted)
  std::size_t regionsFound = 0;
};

// `run` as the workflow opened it (a dump read or the program simulated). Progress 0..1;
// throwing from it cancels (nothing is kept). InputError for a run with nothing to report.
ProgramReport buildProgramReport(const OpenedRun& run, const ReportOptions& options,
                                 const ProgressCallback& progress = {});

}  // namespace isurface::report
