#include "isurface/app_model/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace isurface::app_model {
namespace {

constexpr int kPollMs = 50;
constexpr auto kTermGrace = std::chrono::seconds(2);  // after SIGTERM (it removes its temporary files)

// "LABEL NN%": the label and the fraction; false for any other text.
bool parseProgress(const std::string& text, std::string& label, double& fraction) {
  if (text.size() < 3 || text.back() != '%') return false;
  const std::size_t space = text.find_last_of(' ', text.size() - 2);
  if (space == std::string::npos) return false;
  char* end = nullptr;
  const long percent = std::strtol(text.c_str() + space + 1, &end, 10);
  if (end != text.c_str() + text.size() - 1 || percent < 0 || percent > 100) return false;
  label = text.substr(0, text.find_last_not_of(' ', space) + 1);
  fraction = percent / 100.0;
  return true;
}

// The child, reaped whatever happens: stopped (SIGTERM, then SIGKILL) unless it has ended.
class Child {
 public:
  explicit Child(pid_t pid) : pid_(pid) {}
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child() {
    if (!reaped_) stop();
  }

  // Waits for it to end, polling `cancelled` (true: stop it and throw JobCancelled). Its status.
  int wait(JobControl& control) {
    for (;;) {
      const pid_t r = waitpid(pid_, &status_, WNOHANG);
      if (r == pid_ || (r < 0 && errno != EINTR)) {
        reaped_ = true;
        if (r < 0) status_ = -1;  // not ours to wait for: no exit code to trust
        return status_;
      }
      if (control.cancelRequested()) throw JobCancelled{};  // the destructor stops it
      usleep(kPollMs * 1000);
    }
  }

 private:
  void stop() {
    kill(pid_, SIGTERM);
    const auto deadline = std::chrono::steady_clock::now() + kTermGrace;
    for (;;) {
      const pid_t r = waitpid(pid_, &status_, WNOHANG);
      if (r == pid_ || (r < 0 && errno != EINTR)) break;
      if (std::chrono::steady_clock::now() > deadline) {
        kill(pid_, SIGKILL);
        while (waitpid(pid_, &status_, 0) < 0 && errno == EINTR) {
        }
        break;
      }
      usleep(10000);
    }
    reaped_ = true;
  }

  pid_t pid_;
  int status_ = 0;
  bool reaped_ = false;
};

// Starts `argv` with standard error on `errorFd`, nothing on its input and output, and
// ISURFACE_PROGRESS=1 in its environment (so that it prints its progress to a pipe).
pid_t spawn(const std::vector<std::string>& argv, int errorFd) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, errorFd, STDERR_FILENO);
  std::vector<std::string> environment{"ISURFACE_PROGRESS=1"};
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "ISURFACE_PROGRESS=", 18) != 0) environment.emplace_back(*e);
  std::vector<char*> args, env;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  for (const std::string& e : environment) env.push_back(const_cast<char*>(e.c_str()));
  env.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), env.data());
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot run " + argv[0] + ": " + std::strerror(spawned));
  return pid;
}

struct Pipe {
  int fd[2] = {-1, -1};
  ~Pipe() {
    for (int f : fd)
      if (f >= 0) close(f);
  }
};

}  // namespace

ChildOutcome runChildProcess(const std::vector<std::string>& argv, JobControl& control,
                             const std::function<void(const std::string& label, double fraction)>& progress) {
  Pipe errors;
  if (pipe2(errors.fd, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  const pid_t pid = spawn(argv, errors.fd[1]);
  close(errors.fd[1]);
  errors.fd[1] = -1;

  Child child(pid);
  ChildOutcome outcome;
  std::string line;
  // A line read whole (or the last, unended): progress, or a message kept.
  const auto take = [&](std::string& text) {
    std::string label;
    double fraction = 0;
    if (parseProgress(text, label, fraction)) progress(label, fraction);
    else if (!text.empty()) outcome.messages += text + "\n";
    text.clear();
  };
  for (;;) {
    if (control.cancelRequested()) throw JobCancelled{};
    pollfd p{errors.fd[0], POLLIN, 0};
    if (poll(&p, 1, kPollMs) <= 0) continue;
    char buffer[4096];
    const ssize_t n = read(errors.fd[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    for (ssize_t i = 0; i < n; ++i) {
      if (buffer[i] != '\r' && buffer[i] != '\n') line += buffer[i];
      else take(line);
    }
  }
  take(line);
  // Its standard error closed; it may still run for a while (or forever): Cancel still stops it.
  const int status = child.wait(control);
  outcome.exitCode = status >= 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (status >= 0 && WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
  return outcome;
}

std::string siblingExecutable(const std::string& name) {
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return name;
  const std::string path(self, static_cast<std::size_t>(n));
  return path.substr(0, path.rfind('/') + 1) + name;
}

}  // namespace isurface::app_model
