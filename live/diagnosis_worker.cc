#include "live/diagnosis_worker.h"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "diagnosis/diagnose.h"
#include "core/model_error.h"
#include "live/background_priority.h"

namespace gc::live {
namespace {

double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void diagnose_into(const DiagnosisJob& job, const ParallelFor& parallel, DiagnosisOutcome& out) {
  const Diagnosis diagnosis = diagnose(*job.base.model, job.samples, parallel);
  out.proposal = proposal_from(diagnosis, job.base, job.test_cell, job.samples);
  if (!out.proposal) out.note = diagnosis.summary;
}

void recheck_into(const DiagnosisJob& job, DiagnosisOutcome& out) {
  out.rechecked = job.recheck;
  out.base_rmse_nm = pooled_rmse(*job.base.model, job.samples);
  out.proposed_rmse_nm = pooled_rmse(*job.recheck->model, job.samples);
}

}  // namespace

DiagnosisOutcome run_job(const DiagnosisJob& job, const ParallelFor& parallel) {
  DiagnosisOutcome out;
  out.test_cell = job.test_cell;
  out.cell_generation = job.cell_generation;
  out.base = job.base;
  const double cpu0 = thread_cpu_s();
  try {
    if (job.recheck) {
      recheck_into(job, out);
    } else {
      diagnose_into(job, parallel, out);
    }
  } catch (const std::exception& error) {
    out.proposal.reset();
    out.rechecked.reset();
    out.note = error.what();
  }
  out.cpu_s = thread_cpu_s() - cpu0;
  out.samples = job.samples.size();
  return out;
}

DiagnosisWorker::DiagnosisWorker(std::size_t queue, int nice, double cpu_share,
                                 std::function<void()> done)
    : queue_limit_(std::max<std::size_t>(queue, 1)),
      nice_(nice),
      cpu_share_(std::clamp(cpu_share, 0.01, 1.0)),
      done_(std::move(done)),
      thread_([this] { run(); }) {}

DiagnosisWorker::~DiagnosisWorker() {
  cancel_ = true;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  wake_.notify_all();
  thread_.join();
}

bool DiagnosisWorker::busy(const std::string& test_cell) {
  std::lock_guard lock(mutex_);
  return running_ == test_cell ||
         std::any_of(queue_.begin(), queue_.end(),
                     [&](const DiagnosisJob& j) { return j.test_cell == test_cell; });
}

bool DiagnosisWorker::submit(DiagnosisJob job) {
  {
    std::lock_guard lock(mutex_);
    if (queue_.size() >= queue_limit_ || running_ == job.test_cell) return false;
    for (const DiagnosisJob& j : queue_) {
      if (j.test_cell == job.test_cell) return false;
    }
    queue_.push_back(std::move(job));
  }
  wake_.notify_one();
  return true;
}

std::string DiagnosisWorker::running() {
  std::lock_guard lock(mutex_);
  return running_;
}

std::vector<DiagnosisOutcome> DiagnosisWorker::take_outcomes() {
  std::lock_guard lock(mutex_);
  std::vector<DiagnosisOutcome> out;
  out.swap(outcomes_);
  return out;
}

void DiagnosisWorker::throttled_loop(std::size_t count,
                                     const std::function<void(std::size_t, std::size_t)>& body) {
  // Cancelled at the next loop once the worker stops: the monitor's stop (or SIGHUP) never
  // waits for a whole diagnosis.
  if (cancel_) throw std::runtime_error("diagnosis cancelled: the monitor is stopping");
  if (count == 0) return;
  const double cpu0 = thread_cpu_s();
  body(0, count);
  if (cpu_share_ >= 1.0) return;
  const double rest_s = (thread_cpu_s() - cpu0) * (1.0 / cpu_share_ - 1.0);
  std::unique_lock lock(mutex_);
  wake_.wait_for(lock, std::chrono::duration<double>(rest_s), [&] { return stopping_; });
}

void DiagnosisWorker::run() {
  lower_this_thread(nice_);
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (stopping_) return;
    DiagnosisJob job = std::move(queue_.front());
    queue_.pop_front();
    running_ = job.test_cell;
    lock.unlock();
    DiagnosisOutcome outcome = run_job(job, [this](std::size_t count, const auto& body) {
      throttled_loop(count, body);
    });
    lock.lock();
    running_.clear();
    if (stopping_) return;
    outcomes_.push_back(std::move(outcome));
    lock.unlock();
    done_();
    lock.lock();
  }
}

}  // namespace gc::live
