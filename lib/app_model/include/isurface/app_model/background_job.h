#pragma once
// Long work (loading, simulating, building the surface) off the UI thread, with progress and
// cancellation; the window stays responsive and polls it each frame.
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace isurface::app_model {

// Thrown from a progress callback when the user has cancelled; the job ends quietly.
struct JobCancelled {};

class JobControl {
 public:
  // Records progress (0..1) and throws JobCancelled when cancellation was asked for.
  void progress(double fraction);
  // What the job is doing now, in a few words, shown beside its progress ("candidate 5: ...").
  void stage(std::string text);
  bool cancelRequested() const { return cancel_; }

 private:
  friend class BackgroundJob;
  std::atomic<double> progress_{0};
  std::atomic<bool> cancel_{false};
  mutable std::mutex stageMutex_;
  std::string stage_;
};

class BackgroundJob {
 public:
  BackgroundJob() = default;
  ~BackgroundJob();  // asks to cancel and waits
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  // Runs `work` on a worker thread; `label` names it in the progress bar. A job still running
  // is cancelled and waited for first.
  void start(std::string label, std::function<void(JobControl&)> work);
  void cancel();
  bool running() const { return running_; }
  double progress() const { return control_ ? control_->progress_.load() : 0.0; }
  const std::string& label() const { return label_; }
  std::string stage() const;  // the running job's last JobControl::stage, or ""
  // After the job: the error message if it failed ("" if it succeeded or was cancelled).
  std::string error() const;
  bool wasCancelled() const { return cancelled_; }
  // True once after each job ends (for the UI to take over its result on its own thread).
  bool takeFinished();
  // A job ended and takeFinished() has not been asked since.
  bool finishedPending() const { return finished_; }

 private:
  void join();
  std::string label_;
  std::unique_ptr<JobControl> control_;
  std::thread worker_;
  std::atomic<bool> running_{false}, finished_{false}, cancelled_{false};
  mutable std::mutex errorMutex_;
  std::string error_;
};

}  // namespace isurface::app_model
