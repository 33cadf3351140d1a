// File > Export > report: the active document's quality report (isurface-cli report) made beside
// the window, with its progress in the status bar and Cancel; then saved like any export.
#include <fmt/format.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "inspector_state.h"
#include "isurface/app_model/child_process.h"
#include "isurface/io/atomic_file.h"
#include "isurface/io/whole_file.h"

namespace isurface::panels {

namespace {

// A private folder for the child's files, removed with it.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "isurface-report-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot make a temporary folder for the report");
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};


// Why the report failed, in a line: the child's errors (not its warnings), or how it ended.
std::string failure(const app_model::ChildOutcome& outcome) {
  std::string out;
  std::istringstream lines(outcome.messages);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("error: ", 0) == 0) out += (out.empty() ? "" : " | ") + line.substr(7);
  if (!out.empty()) return out;
  if (outcome.signal != 0) return fmt::format("isurface-cli report was stopped by signal {} ({})", outcome.signal, strsignal(outcome.signal));
  return fmt::format("isurface-cli report ended with exit code {}", outcome.exitCode);
}

}  // namespace

void Inspector::State::startReport(const std::string& path, int regions) {
  Document* doc = activeDocument();
  if (!doc || !doc->samples) {
    status = "nothing to report: open a program or a dump first";
    return;
  }
  std::vector<std::string> arguments = {app_model::siblingExecutable("isurface-cli"), "report"};
  arguments.push_back(doc->programPath.empty() ? doc->dumpPath : doc->programPath);
  if (!doc->programPath.empty() && !doc->dumpPath.empty()) arguments.push_back(doc->dumpPath);
  arguments.insert(arguments.end(), {"--regions", std::to_string(regions)});
  // Its surface joins the passes as the map shown does.
  arguments.insert(arguments.end(), {"--gap-limit", fmt::format("{}", doc->scene ? doc->map.request.gapLimit : settings.gapLimit)});
  // A program simulated here was simulated with the document's machine, and a dump that names
  // none is judged against it: the report's machine is the same.
  const std::string machine = doc->dumpPath.empty() || !doc->machineKnown ? machineDescriptionJson(doc->machine) : "";
  auto result = std::make_shared<JobResult>(WrittenReport{});
  pending = result;
  job.start(kReportJob + doc->name, [result, arguments, machine, path](app_model::JobControl& control) {
    const ScratchFolder scratch;
    std::vector<std::string> argv = arguments;
    if (!machine.empty()) {
      writeFileAtomically(scratch.file("machine.json"), machine);
      argv.insert(argv.end(), {"--machine", scratch.file("machine.json")});
    }
    argv.insert(argv.end(), {"-o", scratch.file("report.html")});
    // The child simulates or reads the run first, then reports: those are a quarter and the rest.
    const app_model::ChildOutcome outcome =
        app_model::runChildProcess(argv, control, [&](const std::string& label, double f) {
          control.progress(label.rfind("reporting", 0) == 0 ? 0.25 + 0.75 * f : 0.25 * f);
        });
    // Exit code 1 is a threshold crossed, which this run does not set; anything else failed.
    if (outcome.exitCode != 0) throw std::runtime_error(failure(outcome));
    WrittenReport& written = std::get<WrittenReport>(*result);
    written.html = readWholeFile(scratch.file("report.html"));
    written.path = path;
  });
}

}  // namespace isurface::panels
