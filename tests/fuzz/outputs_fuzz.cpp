// Fuzz target: the commands that write several files (analyze, optimize, sts), run in-process
// as isurface-cli-all runs them, with one of their outputs made impossible to write: a path
// under a regular file (the write fails) or a folder in the output's place (the rename fails).
// Whatever the program, the rule a user relies on must hold: a command that fails leaves none
// of its outputs and no temporary file behind, and one that succeeds leaves its outputs and
// nothing else. A breach aborts (a finding).
//
// Input: byte 0 picks the command, byte 1 the output to block (bit 7: by a folder), the rest
// is the program (analyze, optimize) or, for sts, a surface line and "name value" lines.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "command.h"

namespace fs = std::filesystem;

namespace {

// Stands for the next output's path in a command line (the input's text may be empty, not this).
const std::string kOutput = "\x01output";

struct Run {
  std::vector<std::string> args;
  std::vector<std::string> outputs;  // file names in the output folder
};

// A plain array, not a path: the folder is removed at exit, after static objects are gone.
char workFolderName[64] = "";

fs::path workFolder() {
  if (workFolderName[0] == 0) {
    std::snprintf(workFolderName, sizeof workFolderName, "%s", "/tmp/isurface-outputs-fuzz-XXXXXX");
    if (!mkdtemp(workFolderName)) std::abort();
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(workFolderName, ec);
    });
  }
  return workFolderName;
}

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) std::abort();
}

// sts options from "name value" lines, bounded so that an input stays a small part.
void addStsOptions(std::istringstream& in, Run& run) {
  static const std::map<std::string, std::string> kFlags = {
      {"radius", "--radius"},        {"feed", "--feed"},           {"angle", "--angle-step"},
      {"arc", "--arc-step"},         {"height", "--height-step"},  {"tool", "--tool-radius"},
      {"rho", "--rho-max"},          {"inserted", "--max-inserted"}, {"uniform", "--uniform-nodes"},
      {"samples", "--samples"},      {"discretise", "--discretise"}, {"nodes", "--nodes"},
      {"interp", "--interp"}};
  std::string name, value;
  while (in >> name >> value) {
    const auto flag = kFlags.find(name);
    if (flag == kFlags.end()) continue;
    run.args.push_back(flag->second);
    run.args.push_back(value);
  }
}

Run describe(std::uint8_t command, const std::string& body, const fs::path& folder) {
  Run run;
  const std::string program = (folder / "program.nc").string();
  switch (command % 3) {
    case 0:
      writeFile(program, body);
      run.args = {"analyze", program, "--max-hours", "0.01"};
      run.outputs = {"regions.json", "map.png"};
      run.args.insert(run.args.end(), {"-o", kOutput, "--png", kOutput});
      break;
    case 1:
      writeFile(program, body);
      run.args = {"optimize", program, "--all", "--max-hours", "0.01"};
      run.outputs = {"new.nc", "report.json"};
      run.args.insert(run.args.end(), {"-o", kOutput, "--report", kOutput});
      break;
    default: {
      std::istringstream in(body);
      std::string surface;
      std::getline(in, surface);
      run.args = {"sts", "--surface", surface, "--radius", "2", "--feed", "0.2"};
      addStsOptions(in, run);
      run.outputs = {"part.nc", "errors.json", "nodes.biip"};
      run.args.insert(run.args.end(), {"-o", kOutput, "--report", kOutput, "--biip", kOutput});
    }
  }
  return run;
}

bool isRegularFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const fs::path folder = workFolder();
  std::error_code ec;
  fs::remove_all(folder / "out", ec);
  fs::create_directories(folder / "out");
  const fs::path out = folder / "out";
  Run run = describe(data[0], std::string(reinterpret_cast<const char*>(data) + 2, size - 2), folder);

  // Every output goes to out/; the blocked one under a regular file, or onto a folder.
  const std::size_t blocked = data[1] % 0x80 % (run.outputs.size() + 1);
  const bool byFolder = (data[1] & 0x80) != 0;
  writeFile(out / "blocker", "");
  std::vector<fs::path> destinations;
  for (std::size_t i = 0; i < run.outputs.size(); ++i) {
    fs::path destination = out / run.outputs[i];
    if (i == blocked) {
      if (byFolder) fs::create_directory(destination);
      else destination = out / "blocker" / run.outputs[i];
    }
    destinations.push_back(destination);
  }
  std::size_t next = 0;
  for (std::string& arg : run.args)
    if (arg == kOutput) arg = destinations.at(next++).string();

  std::vector<char*> argv{const_cast<char*>("isurface-cli-all")};
  for (std::string& arg : run.args) argv.push_back(arg.data());
  // The command's progress and messages are not what is under test.
  std::fflush(stderr);
  const int saved = dup(2);
  std::FILE* quiet = std::freopen("/dev/null", "w", stderr);
  const int code = isurface::cli::runCommands(static_cast<int>(argv.size()), argv.data(),
                                              isurface::cli::allCommands());
  std::fflush(stderr);
  dup2(saved, 2);
  close(saved);
  if (!quiet) std::abort();  // stderr could not be silenced: the harness itself is broken

  const bool anyBlocked = blocked < run.outputs.size();
  if (code == 0 && anyBlocked) std::abort();  // an output that cannot be written went unnoticed
  for (std::size_t i = 0; i < run.outputs.size(); ++i) {
    const bool written = isRegularFile(destinations[i]);
    if (code != 0 && written) std::abort();                           // a failed command left an output
    if (code == 0 && !written) std::abort();                          // a success lost one
  }
  // Nothing but the outputs, the blocker and the blocking folder (empty) is left.
  for (const auto& entry : fs::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    if (name == "blocker") continue;
    if (anyBlocked && byFolder && name == run.outputs[blocked]) {
      if (!fs::is_empty(entry.path())) std::abort();
      continue;
    }
    bool isOutput = false;
    for (const std::string& output : run.outputs) isOutput |= name == output;
    if (!isOutput || code != 0) std::abort();  // a temporary or a partial output left behind
  }
  return 0;
}
