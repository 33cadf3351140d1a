// Degenerate geometry through every command that prints JSON (simulate, info, locate, analyze,
// intervals, fit, optimize), on the programs of the sweep in tests/support/degenerate_cases.h:
// the dump holds no non-finite value, and no JSON may carry "nan", "inf" or a null that stands
// for one.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "degenerate_cases.h"
#include "isurface/io/biip.h"
#include "test_support.h"

namespace fs = std::filesystem;
using isurface::test::runCli;
using isurface::test::scratchDir;

namespace isurface {
namespace {

using test::cases;
using test::countNonFinite;
using test::DegenerateCase;
using test::DegenerateGeometry;

// Every number of a JSON document, with its key path, that is null where a number belongs.
// Nulls the commands print on purpose: an infinite curvature radius (a straight run) and the
// ratios at a section's ends, where there is no neighbour to compare with.
void collectNulls(const nlohmann::json& j, const std::string& path, std::vector<std::string>& out) {
  static const std::set<std::string> intended = {"radius_mm", "distance_ratio", "curvature_ratio"};
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      if (!(it.value().is_null() && intended.count(it.key()))) collectNulls(it.value(), path + "/" + it.key(), out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) collectNulls(j[i], path + "/" + std::to_string(i), out);
  } else if (j.is_null()) {
    out.push_back(path);
  }
}

// Checks a command's JSON output: it parses, holds no nan/inf literal and no unexplained null.
void expectFiniteJson(const std::string& text, const std::string& what) {
  for (const char* word : {"nan", "inf\"", "inf,", "infinity", "-inf"})
    EXPECT_EQ(text.find(word), std::string::npos) << what << " prints " << word << ":\n" << text.substr(0, 2000);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << " is not JSON: " << e.what() << "\n" << text.substr(0, 2000);
    return;
  }
  std::vector<std::string> nulls;
  collectNulls(j, "", nulls);
  EXPECT_TRUE(nulls.empty()) << what << " has null (a non-finite value) at " << nulls.front();
}

TEST_P(DegenerateGeometry, CommandOutputsStayFinite) {
  const DegenerateCase& c = GetParam();
  const fs::path dir = scratchDir() / ("degenerate-" + c.name);
  fs::create_directories(dir);
  const std::string nc = (dir / "in.nc").string(), dump = (dir / "in.biip").string();
  std::ofstream(nc) << c.gcode;

  const auto run = [&](const std::string& args, const std::string& what) {
    const auto r = runCli(args);
    EXPECT_EQ(r.exitCode, 0) << what << ": " << r.err;
    return r;
  };
  expectFiniteJson(run("simulate " + nc + " -o " + dump + " --json", "simulate").out, "simulate --json");
  {
    const BiipReader reader(dump);
    std::vector<double> values(reader.recordCount());
    for (const BiipChannel& channel : reader.header().channels) {
      reader.copyChannel(channel.name, values.data(), 0, values.size());
      EXPECT_EQ(countNonFinite(values), 0u) << "channel " << channel.name << " of the dump";
    }
  }
  const auto info = run("info " + dump, "info");
  expectFiniteJson(info.out, "info");
  EXPECT_NE(info.out.find("\"non_finite_samples\": 0"), std::string::npos) << info.out;
  expectFiniteJson(run("locate " + dump + " --sample 5", "locate").out, "locate");

  const std::string report = (dir / "analyze.json").string();
  run("analyze " + nc + " " + dump + " -o " + report, "analyze");
  expectFiniteJson(isurface::test::readFile(report), "analyze");
  const std::string lines = " --lines 1-100000";
  expectFiniteJson(run("intervals " + nc + lines, "intervals").out, "intervals");
  expectFiniteJson(run("fit " + nc + lines, "fit").out, "fit");
  const std::string compared = (dir / "optimize.json").string();
  run("optimize " + nc + lines + " -o " + (dir / "new.nc").string() + " --report " + compared, "optimize");
  expectFiniteJson(isurface::test::readFile(compared), "optimize --report");
}

INSTANTIATE_TEST_SUITE_P(Sweep, DegenerateGeometry, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace isurface
