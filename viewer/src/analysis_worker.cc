#include "vantage/viewer/analysis_worker.h"

#include <exception>
#include <utility>

namespace vantage::viewer {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

AnalysisSnapshot analyze_layout(const Layout& layout, std::uint64_t revision) {
  const auto start = std::chrono::steady_clock::now();
  AnalysisSnapshot snapshot;
  snapshot.revision = revision;
  snapshot.layout = layout;
  try {
    static_cast<report::LayoutReport&>(snapshot) = report::analyze_layout(layout);
  } catch (const std::exception& e) {
    snapshot.error = e.what();
  }
  snapshot.seconds = seconds_since(start);
  return snapshot;
}

AugmentOutcome augment_once(const Layout& layout, std::uint64_t revision) {
  const auto start = std::chrono::steady_clock::now();
  AugmentOutcome outcome;
  outcome.revision = revision;
  try {
    design::AugmentOptions options;
    options.add = 1;
    options.run_direct = false;
    const design::AugmentResult result = design::augment_layout(layout, options);
    if (result.steps.empty()) {
      outcome.error = result.message.empty() ? "the augmenter made no step" : result.message;
    } else {
      outcome.augmented = result.augmented;
      outcome.step = result.steps.front();
    }
  } catch (const std::exception& e) {
    outcome.error = e.what();
  }
  outcome.seconds = seconds_since(start);
  return outcome;
}

AnalysisWorker::AnalysisWorker() : thread_([this] { run(); }) {}

AnalysisWorker::~AnalysisWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void AnalysisWorker::request_analysis(const Layout& layout, std::uint64_t revision) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_analysis_ = Request{layout, revision, {}};
    newest_analysis_revision_ = revision;
  }
  changed_.notify_all();
}

void AnalysisWorker::request_augment(const Layout& layout, std::uint64_t revision) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_augment_ = Request{layout, revision, {}};
  }
  changed_.notify_all();
}

void AnalysisWorker::request_place(const Layout& layout, std::uint64_t revision,
                                   const PlaceSettings& settings) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_place_ = Request{layout, revision, settings};
  }
  changed_.notify_all();
}

std::optional<AnalysisSnapshot> AnalysisWorker::take_analysis() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<AnalysisSnapshot> out = std::move(finished_analysis_);
  finished_analysis_.reset();
  return out;
}

std::optional<AugmentOutcome> AnalysisWorker::take_augment() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<AugmentOutcome> out = std::move(finished_augment_);
  finished_augment_.reset();
  return out;
}

std::optional<PlaceOutcome> AnalysisWorker::take_place() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<PlaceOutcome> out = std::move(finished_place_);
  finished_place_.reset();
  return out;
}

std::string AnalysisWorker::place_progress() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return place_progress_;
}

bool AnalysisWorker::busy() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return running_ || any_pending();
}

bool AnalysisWorker::wait_idle(std::chrono::milliseconds timeout) const {
  std::unique_lock<std::mutex> lock(mutex_);
  return changed_.wait_for(lock, timeout, [this] { return !running_ && !any_pending(); });
}

AnalysisWorker::Job AnalysisWorker::next_job(Request* request) {
  // Analyses first: the UI waits for them; an augmenter step takes several global solves, and a
  // placement many more.
  std::optional<Request>* pending = &pending_place_;
  Job job = Job::kPlace;
  if (pending_analysis_) {
    pending = &pending_analysis_;
    job = Job::kAnalysis;
  } else if (pending_augment_) {
    pending = &pending_augment_;
    job = Job::kAugment;
  }
  *request = std::move(**pending);
  pending->reset();
  return job;
}

void AnalysisWorker::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    changed_.wait(lock, [this] { return stop_ || any_pending(); });
    if (stop_) return;
    Request request;
    const Job job = next_job(&request);
    running_ = true;
    lock.unlock();
    if (job == Job::kAnalysis) {
      AnalysisSnapshot snapshot = analyze_layout(request.layout, request.revision);
      lock.lock();
      if (snapshot.revision >= newest_analysis_revision_) finished_analysis_ = std::move(snapshot);
    } else if (job == Job::kAugment) {
      AugmentOutcome outcome = augment_once(request.layout, request.revision);
      lock.lock();
      finished_augment_ = std::move(outcome);
    } else {
      PlaceOutcome outcome = place_on_body(request.layout, request.revision, request.settings,
                                           [this](const std::string& stage) {
                                             std::lock_guard<std::mutex> progress_lock(mutex_);
                                             place_progress_ = stage;
                                           });
      lock.lock();
      place_progress_.clear();
      finished_place_ = std::move(outcome);
    }
    running_ = false;
    changed_.notify_all();
  }
}

}  // namespace vantage::viewer
