// One worker thread at a time. The UI thread owns the BackgroundJob (start, cancel, polling);
// the worker touches only its JobControl and, once at its end, the outcome fields.
#include "isurface/app_model/background_job.h"

#include <exception>
#include <system_error>

namespace isurface::app_model {

void JobControl::progress(double fraction) {
  progress_ = fraction >= 0 ? (fraction <= 1 ? fraction : 1.0) : 0.0;  // NaN reads as 0
  if (cancel_) throw JobCancelled{};
}

void JobControl::stage(std::string text) {
  std::lock_guard<std::mutex> lock(stageMutex_);
  stage_ = std::move(text);
}

std::string BackgroundJob::stage() const {
  if (!control_ || !running_) return {};
  std::lock_guard<std::mutex> lock(control_->stageMutex_);
  return control_->stage_;
}

BackgroundJob::~BackgroundJob() {
  cancel();
  join();
}

void BackgroundJob::join() {
  if (worker_.joinable()) worker_.join();
}

void BackgroundJob::cancel() {
  if (control_) control_->cancel_ = true;
}

void BackgroundJob::start(std::string label, std::function<void(JobControl&)> work) {
  cancel();
  join();
  // The outcome of a job replaced by this one is dropped: nobody asked for it any more.
  label_ = std::move(label);
  control_ = std::make_unique<JobControl>();
  {
    std::lock_guard<std::mutex> lock(errorMutex_);
    error_.clear();
  }
  cancelled_ = false;
  finished_ = false;
  running_ = true;
  JobControl* control = control_.get();
  try {
    worker_ = std::thread([this, control, work = std::move(work)] {
      std::string error;
      bool cancelled = false;
      try {
        work(*control);
        control->progress_ = 1.0;
      } catch (const JobCancelled&) {
        cancelled = true;
      } catch (const std::exception& e) {
        error = e.what();
        if (error.empty()) error = "failed";
      } catch (...) {
        error = "failed with an unknown error";
      }
      {
        std::lock_guard<std::mutex> lock(errorMutex_);
        error_ = std::move(error);
      }
      cancelled_ = cancelled;
      // Finished before not running: a poll that sees the job stopped also sees it finished.
      finished_ = true;
      running_ = false;
    });
  } catch (const std::system_error&) {
    running_ = false;
    throw;
  }
}

std::string BackgroundJob::error() const {
  std::lock_guard<std::mutex> lock(errorMutex_);
  return error_;
}

bool BackgroundJob::takeFinished() {
  if (!finished_.exchange(false)) return false;
  join();  // the worker has nothing left to do but return
  return true;
}

}  // namespace isurface::app_model
