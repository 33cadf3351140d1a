#pragma once
// Re-optimising a region of a program, written once for `optimize` and the application's
// Optimise dialog: choose the lines (given, a pass, or the worst predicted region), re-fit
// them, simulate the new program with the same machine, and measure the region before and after.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "isurface/analysis/quality_figures.h"
#include "isurface/analysis/run_comparison.h"
#include "isurface/base/progress.h"
#include "isurface/optimise/region_optimizer.h"

namespace isurface {

// A run as the quality map sees it: samples split into passes, and the surface between them.
struct SurfaceRun {
  std::shared_ptr<const Trajectory> samples;
  PassSet passes;
  std::shared_ptr<const SurfaceMesh> mesh;
  double gapLimit = MeshOptions{}.gapLimit;  // mm: passes further apart were not joined
};

// Splits a program's samples into passes and builds the surface (the program tells rapids
// apart), joining passes up to `gapLimit` mm apart.
SurfaceRun surfaceRun(std::shared_ptr<const Trajectory> samples, const Program* program,
                      double gapLimit = MeshOptions{}.gapLimit);

// The worst region the quality prediction finds inside the passes (as `optimize --auto` takes
// it), with the box of the defect, where it is measured: on a raster, widened to every pass
// joined to its passes on the surface one beside the next; else to whole passes and one more on
// each side. InputError when there is none.
struct ChosenRegion {
  LineRange lines;
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();  // mm, where the figures are measured
  std::size_t vertices = 0;                         // surface vertices of the defect
  LineRange ownPasses;  // the worst region: the lines of the passes it lies on, before any widening
};
ChosenRegion worstRegion(const SurfaceRun& run, const std::string& source);

// The region a box covers (XY, mm): the lines of the surface's samples inside it, widened to
// whole passes and one more on each side, measured inside the box; InputError when it holds none.
ChosenRegion regionInBox(const SurfaceRun& run, const Vec3& lower, const Vec3& upper, const std::string& source);

// Every pass of the program (`optimize --all`): the first to the last line of the surface's
// samples, measured over all of them; InputError when the program has no surface.
ChosenRegion wholeProgramRegion(const SurfaceRun& run, const std::string& source);

// The lines of the pass that holds a sample of `line` (first to last line of its samples);
// nothing when the line is on no pass.
std::optional<LineRange> passOfLine(const SurfaceRun& run, std::uint32_t line);

// What the closed loop chooses for, among candidates no figure of which is worse by more than
// kWorseningAllowed. Balanced: of those not slower, the one whose figures and time improve most
// together. Time: the fastest of them that is not slower. Quality: the one whose figures
// improve most, even if it takes up to kQualitySlowdownAllowed longer.
enum class Objective { Balanced, Time, Quality };

// As the command line and the window name it: "balanced", "time", "quality".
const char* objectiveName(Objective objective);

// How much longer (relative) the program may take under Objective::Quality.
constexpr double kQualitySlowdownAllowed = 0.05;

struct RegionRequest {
  LineRange lines;
  // Where the figures are measured (XY, mm); by default the box of the region's programmed path.
  std::optional<std::pair<Vec3, Vec3>> box;
  OptimizeOptions options;
  Objective objective = Objective::Balanced;
  // Told, as each candidate's simulation starts, which it is ("candidate 5: corners rounded"),
  // for a progress display.
  std::function<void(const std::string&)> onCandidate;
};

struct RegionOptimisation {
  OptimizeResult result;                   // the new text, its passes and new line range
  std::shared_ptr<const Program> program;  // the new program, interpreted
  SurfaceRun after;
  LineRange lines;                         // the region in the old program
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();  // the box measured, mm
  QualityFigures regionBefore, regionAfter;  // in the box, on the region's lines
  QualityFigures wholeBefore, wholeAfter;    // over the whole program
  double timeBefore = 0, timeAfter = 0;    // s, machining time of the whole program
  // s, time spent on the region's lines (the old ones, then their replacement): what a region's
  // gain in time is measured by, a small region's being lost in the whole program's time.
  double regionTimeBefore = 0, regionTimeAfter = 0;
  double maxPathDistance = 0;              // mm, new path to old over the region
  // Lines of the whole program before and after: a program many times longer costs the user
  // (a control's block rate, its transfer), and among candidates that do about as well the
  // shorter is chosen (kSameScoreWithin).
  std::size_t linesBefore = 0, linesAfter = 0;
  // The new program is kept only when it is no slower, its path moved no more than
  // kPathMoveAllowed, no figure, of the region or of the whole program, is worse by more than
  // kWorseningAllowed, and it helps: the time spent on the region's lines or a figure of the
  // region is better by at least kGainRequired; otherwise `reason` says why, and the program
  // stays as it was.
  bool kept = true;
  std::string reason;
  std::string plan;  // the candidate reported: how its interval feeds were planned
  Objective objective = Objective::Balanced;  // the rule it was judged by
  // Every distinct candidate simulated and measured, in the order tried.
  struct Outcome {
    std::string plan;
    bool kept = false;
    std::string reason;
    double timeAfter = 0;  // s
    QualityFigures region, whole;  // after
  };
  std::vector<Outcome> candidates;
};

// How much worse (relative) a figure of the region may get for the new program to be kept.
constexpr double kWorseningAllowed = 0.02;

// mm: how far the new programmed path may lie from the old one for the new program to be kept.
constexpr double kPathMoveAllowed = 0.01;

// How much better (relative) the time or a figure of the region must get for the new program
// to be kept: a change smaller than what a figure may lose is no gain worth a new program.
constexpr double kGainRequired = kWorseningAllowed;

// Why the new program is not kept by the rule above (the time allowed depends on
// r.objective), or nothing when it is.
std::optional<std::string> whyNotKept(const RegionOptimisation& r);

// `text` is the program's source, `program` its interpretation, `before` its run on `machine`.
// Progress: 0..1 over re-fitting and simulating the new program. The candidate is simulated and
// judged (`whyNotKept`); one that is worse is reported, not kept (`kept`, `reason`).
RegionOptimisation optimiseRegion(const std::string& text, const Program& program, const SurfaceRun& before,
                                  const Machine& machine, const RegionRequest& request,
                                  const ProgressCallback& progress = {});

// One line of figures: machining time, speed fluctuation, inconsistency, jerk (mm/min, mm/s^3),
// and, for a candidate that was not kept, why: regionFigures(r) + ". " + regionVerdict(r).
std::string regionSummary(const RegionOptimisation& r);
std::string regionFigures(const RegionOptimisation& r);
// Whether the candidate is kept, under which objective, and why ("Kept (balanced): ...").
std::string regionVerdict(const RegionOptimisation& r);

}  // namespace isurface
