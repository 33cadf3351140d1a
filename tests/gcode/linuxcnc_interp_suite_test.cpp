// LinuxCNC's own interpreter regression tests (tests/interp/ of its repository; a copy in
// ../shared/realdata/linuxcnc-tests-interp/, GPL data read from there and never copied here):
// every milling test that rs274 runs alone (one program, maybe a tool table, no INI file; the
// lathe cycles G70-G76, the Fanuc M98 tests and the plug-in tests left out). Each must be EQUAL
// (the same motion end points as rs274, in order) or REFUSED with an error naming the file and
// the line; a silent difference fails. docs/interpreter-vs-linuxcnc.md lists the results.
//
// Frame: rs274 prints each STRAIGHT_TRAVERSE / STRAIGHT_FEED / ARC_FEED end in the program's
// coordinates of the active G54-G59.3 system, without its rotation, the G92 / G52 offset and the
// tool length offset (SET_G92_OFFSET says the offset), in program units with 4 decimals.
// `isurface-cli canon` prints the same point with the G92 / G52 offset added, in mm. So the
// offset is added to rs274's point and both are compared in program units within 1e-4 (rs274's
// last printed decimal).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <regex>
#include <sstream>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/machine/tool_table.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

struct SuiteTest {
  const char* folder;
  const char* program;
  const char* toolTable;  // "" for none
};

// As each folder's test.sh runs rs274.
const SuiteTest kSuite[] = {
    {"cam-nisley", "cam.ngc", "test.tbl"},
    {"crazy-paths", "test.ngc", ""},
    {"do-while-break", "test.ngc", ""},
    {"exists", "test.ngc", ""},
    {"flowsnake", "flowsnake.ngc", ""},
    {"fractional-linenumbers", "test.ngc", ""},
    {"g10/g10-l1-l10", "test.ngc", "test.tbl"},
    {"g10/g10-l11", "test.ngc", "test.tbl"},
    {"g10/g10-l2-while-active", "test.ngc", ""},
    {"g10/g10-l20-while-active", "test.ngc", ""},
    {"g10/g10-with-g92", "test.ngc", "test.tbl"},
    {"g33.1", "g33.1.ngc", ""},
    {"g52/g52-g92-interaction", "g52-g92-interaction.ngc", ""},
    {"g6164", "test.ngc", ""},
    {"g64-r-planner", "test.ngc", ""},
    {"g81/g17/g98", "g17-g98-g81.ngc", ""},
    {"g81/g17/g99", "g17-g99-g81.ngc", ""},
    {"g81/g18/g98", "g18-g98-g81.ngc", ""},
    {"g81/g18/g99", "g18-g99-g81.ngc", ""},
    {"g81/g19/g98", "g19-g98-g81.ngc", ""},
    {"g81/g19/g99", "g19-g99-g81.ngc", ""},
    {"g84/g17/g98", "g17-g98-g84.ngc", ""},
    {"g84/g17/g99", "g17-g99-g84.ngc", ""},
    {"g84/g18/g98", "g18-g98-g84.ngc", ""},
    {"g84/g18/g99", "g18-g99-g84.ngc", ""},
    {"g84/g19/g98", "g19-g98-g84.ngc", ""},
    {"g84/g19/g99", "g19-g99-g84.ngc", ""},
    {"inside-corners", "test.ngc", ""},
    {"inverse-time-with-comp", "inverse.ngc", ""},
    {"machine-coord-params", "test.ngc", "test.tbl"},
    {"magic_comments/param_format_printing", "test.ngc", ""},
    {"namedparam-bug424", "test.ngc", ""},
    {"oword-bug315", "test.ngc", ""},
    {"oword-bug315-p2", "test.ngc", ""},
    {"return-value", "test.ngc", ""},
    {"rotation/abs-pts", "test.ngc", "test.tbl"},
    {"rotation/g28", "g28.ngc", ""},
    {"rotation/g53", "g53.ngc", ""},
    {"subs-follow-main", "test.ngc", ""},
    {"unit-conversion", "test.ngc", ""},
};

std::string suiteFolder() { return realdataPath("linuxcnc-tests-interp"); }

struct End {
  Vec3 point;   // mm
  double unit;  // mm per program unit when printed
};

// rs274's motion ends, G92 offset added, in mm (with the units they were printed in).
std::vector<End> rs274Ends(const std::string& canon) {
  static const std::regex motion(
      R"((STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|SET_G92_OFFSET|SELECT_PLANE|USE_LENGTH_UNITS)\(([^)]*)\))");
  std::vector<End> ends;
  Vec3 offset = Vec3::Zero();
  int u = 0, v = 1, w = 2;  // the plane's first and second axis, its normal
  double unit = 1;
  std::istringstream in(canon);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, motion)) continue;
    const std::string what = m[1], args = m[2];
    if (what == "USE_LENGTH_UNITS") {
      unit = args.find("INCH") != std::string::npos ? 25.4 : 1.0;
      continue;
    }
    if (what == "SELECT_PLANE") {
      if (args == "CANON_PLANE_XZ") u = 2, v = 0, w = 1;
      else if (args == "CANON_PLANE_YZ") u = 1, v = 2, w = 0;
      else u = 0, v = 1, w = 2;
      continue;
    }
    std::vector<double> n;
    std::istringstream list(args);
    for (std::string a; std::getline(list, a, ',');) n.push_back(std::stod(a));
    Vec3 p;
    if (what == "SET_G92_OFFSET") {
      offset = Vec3(n.at(0), n.at(1), n.at(2));
      continue;
    }
    if (what == "ARC_FEED") {
      p[u] = n.at(0);
      p[v] = n.at(1);
      p[w] = n.at(5);
    } else {
      p = Vec3(n.at(0), n.at(1), n.at(2));
    }
    ends.push_back(End{(p + offset) * unit, unit});
  }
  return ends;
}

bool rs274Installed() { return std::system("command -v rs274 > /dev/null 2>&1") == 0; }

// rs274's output for a test: run as its test.sh runs it, else the folder's `expected`.
// `refused`: rs274 stopped on an error.
std::string oracleOutput(const SuiteTest& t, bool& ran, bool& refused) {
  const std::string folder = suiteFolder() + "/" + t.folder;
  ran = rs274Installed();
  refused = false;
  if (!ran) return readFile(folder + "/expected");
  const std::string out = (scratchDir() / "suite.canon").string();
  const std::string table = *t.toolTable ? std::string("-t ") + t.toolTable + " " : "";
  const std::string command = "cd '" + folder + "' && rs274 " + table + "-g " + t.program + " '" + out +
                              "' < /dev/null > /dev/null 2>&1";
  refused = std::system(command.c_str()) != 0;
  return readFile(out);
}

// Unchecked: rs274 is not installed and the folder's `expected` keeps only rs274's messages.
enum class Outcome { Equal, Refused, Different, Unchecked };

Outcome compare(const SuiteTest& t, std::size_t& moves, std::string& why) {
  const std::string folder = suiteFolder() + "/" + t.folder;
  const std::string program = folder + "/" + t.program;
  bool ran = false, theyRefuse = false;
  const std::vector<End> theirs = rs274Ends(oracleOutput(t, ran, theyRefuse));
  moves = theirs.size();
  InterpreterOptions options;
  options.subroutinePath.push_back(folder);
  if (*t.toolTable) options.toolDiameters = readToolTable(folder + "/" + t.toolTable, /*inch=*/true);  // rs274's units
  const InterpretResult ours = interpretGcode(readFile(program), program, options);
  if (!ours.ok()) {
    const Diagnostic& e = ours.errors.front();
    why = e.str();
    EXPECT_EQ(e.file, program) << why;
    EXPECT_GT(e.line, 0u) << why;
    return Outcome::Refused;
  }
  if (theyRefuse) {
    why = "rs274 refuses it, the interpreter does not";
    return Outcome::Different;
  }
  std::vector<Vec3> mine;
  for (const Move& m : ours.program.moves)
    if (m.isMotion()) mine.push_back(m.end);
  if (!ran && theirs.empty() && !mine.empty()) return Outcome::Unchecked;
  if (mine.size() != theirs.size()) {
    why = std::to_string(mine.size()) + " moves, rs274 " + std::to_string(theirs.size());
    return Outcome::Different;
  }
  for (std::size_t i = 0; i < mine.size(); ++i) {
    const double off = (mine[i] - theirs[i].point).cwiseAbs().maxCoeff() / theirs[i].unit;
    if (off > 1e-4 + 1e-9) {
      why = "move " + std::to_string(i) + " differs by " + std::to_string(off) + " program units";
      return Outcome::Different;
    }
  }
  return Outcome::Equal;
}

}  // namespace

TEST(linuxcncInterpSuite, EveryMillingTestIsEqualOrRefusedWithItsLine) {
  ISURFACE_SKIP_WITHOUT_REALDATA(suiteFolder() + "/cam-nisley/cam.ngc");
  std::size_t equalWithMoves = 0, withMoves = 0;
  for (const SuiteTest& t : kSuite) {
    std::size_t moves = 0;
    std::string why;
    const Outcome outcome = compare(t, moves, why);
    EXPECT_NE(outcome, Outcome::Different) << t.folder << ": a silent difference: " << why;
    if (moves > 0) ++withMoves;
    if (moves > 0 && outcome == Outcome::Equal) ++equalWithMoves;
    static const char* const kSaid[] = {"equal", "refused", "DIFFERENT", "not compared (no rs274)"};
    std::cout << t.folder << ": " << kSaid[static_cast<int>(outcome)]
              << " (" << moves << " moves)" << (why.empty() ? "" : ": " + why) << "\n";
  }
  std::cout << equalWithMoves << " of the " << withMoves << " tests with moves give rs274's moves\n";
  // G93 with compensation and G33.1 are refused (the document says why).
  EXPECT_GE(equalWithMoves, 29u);
}
