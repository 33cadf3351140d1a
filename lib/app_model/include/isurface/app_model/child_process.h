#pragma once
// Runs another program of the suite (isurface-cli) beside the window, from a background job.
// The window's OpenGL context (GLX) and the headless one that command-line renders use (OSMesa)
// cannot live in one process, so work that renders headless, such as a report, runs in a
// child process. Its standard error is read as it comes: progress lines ("\rLABEL NN%", with
// ISURFACE_PROGRESS=1 in its environment) and, when it fails, its messages.
#include <functional>
#include <string>
#include <vector>

#include "isurface/app_model/background_job.h"

namespace isurface::app_model {

struct ChildOutcome {
  int exitCode = -1;     // the child's exit code; -1 when a signal ended it
  int signal = 0;        // the signal that ended it, if one did
  std::string messages;  // what it wrote on standard error that was not progress
};

// Runs `argv` (argv[0] a path) and waits for it. Each progress line read is handed to
// `progress` (its label and fraction 0..1), which reports to `control`; when the job is
// cancelled the child is stopped (SIGTERM, then SIGKILL) and JobCancelled passed on.
// std::runtime_error when the child cannot be started.
ChildOutcome runChildProcess(const std::vector<std::string>& argv, JobControl& control,
                             const std::function<void(const std::string& label, double fraction)>& progress);

// The path of a program installed or built beside the running one (same folder).
std::string siblingExecutable(const std::string& name);

}  // namespace isurface::app_model
