#pragma once

/// The viewer's global analysis, off the UI thread.
///
/// The viewer computes nothing itself: analyze_layout() calls report::analyze_layout() — the same
/// call as `vantage analyze` — augment_once() calls design::augment_layout for one greedy
/// step, and place_on_body() calls design::place_markers on the body. AnalysisWorker runs
/// them on one background thread. Each request carries the document revision it was made for;
/// a newer request replaces a pending one, and a finished result whose revision is older than the
/// newest request is dropped, so the UI only ever receives results for what it last asked.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "vantage/analysis/layout.h"
#include "vantage/design/augment.h"
#include "vantage/report/layout_report.h"
#include "vantage/viewer/body_placement.h"

namespace vantage::viewer {

/// Everything the viewer shows about one revision of the layout: the report `vantage analyze`
/// prints (report::analyze_layout()), with the revision it belongs to.
struct AnalysisSnapshot : report::LayoutReport {
  std::uint64_t revision = 0;
  double seconds = 0.0;  ///< wall time of the whole analysis
  std::string error;     ///< non-empty when the analysis threw (then only layout is set)
};

/// One greedy augmenter step on a layout.
struct AugmentOutcome {
  std::uint64_t revision = 0;  ///< revision of the layout it started from
  Layout augmented;            ///< the input with one vector or marker appended
  design::AugmentStep step;
  double seconds = 0.0;
  std::string error;  ///< non-empty when the augmenter threw
};

/// Synchronous analysis, as `vantage analyze LAYOUT` (geometric pair weights, cross-check on).
/// Never throws: errors go to AnalysisSnapshot::error.
AnalysisSnapshot analyze_layout(const Layout& layout, std::uint64_t revision);

/// Synchronous augmenter step: design::augment_layout with add = 1, no direct optimiser.
/// Never throws: errors go to AugmentOutcome::error.
AugmentOutcome augment_once(const Layout& layout, std::uint64_t revision);

class AnalysisWorker {
 public:
  AnalysisWorker();
  ~AnalysisWorker();  ///< finishes the job in progress (it cannot be interrupted), then joins
  AnalysisWorker(const AnalysisWorker&) = delete;
  AnalysisWorker& operator=(const AnalysisWorker&) = delete;

  /// Asks for analyze_layout(layout, revision); replaces a pending analysis request.
  void request_analysis(const Layout& layout, std::uint64_t revision);
  /// Asks for augment_once(layout, revision); replaces a pending augment request.
  void request_augment(const Layout& layout, std::uint64_t revision);

  /// Asks for place_on_body(layout, revision, settings); replaces a pending placement request.
  void request_place(const Layout& layout, std::uint64_t revision, const PlaceSettings& settings);

  /// The newest finished analysis not taken yet, if any.
  std::optional<AnalysisSnapshot> take_analysis();
  /// The finished augmenter step not taken yet, if any.
  std::optional<AugmentOutcome> take_augment();

  /// The finished placement not taken yet, if any.
  std::optional<PlaceOutcome> take_place();
  /// The stage the running placement last reported ("occlusion grid", "greedy 3/12", ...), or
  /// empty when none runs.
  std::string place_progress() const;

  /// True while a request is pending or running.
  bool busy() const;
  /// Blocks until nothing is pending or running, or `timeout` passes; true when idle.
  bool wait_idle(std::chrono::milliseconds timeout) const;

 private:
  struct Request {
    Layout layout;
    std::uint64_t revision = 0;
    PlaceSettings settings;  // placement requests only
  };
  enum class Job { kAnalysis, kAugment, kPlace };
  bool any_pending() const { return pending_analysis_ || pending_augment_ || pending_place_; }
  Job next_job(Request* request);
  void run();

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::optional<Request> pending_analysis_;
  std::optional<Request> pending_augment_;
  std::optional<Request> pending_place_;
  std::uint64_t newest_analysis_revision_ = 0;
  std::optional<AnalysisSnapshot> finished_analysis_;
  std::optional<AugmentOutcome> finished_augment_;
  std::optional<PlaceOutcome> finished_place_;
  std::string place_progress_;
  bool running_ = false;
  bool stop_ = false;
  std::thread thread_;  // last: starts after the members above exist
};

}  // namespace vantage::viewer
