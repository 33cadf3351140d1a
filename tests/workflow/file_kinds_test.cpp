// Files told apart by their content: programs, dumps, traces, and what is none of them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "isurface/workflow/file_kinds.h"
#include "isurface/workflow/run_inputs.h"
#include "workflow_fixtures.h"

using namespace isurface;
using namespace isurface::test;

namespace {

std::string written(const std::string& name, const std::string& content) {
  const std::string path = (scratchDir() / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

std::string randomBytes(std::size_t n) {
  std::mt19937 random(7);
  std::string bytes(n, '\0');
  for (char& c : bytes) c = static_cast<char>(random() & 0xff);
  return bytes;
}

std::string kindError(const std::string& path) {
  try {
    fileKind(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(fileKinds, RandomBytesNamedAsADumpAreNotReadAsGcode) {
  const std::string path = written("random.biip", randomBytes(5000));
  EXPECT_NE(kindError(path).find("is not a Biip dump: it does not begin with the bytes 'BIIP'"), std::string::npos)
      << kindError(path);
  OpenRunRequest request;
  request.files = {path, ""};
  try {
    openRun(request);
    ADD_FAILURE() << "opened";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("random.biip"), std::string::npos);
    EXPECT_EQ(std::string(e.what()).find("Bad character"), std::string::npos) << e.what();
  }
}

TEST(fileKinds, BinaryUnderAnyOtherNameIsNamedAsSuch) {
  const std::string path = written("random.nc", randomBytes(5000));
  EXPECT_NE(kindError(path).find("is neither a G-code program, a Biip dump nor a trace"), std::string::npos);
  // A lone end-of-file or tape-control character does not make a program binary.
  EXPECT_EQ(fileKind(written("tape.nc", "%\n\x12O1000\nG0 X1\n%\n\x1a")), FileKind::Program);
}

TEST(fileKinds, ProgramsDumpsAndTracesAreToldApart) {
  EXPECT_EQ(fileKind(sourcePath("samples/transition-surface.nc")), FileKind::Program);
  EXPECT_EQ(fileKind(transitionDump()), FileKind::Dump);
  EXPECT_EQ(fileKind(written("trace.txt", "0 1.5 2.5 -3 12\n1 1.6 2.5 -3 12\n2 1.7 2.5 -3 12\n")),
            FileKind::HalsamplerTrace);
  EXPECT_EQ(fileKind(written("log.txt", "t,x,y,z\n0,1,2,3\n0.001,1.1,2,3\n")), FileKind::CsvTrace);
  const std::string halsampler = realdataPath("linuxcnc_test.halsampler.txt");
  if (fileExists(halsampler)) {
    EXPECT_EQ(fileKind(halsampler), FileKind::HalsamplerTrace);
  }
  const std::string umich = realdataPath("umich_experiment_01.csv");
  if (fileExists(umich)) {
    EXPECT_EQ(fileKind(umich), FileKind::CsvTrace);
  }
}

TEST(fileKinds, ATraceOpensAfterItsProgramAsItsSamples) {
  const std::string program = realdataPath("linuxcnc_test.ngc");
  const std::string trace = realdataPath("linuxcnc_test.halsampler.txt");
  ISURFACE_SKIP_WITHOUT_REALDATA(program, trace);
  const std::vector<RunFiles> runs = pairRunFiles({program, trace});
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].dump, trace);
  OpenRunRequest request;
  request.files = runs[0];
  const OpenedRun run = openRun(request);
  ASSERT_TRUE(run.program && run.samples);
  EXPECT_GT(run.samples->size(), 1000u);
  EXPECT_FALSE(run.machineKnown);
}

TEST(fileKinds, ACsvTraceWithoutPositionColumnsNamesTheImportCommand) {
  const std::string path = written("unnamed.csv", "a,b,c\n1,2,3\n4,5,6\n");
  try {
    readTrace(path, fileKind(path));
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("isurface-cli import csv"), std::string::npos) << e.what();
  }
}

TEST(fileKinds, ProseIsNotAProgram) {
  const std::string readme = written("README.md", "# Programs\n\nThese programs were written by others.\nSee below.\n");
  EXPECT_NE(kindError(readme).find("is not a G-code program"), std::string::npos) << kindError(readme);
  // Programs of many styles are: block numbers, comments first, parameters, O-words, lower case.
  for (const char* text : {"N10 G0 X1\n", "(header)\nG21\n", "#1 = 3\nG1 X#1\n", "o<sub> sub\no<sub> endsub\n",
                           "%\nO1000\ng0 x 1\n", "; note\nX1 Y2\n", "$H\nG0 X0\n"})
    EXPECT_EQ(fileKind(written("styles.nc", text)), FileKind::Program) << text;
  EXPECT_EQ(fileKind(written("empty.nc", "")), FileKind::Program);
  // An empty file of another name is nothing the tool can tell.
  EXPECT_NE(kindError(written("empty.txt", "")).find("is empty"), std::string::npos);
  EXPECT_NE(kindError(written("notes", "\n\n")).find("is empty"), std::string::npos);
  // One of LinuxCNC's parameters is not nothing.
  EXPECT_EQ(fileKind(written("setup", "#<depth> = 2\n")), FileKind::Program);
  // A log with a few lines that read as G-code is still not a program.
  const std::string log = written("run.log", "Starting run 4\nreading part.nc\n(Failed) 2 tests\nsee output\n"
                                             "% complete: 100\ntotal 12.5 s\nexit code 1\n");
  EXPECT_NE(kindError(log).find("2 of its first 7 lines read as G-code"), std::string::npos) << kindError(log);
}

TEST(fileKinds, EveryRealProgramAndSampleIsAProgram) {
  std::vector<std::string> programs;
  for (const char* folder : {"samples"})
    for (const auto& e : std::filesystem::directory_iterator(sourcePath(folder)))
      if (e.path().extension() == ".nc") programs.push_back(e.path().string());
  ASSERT_GE(programs.size(), 3u) << "the bundled samples are missing";
  const std::filesystem::path realdata = realdataPath("");
  if (std::filesystem::is_directory(realdata))
    for (const auto& e : std::filesystem::directory_iterator(realdata)) {
      const std::string ext = e.path().extension().string();
      if (ext == ".nc" || ext == ".ngc" || ext == ".NC") programs.push_back(e.path().string());
    }
  for (const std::string& p : programs) EXPECT_EQ(fileKind(p), FileKind::Program) << p;
}
