#pragma once

/// The Monte Carlo runner: every selected estimator on the same trials, in parallel over trials,
/// with results that are bit-identical for a given seed at any thread count and under any
/// sharding (trial t always draws from TrialRandom::for_trial(seed, t); only time_us, a wall
/// clock, differs between runs).
///
/// Errors of an estimate (R, p) against the truth (R_true, p_true):
///   rot_err_deg   = angle of R^T R_true (geodesic), degrees
///   trans_err     = |p - p_true|, object units (NaN when no translation is estimated)
///   trans_err_rel = |p - p_true| / |p_true| (NaN when no translation is estimated)
///   trans_err_deg = angle between p and p_true, degrees (the only translation error two views
///                   define, as T is a direction; NaN without translation)
///   scale_err     = |alpha / alpha_true - 1| (NaN when the method has no scale)
/// A trial fails when its status is not ok; "wrong but ok" is a trial with rot_err_deg > 90
/// whose status claims success: the failure a user cannot see.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vantage/simulate/estimators.h"
#include "vantage/simulate/progress.h"
#include "vantage/simulate/random.h"
#include "vantage/simulate/scene.h"
#include "vantage/simulate/statistics.h"

namespace vantage::simulate {

/// Rotation error (degrees) above which an ok status counts as wrong_but_ok.
inline constexpr double kWrongButOkDeg = 90.0;

/// The K-th of N deterministic slices of the trials (1 <= index <= count): trials
/// [floor((K-1) T / N), floor(K T / N)).
struct Shard {
  int index = 1;
  int count = 1;
};

/// "K/N" to a Shard; throws InvalidArgument naming `argument` unless 1 <= K <= N.
Shard parse_shard(const std::string& text, const std::string& argument);

struct TrialError;
struct MonteCarloRun;

/// Options of run_monte_carlo().
struct MonteCarloOptions {
  long trials = 1000;      ///< total trials of the (unsharded) run, >= 1
  std::uint64_t seed = 1;  ///< run seed
  int threads = 0;         ///< worker threads, >= 0; 0 = std::thread::hardware_concurrency()
  Shard shard;             ///< the slice of trials this call runs
  /// Draw a one-line progress bar on stderr (only when stderr is a terminal and the run takes
  /// longer than about a second).
  bool progress = false;
  /// Keep every trial's errors in MonteCarloRun::trial_index and ::errors (for per-trial output:
  /// memory grows with the trials). Without it the run holds only the streaming statistics,
  /// whose memory does not grow with the trials.
  bool keep_trials = false;
  /// Called with the run so far (its names), each trial's index and its errors (one per
  /// estimator, in the order of run.names), in increasing trial order, on the calling thread, as
  /// blocks of trials complete: for writing per-trial rows without keeping them. May throw (the run
  /// stops).
  std::function<void(const MonteCarloRun& run, long trial, const std::vector<TrialError>& errors)>
      on_trial;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// One estimator on one trial.
struct TrialError {
  double rot_err_deg = 0.0;
  double trans_err = 0.0;
  double trans_err_rel = 0.0;
  double trans_err_deg = 0.0;
  double scale_err = 0.0;
  double time_us = 0.0;  ///< wall-clock time of the solve, microseconds
  /// The estimate's PoseStatus name ("ok", "degenerate", ...), or "ambiguous" for an ok estimate
  /// that is PoseEstimate::ambiguous (the data cannot tell it from its alternative).
  std::string status;
  bool ok = true;  ///< status "ok": PoseStatus::kOk and not ambiguous
};

/// The errors of (R, p, alpha) against the scene's truth (file comment; a NaN entry of p means
/// no translation); time_us stays 0.
TrialError trial_error(const PoseEstimate& estimate, const Scene& scene);

/// Per-estimator statistics of a run.
struct EstimatorSummary {
  std::string name;
  long trials = 0;
  Summary rot_err_deg;
  Summary trans_err;
  Summary trans_err_rel;
  Summary trans_err_deg;
  Summary scale_err;
  Summary time_us;
  long failures = 0;                      ///< trials whose status is not ok
  std::map<std::string, long> by_status;  ///< every status and its count (ok ones too)
  long wrong_but_ok = 0;                  ///< ok status with rot_err_deg > kWrongButOkDeg
};

/// An EstimatorSummary built one trial at a time, in trial order, in memory that does not grow
/// with the trials (SummaryAccumulator per error; one count per distinct status).
class EstimatorAccumulator {
 public:
  explicit EstimatorAccumulator(std::string name = {}) : name_(std::move(name)) {}
  void add(const TrialError& error);
  EstimatorSummary summary() const;

 private:
  std::string name_;
  long trials_ = 0;
  SummaryAccumulator rot_err_deg_, trans_err_, trans_err_rel_, trans_err_deg_, scale_err_, time_us_;
  long failures_ = 0;
  std::map<std::string, long> by_status_;
  long wrong_but_ok_ = 0;
};

/// A run (or a shard of one, or a merge of shards): the streaming statistics of every estimator
/// and, when kept, the per-trial errors.
struct MonteCarloRun {
  long total_trials = 0;  ///< trials of the whole run
  std::uint64_t seed = 0;
  long trials = 0;                 ///< trials held (this shard's, or every merged shard's)
  std::vector<std::string> names;  ///< estimator names
  /// One per estimator, fed in trial order: what summarize() reports.
  std::vector<EstimatorAccumulator> accumulators;
  /// The trials held, increasing, and errors[e][k] of estimator names[e] on trial
  /// trial_index[k]: only with MonteCarloOptions::keep_trials (empty otherwise), and always
  /// after run_from_json() and merge_runs().
  std::vector<long> trial_index;
  std::vector<std::vector<TrialError>> errors;

  /// Adds one trial's errors (one per estimator) to the statistics, and to trial_index/errors
  /// when `keep`. Trials must come in increasing order.
  void add_trial(long trial, const std::vector<TrialError>& per_estimator, bool keep);
};

/// One trial's scene: a generator is called with the trial index and that trial's engine.
using SceneGenerator = std::function<Scene(long trial, TrialRandom& random)>;

/// Runs `estimators` on the scenes of the trials of options.shard. Throws InvalidArgument on
/// invalid options; exceptions of the generator or an estimator propagate (first one wins).
MonteCarloRun run_monte_carlo(const SceneGenerator& generator,
                              const std::vector<Estimator>& estimators,
                              const MonteCarloOptions& options);

/// Calls body(k) for k in [0, count) on `threads` worker threads (0 = hardware concurrency),
/// drawing a progress bar when asked. The order of the calls is unspecified; the first
/// exception thrown by a body is rethrown after all workers stop.
void parallel_for(long count, int threads, bool progress, const std::function<void(long k)>& body);

/// The worker threads parallel_for() runs for `threads` (0 = hardware concurrency), at least 1.
int worker_count(int threads);

/// Trials per worker in a block of parallel_for_in_order(): the results of at most this many
/// times worker_count(threads) trials are held at a time.
inline constexpr long kTrialsPerWorker = 512;

/// Streams: for each block of consecutive k in [0, count) (kTrialsPerWorker per worker), computes
/// compute(k) -> Result in parallel, then calls consume(k, result) for the block's k in
/// increasing order on the calling thread. Memory for results is one block, whatever `count`;
/// the progress bar (when asked) counts consumed k. The first exception of a compute is rethrown
/// after the block's workers stop; one of consume stops the loop.
template <class Result, class Compute, class Consume>
void parallel_for_in_order(long count, int threads, bool progress, Compute compute,
                           Consume consume) {
  const long block = kTrialsPerWorker * worker_count(threads);
  std::vector<Result> results(static_cast<std::size_t>(std::min(block, std::max(0L, count))));
  ProgressBar bar(count, progress && stderr_is_terminal());
  for (long begin = 0; begin < count; begin += block) {
    const long size = std::min(block, count - begin);
    parallel_for(size, threads, false, [&](long slot) {
      results[static_cast<std::size_t>(slot)] = compute(begin + slot);
    });
    for (long slot = 0; slot < size; ++slot) {
      consume(begin + slot, results[static_cast<std::size_t>(slot)]);
    }
    bar.update(begin + size);
  }
}

/// The trials [first, last) of a shard of `total` trials.
std::pair<long, long> shard_range(long total, const Shard& shard);

/// Statistics of every estimator of `run` (from its accumulators).
std::vector<EstimatorSummary> summarize(const MonteCarloRun& run);

/// The union of shards of one run: same seed, total_trials and estimator names, disjoint trial
/// sets; its statistics are folded in trial order, so they equal one run's exactly. Throws
/// InvalidArgument naming `sources[i]` for a shard that does not fit.
MonteCarloRun merge_runs(const std::vector<MonteCarloRun>& shards,
                         const std::vector<std::string>& sources);

}  // namespace vantage::simulate
