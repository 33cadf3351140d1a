// isurface-cli optimize: the re-optimised program and its comparison report, bad ranges refused,
// and --auto on the transition sample meeting the paper's acceptance.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

#include "isurface/analysis/quality_figures.h"
#include "isurface/workflow/region_optimisation.h"
#include "isurface/workflow/run_inputs.h"
#include "cam_style_transition.h"
#include "control_machines.h"
#include "scratch_files.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

// The optimiser's gains are shown on a control that brakes at chord junctions, as the paper's NC
// system does (control_machines.h); the default machine's smooths them and leaves little to gain.
std::string onBrakingControl() { return " --machine " + sourcePath(kMachineWithoutChordSmoothing); }

}  // namespace

TEST(regionOptimizer, CommandWritesTheProgramAndTheComparison) {
  const std::string out = (scratchDir() / "optimized.nc").string(), report = (scratchDir() / "cmp.json").string();
  const CommandResult r = runCli("optimize " + sourcePath("samples/transition-surface.nc") + " --lines 105-400 -o " +
                                 out + " --report " + report);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json cmp = nlohmann::json::parse(readFile(report));
  EXPECT_LT(cmp["max_path_distance_mm"].get<double>(), 0.01);
  EXPECT_GE(cmp["passes"].size(), 3u);
  for (const char* part : {"region", "whole_program"})
    for (const char* key : {"samples", "speed_fluctuation_mm_min", "speed_inconsistency_p99_mm_min",
                            "speed_inconsistency_mean_mm_min", "jerk_p99_mm_s3", "predicted_deviation_p99_um"})
      EXPECT_TRUE(cmp[part]["after"].contains(key)) << part << " " << key;
  EXPECT_TRUE(cmp.contains("kept"));
  // The program's size before and after, as the files have it: a cost the user pays.
  auto lines = [](const std::string& path) {
    const std::string text = readFile(path);
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  };
  EXPECT_EQ(cmp["program_lines"]["before"].get<std::size_t>(), lines(sourcePath("samples/transition-surface.nc")));
  if (cmp["kept"].get<bool>()) {
    EXPECT_EQ(cmp["program_lines"]["after"].get<std::size_t>(), lines(out));
  }
  EXPECT_NE(r.out.find(fmt::format("program {} -> {} lines", cmp["program_lines"]["before"].get<std::size_t>(),
                                   cmp["program_lines"]["after"].get<std::size_t>())),
            std::string::npos)
      << r.out;
  EXPECT_EQ(runCli("optimize " + sourcePath("samples/transition-surface.nc") + " --lines 9-1 -o " + out).exitCode, 2);
  EXPECT_EQ(runCli("optimize " + sourcePath("samples/transition-surface.nc") + " --lines 1-5 --auto -o " + out).exitCode, 2);
}

// The progress line (asked for on a pipe, as the window asks) says which candidate is simulated,
// each update a "LABEL NN%" line that a reader parses; no terminal codes down a pipe.
TEST(regionOptimizer, ProgressSaysWhichCandidateIsSimulated) {
  const std::string out = (scratchDir() / "optimized-progress.nc").string();
  const CommandResult r = runShell("ISURFACE_PROGRESS=1 " + std::string(::isurface::test::cliProgram()) + " optimize " +
                                   sourcePath("samples/transition-surface.nc") + " --lines 105-400 -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("\roptimising, candidate 1: each pass its own interval feeds "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\roptimising, candidate 2: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\roptimising 100%\n"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos);
  // Each record: the label, a space, a whole percentage (what the window's reader takes).
  std::size_t records = 0;
  for (std::size_t at = 0; at < r.err.size();) {
    const std::size_t end = std::min(r.err.find_first_of("\r\n", at), r.err.size());
    const std::string record = r.err.substr(at, end - at);
    at = end + 1;
    if (record.find("optimising") != 0) continue;
    ++records;
    ASSERT_EQ(record.back(), '%') << record;
    const std::size_t space = record.find_last_of(' ', record.size() - 2);
    ASSERT_NE(space, std::string::npos) << record;
    const int percent = std::stoi(record.substr(space + 1));
    EXPECT_TRUE(percent >= 0 && percent <= 100) << record;
  }
  EXPECT_GT(records, 3u);
}

// --auto on the bundled transition sample. The re-fitted candidate halves the speed fluctuation
// and the speed difference between neighbouring passes (p99) in the worst region, keeps the
// time and stays within 0.01 mm of the path; whether it is kept is the closed loop's call (no
// figure, the predicted deviation included, may grow by more than 2 %): kept, the output is the
// new program; not kept, it is the old one byte for byte and the report says why.
TEST(regionOptimizerLong, AutoOnTheTransitionSampleHalvesFluctuationAndInconsistency) {
  const std::string input = sourcePath("samples/transition-surface.nc");
  const std::string out = (scratchDir() / "transition-auto.nc").string(), report = (scratchDir() / "auto.json").string();
  const CommandResult r = runCli("optimize " + input + " --auto -o " + out + " --report " + report + onBrakingControl());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json cmp = nlohmann::json::parse(readFile(report));
  const nlohmann::json& before = cmp["region"]["before"];
  const nlohmann::json& after = cmp["region"]["after"];
  EXPECT_GT(before["samples"].get<double>(), 1000);
  EXPECT_GT(after["samples"].get<double>(), 1000);
  EXPECT_LE(after["speed_fluctuation_mm_min"].get<double>(), 0.5 * before["speed_fluctuation_mm_min"].get<double>());
  EXPECT_LE(after["speed_inconsistency_p99_mm_min"].get<double>(),
            0.5 * before["speed_inconsistency_p99_mm_min"].get<double>());
  EXPECT_LE(cmp["machining_time_s"]["after"].get<double>(), cmp["machining_time_s"]["before"].get<double>());
  EXPECT_LT(cmp["max_path_distance_mm"].get<double>(), 0.01);
  // The region is inside the passes (the transition), not where they start and end.
  EXPECT_GT(cmp["compared_box_mm"]["min"][0].get<double>(), 5.0);
  EXPECT_LT(cmp["compared_box_mm"]["max"][0].get<double>(), 75.0);
  if (cmp["kept"].get<bool>()) {
    EXPECT_NE(readFile(out), readFile(input));
  } else {
    EXPECT_EQ(readFile(out), readFile(input));
    EXPECT_FALSE(cmp["reason"].get<std::string>().empty());
    EXPECT_NE(r.out.find("Not kept"), std::string::npos) << r.out;
  }
}

TEST(regionOptimizer, ModesAreExclusiveAndABoxMustCrossThePasses) {
  const std::string program = sourcePath("samples/transition-surface.nc");
  const std::string out = (scratchDir() / "modes.nc").string();
  for (const char* modes : {"--auto --all", "--lines 11-20 --box 0,0,10,10", ""})
    EXPECT_EQ(runCli("optimize " + program + " " + modes + " -o " + out).exitCode, 2) << modes;
  for (const char* box : {"1,2,3", "0,0,0,5", "a,b,c,d", "0,0,5,5,6"})
    EXPECT_EQ(runCli("optimize " + program + " --box " + box + " -o " + out).exitCode, 2) << box;
  const CommandResult outside = runCli("optimize " + program + " --box 500,500,600,600 -o " + out);
  EXPECT_EQ(outside.exitCode, 2);
  EXPECT_NE(outside.err.find("no cutting pass crosses the box"), std::string::npos) << outside.err;
  EXPECT_FALSE(fileExists(out));
}

namespace {

QualityFigures figuresOf(const std::string& nc, double& time) {
  const Program p = readProgram(nc);
  const SurfaceRun run =
      surfaceRun(std::make_shared<const Trajectory>(simulateRun(p, machineWithoutChordSmoothing())), &p);
  time = machiningTime(*run.samples);
  return measureQualityFigures(*run.samples, *run.mesh);
}

// What `optimize PROGRAM MODE` writes is either the program byte for byte, or one that,
// simulated and measured again here (not the report's numbers), is not longer (up to 5 % for
// --objective quality) and no figure of the whole program is worse by more than 2 %; or, for a
// program it cannot treat, nothing at all and an error that names the program.
// RefusedUnjoined: no sample of the region has a neighbouring pass on the surface, so that
// nothing between passes can be measured there (the reason says so).
enum class Outcome { Refused, RefusedUnjoined, Unchanged, Kept, Failed };

Outcome expectNeverWorse(const std::string& program, const std::string& mode) {
  SCOPED_TRACE(program + " " + mode);
  const std::string out = (scratchDir() / "never-worse.nc").string(), report = (scratchDir() / "never-worse.json").string();
  std::filesystem::remove(out);
  std::filesystem::remove(report);
  const CommandResult r =
      runCli("optimize " + program + " " + mode + " -o " + out + " --report " + report + onBrakingControl());
  if (r.exitCode == 2) {
    EXPECT_NE(r.err.find("error: " + program), std::string::npos) << r.err;
    EXPECT_FALSE(fileExists(out));
    return r.err.find("no sample of the region has a neighbouring pass on the surface") != std::string::npos
               ? Outcome::RefusedUnjoined
               : Outcome::Refused;
  }
  EXPECT_EQ(r.exitCode, 0) << r.err;
  if (r.exitCode != 0) return Outcome::Failed;
  const nlohmann::json cmp = nlohmann::json::parse(readFile(report));
  if (!cmp["kept"].get<bool>()) {
    EXPECT_EQ(readFile(out), readFile(program));
    EXPECT_NE(r.err.find("not kept"), std::string::npos) << r.err;
    return Outcome::Unchanged;
  }
  double timeBefore = 0, timeAfter = 0;
  const QualityFigures before = figuresOf(program, timeBefore);
  const QualityFigures after = figuresOf(out, timeAfter);
  const double slack = cmp["objective"] == "quality" ? 0.05 * timeBefore : 0.0;
  EXPECT_LE(timeAfter, timeBefore + slack + 0.0005);
  EXPECT_EQ(worseFigure(before, after, 0.02), "");
  EXPECT_LT(cmp["max_path_distance_mm"].get<double>(), 0.01);
  return Outcome::Kept;
}

bool treated(Outcome outcome) { return outcome != Outcome::Refused && outcome != Outcome::RefusedUnjoined; }

// --box over the middle of the program's feed moves (a quarter of their extent each way, mm),
// --lines over the middle third of its lines; empty when the program cannot be read.
std::vector<std::string> regionModes(const std::string& program) {
  Program p;
  try {
    p = readProgram(program);
  } catch (const InputError&) {
    return {};
  }
  Vec3 lower = Vec3::Constant(1e300), upper = Vec3::Constant(-1e300);
  std::uint32_t lastLine = 0;
  for (const Move& m : p.moves) {
    lastLine = std::max(lastLine, m.line);
    if (m.kind == MoveKind::Rapid || !m.isMotion()) continue;
    lower = lower.cwiseMin(m.end), upper = upper.cwiseMax(m.end);
  }
  std::vector<std::string> modes = {"--lines " + std::to_string(lastLine / 3 + 1) + "-" + std::to_string(2 * lastLine / 3 + 1)};
  if (lower.x() < upper.x() && lower.y() < upper.y()) {
    const Vec3 centre = 0.5 * (lower + upper), reach = 0.125 * (upper - lower);
    modes.push_back(fmt::format("--box {:.4f},{:.4f},{:.4f},{:.4f}", centre.x() - reach.x(), centre.y() - reach.y(),
                                centre.x() + reach.x(), centre.y() + reach.y()));
  }
  return modes;
}

const std::vector<std::string> kEveryMode = {"--all", "--box 20,0,30,27", "--auto", "--auto --objective quality",
                                             "--auto --objective time"};
const std::vector<std::string> kWholeProgramModes = {"--all", "--auto", "--auto --objective quality",
                                                    "--auto --objective time"};

}  // namespace

// Whatever the mode and the objective, what `optimize` writes is never worse than what it was
// given (expectNeverWorse): on a program written as a CAM system writes one
// (tests/support/cam_style_transition.h), every mode, small enough for every run of the suite.
TEST(regionOptimizer, NoModeWritesAWorseCamStyleProgram) {
  const std::string cam = writeScratch("cam-style-transition.nc", isurface::testing::camStyleTransitionProgram());
  for (const std::string& mode : kEveryMode) EXPECT_TRUE(treated(expectNeverWorse(cam, mode))) << mode;
}

// The same on every bundled sample (minutes: label `long`).
TEST(regionOptimizerLong, NoModeWritesAWorseSample) {
  const std::pair<std::string, std::vector<std::string>> cases[] = {
      {sourcePath("samples/transition-surface.nc"), kEveryMode},
      {sourcePath("samples/wuzhishan.nc"), {"--auto", "--all"}},
      {sourcePath("samples/cola-bottle-bottom.nc"), {"--auto"}}};
  for (const auto& [program, modes] : cases)
    for (const std::string& mode : modes) EXPECT_TRUE(treated(expectNeverWorse(program, mode))) << program << " " << mode;
}

#ifndef ISURFACE_SANITIZED
// The same on the programs of ../shared/realdata, written by others, in every mode and
// objective. The small ones in one test. cameo.nc (196 min) --all and --auto, stellabee1.ngc
// (inch, 142 min) --auto here (one test each, so that they run beside the others); the rest of
// those two takes about 13 minutes (every objective simulates every candidate; stellabee1.ngc
// --all about a minute and a quarter) and is run by
// bench/optimize_realdata.sh --every-mode (the DISABLED_ tests below). Of the small programs, the LinuxCNC examples other than
// linuxcnc_test.ngc have no finishing passes (or are inverse-time) and the NIST programs use a
// word iSurface refuses: those are refused with an error, the others never, but for a region
// where nothing between passes can be measured (linuxcnc_test.ngc's box: the outlines of slots
// and circles of a 2D profiling program, no surface).
TEST(regionOptimizerLong, NoModeWritesAWorseSmallRealProgram) {
  ISURFACE_SKIP_WITHOUT_REALDATA(realdataPath("communicator.nc"));
  const std::vector<std::string> treated = {"communicator.nc", "linuxcnc_test.ngc"};
  int kept = 0;
  for (const char* name : {"communicator.nc", "linuxcnc_test.ngc", "linuxcnc_comp.ngc", "linuxcnc_daisy.ngc",
                           "linuxcnc_factorial.ngc", "linuxcnc_flowsnake.ngc", "nist_827-9999-904_FIXT.NC",
                           "nist_827-9999-904_OP1.NC"}) {
    const std::string program = realdataPath(name);
    std::vector<std::string> modes = kWholeProgramModes;
    for (const std::string& region : regionModes(program)) modes.push_back(region);
    const bool isTreated = std::find(treated.begin(), treated.end(), name) != treated.end();
    for (const std::string& mode : modes) {
      const Outcome outcome = expectNeverWorse(program, mode);
      kept += outcome == Outcome::Kept;
      if (isTreated) {
        EXPECT_NE(outcome, Outcome::Refused) << name << " " << mode;
      }
    }
  }
  // Most runs here keep the program (a change that helps by less than kGainRequired is not
  // written): communicator.nc --all and one more are rewritten.
  EXPECT_GE(kept, 2) << "the realdata runs changed nothing: the property was not tested on a new program";
}

static void expectNeverRefused(const std::string& name, const std::vector<std::string>& modes) {
  for (const std::string& mode : modes) EXPECT_TRUE(treated(expectNeverWorse(realdataPath(name), mode))) << mode;
}

const char* const kLongRealPrograms[] = {"cameo.nc", "stellabee1.ngc"};

// One test per mode, so that they run beside each other: each simulates the whole program once per
// candidate (5 minutes here on a slow machine).
TEST(regionOptimizerLong, NoModeWritesAWorseCameo) {
  ISURFACE_SKIP_WITHOUT_REALDATA(realdataPath("cameo.nc"));
  expectNeverRefused("cameo.nc", {"--all"});
}

TEST(regionOptimizerLong, NoModeWritesAWorseCameoAuto) {
  ISURFACE_SKIP_WITHOUT_REALDATA(realdataPath("cameo.nc"));
  expectNeverRefused("cameo.nc", {"--auto"});
}

TEST(regionOptimizerLong, NoModeWritesAWorseStellabee) {
  ISURFACE_SKIP_WITHOUT_REALDATA(realdataPath("stellabee1.ngc"));
  expectNeverRefused("stellabee1.ngc", {"--auto"});
}

TEST(regionOptimizer, DISABLED_NoObjectiveWritesAWorseLongRealProgram) {
  if (fileExists(realdataPath("stellabee1.ngc"))) expectNeverRefused("stellabee1.ngc", {"--all"});
  for (const char* name : kLongRealPrograms)
    if (fileExists(realdataPath(name))) expectNeverRefused(name, {"--auto --objective quality", "--auto --objective time"});
}

TEST(regionOptimizer, DISABLED_NoRegionModeWritesAWorseLongRealProgram) {
  for (const char* name : kLongRealPrograms)
    if (fileExists(realdataPath(name))) expectNeverRefused(name, regionModes(realdataPath(name)));
}
#endif

// The objectives on a program written as a CAM system writes one. Running the smooth re-fitted
// fillets at the programmed feed deepens the servo's deviation there, so the paper's plan is
// not kept. Its bends planned within the servo's deviation, with ramps into and out of them,
// are: the speed is then even and the same from one pass to the next (fluctuation and
// inconsistency at most half of before), and every figure of the region is better; under
// quality, whichever such candidate improves the region most, up to 5 % slower.
// `optimize --auto` on the CAM-style program under `objective`: its report, the program kept.
nlohmann::json camStyleOptimised(const std::string& objective, std::string& cam, std::string& out) {
  cam = writeScratch("cam-" + objective + ".nc", isurface::testing::camStyleTransitionProgram());
  out = (scratchDir() / ("cam-" + objective + "-out.nc")).string();
  const std::string report = (scratchDir() / ("cam-" + objective + ".json")).string();
  EXPECT_EQ(runCli("optimize " + cam + " --auto --objective " + objective + " -o " + out + " --report " + report +
                   onBrakingControl())
                .exitCode,
            0);
  nlohmann::json cmp = nlohmann::json::parse(readFile(report));
  EXPECT_EQ(cmp["objective"], objective);
  EXPECT_TRUE(cmp["kept"].get<bool>()) << cmp["reason"];
  return cmp;
}

TEST(regionOptimizer, ObjectivesChooseAmongTheCandidatesNoneWorse) {
  std::string cam, out;
  const nlohmann::json cmp = camStyleOptimised("quality", cam, out);
  ASSERT_TRUE(cmp["kept"].get<bool>());
  EXPECT_NE(cmp["plan"].get<std::string>().find("bends within the servo's deviation"), std::string::npos) << cmp["plan"];
  EXPECT_NE(cmp["plan"].get<std::string>().find("ramps of"), std::string::npos) << cmp["plan"];
  const nlohmann::json &before = cmp["region"]["before"], &after = cmp["region"]["after"];
  for (const char* figure : {"speed_fluctuation_mm_min", "speed_inconsistency_p99_mm_min", "jerk_p99_mm_s3",
                             "predicted_deviation_p99_um"})
    EXPECT_LT(after[figure].get<double>(), before[figure].get<double>()) << figure;
  for (const char* figure : {"speed_fluctuation_mm_min", "speed_inconsistency_p99_mm_min"})
    EXPECT_LE(after[figure].get<double>(), 0.5 * before[figure].get<double>()) << figure;
  EXPECT_LE(cmp["machining_time_s"]["after"].get<double>(), 1.05 * cmp["machining_time_s"]["before"].get<double>());
  EXPECT_LT(cmp["max_path_distance_mm"].get<double>(), 0.01);
  EXPECT_NE(readFile(out), readFile(cam));
  // Every candidate tried is in the report, the paper's plan first, each with its figures.
  ASSERT_GE(cmp["candidates"].size(), 2u);
  EXPECT_EQ(cmp["candidates"][0]["plan"], "each pass its own interval feeds");
  EXPECT_TRUE(cmp["candidates"][0]["region"].contains("predicted_deviation_p99_um"));
  EXPECT_EQ(runCli("optimize " + cam + " --auto --objective fastest -o " + out).exitCode, 2);
}

// The first goal, on the same program, under the default objective: its bends eased in
// and out of the plane and the slope (eased_path.h) and planned within the servo's deviation,
// the speed in the worst region is half as uneven and half as different from pass to pass, and
// the program is not slower; no figure, in the region or over the whole program, is worse by
// more than 2 %, and the path moves by less than 0.01 mm.
TEST(regionOptimizer, ACamStyleProgramRunsHalfAsUnevenlyInNoMoreTime) {
  std::string cam, out;
  const nlohmann::json cmp = camStyleOptimised("balanced", cam, out);
  ASSERT_TRUE(cmp["kept"].get<bool>());
  EXPECT_NE(cmp["plan"].get<std::string>().find("bends eased in and out"), std::string::npos) << cmp["plan"];
  const nlohmann::json &before = cmp["region"]["before"], &after = cmp["region"]["after"];
  for (const char* figure : {"speed_fluctuation_mm_min", "speed_inconsistency_p99_mm_min"})
    EXPECT_LE(after[figure].get<double>(), 0.5 * before[figure].get<double>()) << figure;
  for (const char* part : {"region", "whole_program"})
    for (const auto& [figure, value] : cmp[part]["before"].items()) {
      if (figure == "samples") continue;
      EXPECT_LE(cmp[part]["after"][figure].get<double>(), 1.02 * value.get<double>()) << part << " " << figure;
    }
  EXPECT_LE(cmp["machining_time_s"]["after"].get<double>(), cmp["machining_time_s"]["before"].get<double>());
  EXPECT_LT(cmp["max_path_distance_mm"].get<double>(), 0.01);
}
