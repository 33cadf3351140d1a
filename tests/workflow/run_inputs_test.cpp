// Opening programs and dumps, and joining a dump to its program: once, for the CLI and the app.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <limits>

#include "isurface/io/biip.h"
#include "workflow_fixtures.h"

using namespace isurface;
using namespace isurface::test;

namespace {

std::string messageOf(const OpenRunRequest& request) {
  try {
    openRun(request);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(runInputs, FilesArePairedByContentADumpJoiningTheProgramBeforeIt) {
  const std::string dump = transitionDump();
  // A dump named like a program, and a program named like a dump: told apart by their bytes.
  const std::string disguisedDump = (scratchDir() / "dump-named.nc").string();
  const std::string disguisedProgram = (scratchDir() / "program-named.biip").string();
  std::filesystem::copy_file(dump, disguisedDump, std::filesystem::copy_options::overwrite_existing);
  std::ofstream(disguisedProgram) << "G1 X1 F100\n";
  EXPECT_TRUE(isBiipFile(disguisedDump));
  EXPECT_FALSE(isBiipFile(disguisedProgram));
  const auto runs = pairRunFiles({"a.nc", dump, disguisedProgram, disguisedDump, dump});
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0].program, "a.nc");
  EXPECT_EQ(runs[0].dump, dump);
  EXPECT_EQ(runs[1].program, disguisedProgram);
  EXPECT_EQ(runs[1].dump, disguisedDump);
  EXPECT_EQ(runs[2].program, "");
  EXPECT_EQ(runs[2].dump, dump);
}

TEST(runInputs, TheProgramsOwnDumpJoinsAndBringsTheMachineItWasMadeWith) {
  const std::string dump = simulatedDump("transition-surface", slowMachine(), "slow");
  OpenRunRequest request;
  request.files = {sourcePath("samples/transition-surface.nc"), dump};
  const OpenedRun run = openRun(request);
  ASSERT_TRUE(run.program && run.samples);
  EXPECT_EQ(run.samples->size(), BiipReader(dump).recordCount());
  EXPECT_TRUE(run.machineKnown);
  EXPECT_EQ(run.machine.name, "slow test machine");
  EXPECT_DOUBLE_EQ(run.machine.cycle, 0.002);
  EXPECT_DOUBLE_EQ(run.machine.axes[0].maxAcceleration, slowMachine().axes[0].maxAcceleration);
}

TEST(runInputs, ADumpOfAnotherProgramIsRefusedNamingBothFiles) {
  const std::string dump = transitionDump();
  const std::string program = sourcePath("samples/wuzhishan.nc");
  OpenRunRequest request;
  request.files = {program, dump};
  const std::string message = messageOf(request);
  EXPECT_NE(message.find(dump), std::string::npos) << message;
  EXPECT_NE(message.find(program), std::string::npos) << message;
  EXPECT_NE(message.find("transition-surface.nc"), std::string::npos) << message;  // what its metadata names
  request.force = true;
  EXPECT_EQ(messageOf(request), "");
}

TEST(runInputs, ADumpThatNamesNoProgramIsRefusedWhenItsSamplesLeaveThePath) {
  // A trace-like dump (no source in its metadata) of the transition surface, given with another
  // program: its samples lie far from that program's moves.
  OpenRunRequest own;
  own.files = {"", transitionDump()};
  Trajectory samples = *openRun(own).samples;
  samples.source = "";
  const std::string anonymous = (scratchDir() / "anonymous.biip").string();
  writeTrajectoryBiip(samples, anonymous);
  OpenRunRequest request;
  request.files = {sourcePath("samples/wuzhishan.nc"), anonymous};
  const std::string message = messageOf(request);
  EXPECT_NE(message.find("lie farther than"), std::string::npos) << message;
  // With its own program it joins.
  request.files.program = sourcePath("samples/transition-surface.nc");
  EXPECT_EQ(messageOf(request), "");
}

TEST(runInputs, AProgramAloneIsSimulatedWithTheGivenMachine) {
  OpenRunRequest request;
  request.files = {sourcePath("samples/transition-surface.nc"), ""};
  request.machine = slowMachine();
  const OpenedRun run = openRun(request);
  ASSERT_TRUE(run.samples);
  EXPECT_DOUBLE_EQ(run.samples->cycle, 0.002);
  EXPECT_EQ(run.machine.name, "slow test machine");
  // Machining time is first sample to last: n - 1 cycles.
  EXPECT_DOUBLE_EQ(machiningTime(*run.samples), double(run.samples->size() - 1) * 0.002);
}

TEST(runInputs, AHaasProgramReadsAsItsControlReadsIt) {
  // Mastercam output for a Haas control: inch by the control's default (its G20 comes later in
  // some of its programs), Fanuc's G80 that leaves G0-G3 in effect.
  const std::string program = realdataPath("nist_827-9999-904_OP1.NC");
  ISURFACE_SKIP_WITHOUT_REALDATA(program);
  EXPECT_THROW(readProgram(program), InputError);  // RS274/NGC: axis words after G80
  std::vector<std::string> warnings;
  const Program p = readProgram(program, {}, &warnings, loadMachine(sourcePath("resources/machines/fanuc-inch.json")));
  EXPECT_GT(p.moves.size(), 1000u);
  // N106 G0 G90 G54 X5.787 Y-3.4579: inches, in mm.
  EXPECT_NEAR(p.moves[2].end.x(), 5.787 * 25.4, 1e-9);
  EXPECT_NEAR(p.moves[2].end.y(), -3.4579 * 25.4, 1e-9);
  bool lookAhead = false;
  for (const std::string& w : warnings) lookAhead |= w.find("G08 P") != std::string::npos;
  EXPECT_TRUE(lookAhead);
}

TEST(runInputs, ADumpsNonFiniteSamplesAreCountedOnceWhetherLoadedWholeOrThinned) {
  // A dump alone: 1000 records on a line, three of them with a NaN or an infinity.
  const std::string dump = (scratchDir() / "non-finite.biip").string();
  {
    struct Record {
      double x, y, z;
    };
    BiipWriter writer(dump, {{"x", BiipType::F64, 0}, {"y", BiipType::F64, 8}, {"z", BiipType::F64, 16}}, 0.001, "{}");
    for (int i = 0; i < 1000; ++i) {
      Record r{0.01 * i, 0, 0};
      if (i == 10) r.x = std::numeric_limits<double>::quiet_NaN();
      if (i == 11) r.y = std::numeric_limits<double>::infinity();
      if (i == 500) r.z = -std::numeric_limits<double>::infinity();
      writer.append(&r);
    }
    writer.commit();
  }
  const std::string expected = dump + ": 3 samples with non-finite x/y/z are kept out of geometry";
  for (const std::size_t thinning : {std::size_t(1), std::size_t(7)}) {
    OpenRunRequest request;
    request.files = {"", dump};
    request.channels.thinning = thinning;
    const OpenedRun run = openRun(request);
    EXPECT_EQ(std::count(run.warnings.begin(), run.warnings.end(), expected), 1) << "thinning " << thinning;
    // What the reader alone says of the same file.
    const BiipReader reader(dump);
    ASSERT_EQ(reader.warnings().size(), reader.headerWarnings().size() + 1);
    EXPECT_EQ(dump + ": " + reader.warnings().back(), expected);
  }
}
