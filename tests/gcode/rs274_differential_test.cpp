// The interpreter against LinuxCNC's rs274 on programs that use parameters and expressions
// (tests/generators/make_expression_programs.py), O-word control flow
// (tests/generators/make_control_flow_programs.py), cutter radius compensation
// (tests/generators/make_cutter_comp_programs.py, with their tool table), subroutines in files of
// their own (subfile-main.ngc calls subfile_square.ngc, which calls subfile_corner.ngc), and the LinuxCNC
// programs of ../shared/realdata: every motion command's end point, in order, as rs274 printed it
// (4 decimals, program units). rs274's output is recorded in tests/data/rs274 so that the
// comparison runs everywhere; where rs274 is installed, it is run again and must still print
// what was recorded. A program rs274 refuses keeps its message in a .error file: the interpreter
// must refuse it too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "gcode_test_support.h"
#include "rs274_canon.h"
#include "isurface/machine/tool_table.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

// The end points of rs274's motion commands, in order, with the G92 / G52 offset rs274 prints
// apart added: iSurface's moves are in the workpiece's coordinates.
std::vector<Vec3> motionEnds(const std::string& canon) {
  std::vector<Vec3> ends;
  for (const Rs274Motion& m : rs274Motions(canon)) ends.push_back(m.end + m.g92Offset);
  return ends;
}

// The tool table rs274 was given for a program (none: every tool of radius 0). rs274 reads a
// tool table in inches.
std::string toolTableOf(const std::string& program) {
  const std::filesystem::path p(program);
  const std::filesystem::path table = p.stem().string().rfind("comp-", 0) == 0
                                          ? p.parent_path() / "comp.tbl"
                                          : std::filesystem::path(sourcePath("tests/data/rs274/realdata")) / (p.stem().string() + ".tbl");
  return std::filesystem::exists(table) ? table.string() : "";
}

std::string errorPath(const std::string& program) {
  return std::filesystem::path(program).replace_extension(".error").string();
}

std::vector<std::string> programs() {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(sourcePath("tests/data/rs274")))
    if (entry.path().extension() == ".ngc") out.push_back(entry.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string canonPath(const std::string& program) {
  return std::filesystem::path(program).replace_extension(".canon").string();
}

// control-20.ngc breaks out of a while loop from inside an if, then runs a do/while loop:
// rs274 2.9.0~pre1 runs that do loop once, as if its `while` began a new loop, where LinuxCNC's
// manual (and this interpreter) run it until its condition fails; gcode_control_flow_test.cpp
// checks the manual's reading on a smaller program.
bool rs274DepartsFromItsManual(const std::string& program) {
  return std::filesystem::path(program).filename() == "control-20.ngc";
}

// Our moves (mm) against rs274's end points (program units: inch in a G20 program).
void expectSameMoves(const std::string& program, const std::string& canon, std::size_t& compared) {
  const std::string text = readFile(program);
  InterpreterOptions options;
  options.subroutinePath.push_back(std::filesystem::path(program).parent_path().string());  // as a file is read
  if (const std::string table = toolTableOf(program); !table.empty())
    options.toolDiameters = readToolTable(table, /*inch=*/true);
  const InterpretResult ours = interpretGcode(text, program, options);
  if (fileExists(errorPath(program))) {
    EXPECT_FALSE(ours.ok()) << program << ": rs274 refuses it: " << readFile(errorPath(program));
    return;
  }
  ASSERT_TRUE(ours.ok()) << ours.errors.front().str();
  std::string upper = text;
  std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
  const double perMm = upper.find("G20") != std::string::npos ? 1 / 25.4 : 1.0;
  std::vector<Vec3> moved;
  for (const Move& m : ours.program.moves)
    if (m.isMotion()) moved.push_back(m.end * perMm);
  const std::vector<Vec3> theirs = motionEnds(readFile(canon));
  ASSERT_EQ(moved.size(), theirs.size()) << program;
  for (std::size_t i = 0; i < theirs.size(); ++i)
    EXPECT_LT((moved[i] - theirs[i]).cwiseAbs().maxCoeff(), 6e-5) << program << " move " << i;  // 4 decimals
  compared += theirs.size();
}

bool rs274Installed() { return std::system("command -v rs274 > /dev/null 2>&1") == 0; }

}  // namespace

TEST(rs274Differential, GeneratedProgramsGiveRs274sMoves) {
  const std::vector<std::string> files = programs();
  ASSERT_GE(files.size(), 40u);
  std::size_t compared = 0;
  for (const std::string& file : files)
    if (!rs274DepartsFromItsManual(file)) expectSameMoves(file, canonPath(file), compared);
  EXPECT_GT(compared, 500u);
}

TEST(rs274Differential, LinuxCncProgramsGiveRs274sMoves) {
  std::size_t compared = 0;
  for (const char* name : {"linuxcnc_factorial", "linuxcnc_flowsnake", "linuxcnc_daisy", "linuxcnc_comp"}) {
    const std::string program = realdataPath(std::string(name) + ".ngc");
    ISURFACE_SKIP_WITHOUT_REALDATA(program);
    expectSameMoves(program, sourcePath("tests/data/rs274/realdata/" + std::string(name) + ".canon"), compared);
  }
  EXPECT_GT(compared, 3000u);
}

TEST(rs274Differential, TheRecordedOutputIsWhatRs274PrintsToday) {
  if (!rs274Installed()) GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
  for (const std::string& file : programs()) {
    const std::string out = (scratchDir() / "live.canon").string();
    const std::string table = toolTableOf(file);
    // rs274 finds subroutine files in its working folder.
    const std::string folder = std::filesystem::path(file).parent_path().string();
    const int status = std::system(("cd '" + folder + "' && rs274 " + (table.empty() ? "" : "-t '" + table + "' ") +
                                    "-g '" + file + "' '" + out + "' < /dev/null > /dev/null 2>&1")
                                       .c_str());
    if (fileExists(errorPath(file))) {
      EXPECT_NE(status, 0) << file << " is recorded as refused";
      continue;
    }
    ASSERT_EQ(status, 0) << file;
    const std::vector<Vec3> live = motionEnds(readFile(out)), recorded = motionEnds(readFile(canonPath(file)));
    ASSERT_EQ(live.size(), recorded.size()) << file;
    for (std::size_t i = 0; i < live.size(); ++i) EXPECT_EQ(live[i], recorded[i]) << file << " move " << i;
  }
}
