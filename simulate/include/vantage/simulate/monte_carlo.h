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

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "vantage/simulate/estimators.h"
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

/// Options of run_monte_carlo().
struct MonteCarloOptions {
  long trials = 1000;      ///< total trials of the (unsharded) run, >= 1
  std::uint64_t seed = 1;  ///< run seed
  int threads = 0;         ///< worker threads, >= 0; 0 = std::thread::hardware_concurrency()
  Shard shard;             ///< the slice of trials this call runs
  /// Draw a one-line progress bar on stderr (only when stderr is a terminal and the run takes
  /// longer than about a second).
  bool progress = false;

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

/// A run (or a shard of one, or a merge of shards): the per-trial errors of every estimator.
struct MonteCarloRun {
  long total_trials = 0;  ///< trials of the whole run
  std::uint64_t seed = 0;
  std::vector<long> trial_index;   ///< the trials held, increasing
  std::vector<std::string> names;  ///< estimator names
  /// errors[e][k]: estimator names[e] on trial trial_index[k].
  std::vector<std::vector<TrialError>> errors;
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

/// The trials [first, last) of a shard of `total` trials.
std::pair<long, long> shard_range(long total, const Shard& shard);

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

/// Statistics of every estimator of `run`.
std::vector<EstimatorSummary> summarize(const MonteCarloRun& run);

/// The union of shards of one run: same seed, total_trials and estimator names, disjoint trial
/// sets. Throws InvalidArgument naming `sources[i]` for a shard that does not fit.
MonteCarloRun merge_runs(const std::vector<MonteCarloRun>& shards,
                         const std::vector<std::string>& sources);

}  // namespace vantage::simulate
