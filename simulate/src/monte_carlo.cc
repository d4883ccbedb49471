#include "vantage/simulate/monte_carlo.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/common.h"
#include "vantage/simulate/progress.h"

namespace vantage::simulate {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

bool fail(std::string* why, const std::string& message) {
  if (why) *why = message;
  return false;
}

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace

Shard parse_shard(const std::string& text, const std::string& argument) {
  const auto slash = text.find('/');
  Shard shard;
  try {
    std::size_t used_k = 0;
    std::size_t used_n = 0;
    if (slash == std::string::npos) throw std::invalid_argument("no slash");
    shard.index = std::stoi(text.substr(0, slash), &used_k);
    shard.count = std::stoi(text.substr(slash + 1), &used_n);
    if (used_k != slash || used_n != text.size() - slash - 1) throw std::invalid_argument("junk");
  } catch (const std::exception&) {
    throw InvalidArgument(argument + ": must be K/N with integers 1 <= K <= N, got '" + text + "'");
  }
  if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) {
    throw InvalidArgument(argument + ": must be K/N with 1 <= K <= N, got '" + text + "'");
  }
  return shard;
}

bool MonteCarloOptions::is_valid(std::string* why) const {
  if (trials < 1) return fail(why, "trials: must be >= 1");
  if (threads < 0) return fail(why, "threads: must be >= 0");
  if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) {
    return fail(why, "shard: must satisfy 1 <= index <= count");
  }
  if (shard.count > trials) return fail(why, "shard: count must not exceed trials");
  return true;
}

std::pair<long, long> shard_range(long total, const Shard& shard) {
  // floor(total k / count) without overflow: total = q count + r.
  const long q = total / shard.count;
  const long r = total % shard.count;
  const auto bound = [&](long k) { return q * k + r * k / shard.count; };
  return {bound(shard.index - 1), bound(shard.index)};
}

TrialError trial_error(const PoseEstimate& estimate, const Scene& scene) {
  TrialError error;
  const Eigen::Vector3d& p = estimate.p_camera_object;
  error.rot_err_deg =
      rotation_angle_between(estimate.R_camera_object, scene.R_true) * kDegreesPerRadian;
  const bool translation = p.allFinite() && scene.has_translation;
  error.trans_err = translation ? (p - scene.p_true).norm() : kNaN;
  error.trans_err_rel = error.trans_err / scene.p_true.norm();
  error.trans_err_deg = translation ? angle_between(p, scene.p_true) * kDegreesPerRadian : kNaN;
  error.scale_err =
      std::isnan(estimate.alpha) ? kNaN : std::abs(estimate.alpha / scene.alpha_true - 1.0);
  const bool ok = estimate.status == PoseStatus::kOk;
  error.status = ok && estimate.ambiguous ? "ambiguous" : to_string(estimate.status);
  error.ok = ok && !estimate.ambiguous;
  return error;
}

int worker_count(int threads) {
  return threads > 0 ? threads
                     : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void parallel_for(long count, int threads, bool progress, const std::function<void(long k)>& body) {
  const int workers =
      static_cast<int>(std::max<long>(1, std::min<long>(count, worker_count(threads))));
  std::atomic<long> next{0};
  std::atomic<long> done{0};
  std::atomic<bool> stop{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;
  const auto work = [&] {
    for (long k = next++; k < count && !stop; k = next++) {
      try {
        body(k);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        stop = true;
      }
      ++done;
    }
  };
  // With a progress bar the calling thread only draws it; otherwise it is one of the workers.
  progress = progress && stderr_is_terminal();
  std::vector<std::thread> pool;
  for (int w = progress ? 0 : 1; w < workers; ++w) pool.emplace_back(work);
  if (progress) {
    ProgressBar bar(count, true);
    while (done < count && !stop) {
      bar.update(done);
      std::this_thread::sleep_for(ProgressBar::kInterval / 2);
    }
    bar.update(done);
  } else {
    work();
  }
  for (std::thread& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

void EstimatorAccumulator::add(const TrialError& error) {
  ++trials_;
  rot_err_deg_.add(error.rot_err_deg);
  trans_err_.add(error.trans_err);
  trans_err_rel_.add(error.trans_err_rel);
  trans_err_deg_.add(error.trans_err_deg);
  scale_err_.add(error.scale_err);
  time_us_.add(error.time_us);
  ++by_status_[error.status];
  if (!error.ok) ++failures_;
  if (error.ok && error.rot_err_deg > kWrongButOkDeg) ++wrong_but_ok_;
}

EstimatorSummary EstimatorAccumulator::summary() const {
  EstimatorSummary s;
  s.name = name_;
  s.trials = trials_;
  s.rot_err_deg = rot_err_deg_.summary();
  s.trans_err = trans_err_.summary();
  s.trans_err_rel = trans_err_rel_.summary();
  s.trans_err_deg = trans_err_deg_.summary();
  s.scale_err = scale_err_.summary();
  s.time_us = time_us_.summary();
  s.failures = failures_;
  s.by_status = by_status_;
  s.wrong_but_ok = wrong_but_ok_;
  return s;
}

void MonteCarloRun::add_trial(long trial, const std::vector<TrialError>& per_estimator, bool keep) {
  VANTAGE_CHECK(per_estimator.size() == names.size(), "one error per estimator");
  if (accumulators.size() != names.size()) {
    accumulators.clear();
    for (const std::string& name : names) accumulators.emplace_back(name);
    errors.assign(names.size(), {});
  }
  ++trials;
  for (std::size_t e = 0; e < names.size(); ++e) {
    accumulators[e].add(per_estimator[e]);
    if (keep) errors[e].push_back(per_estimator[e]);
  }
  if (keep) trial_index.push_back(trial);
}

MonteCarloRun run_monte_carlo(const SceneGenerator& generator,
                              const std::vector<Estimator>& estimators,
                              const MonteCarloOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("run_monte_carlo: " + why);
  MonteCarloRun run;
  run.total_trials = options.trials;
  run.seed = options.seed;
  for (const Estimator& e : estimators) {
    run.names.push_back(e.name);
    run.accumulators.emplace_back(e.name);
  }
  run.errors.assign(estimators.size(), {});
  // Plain variables, not a structured binding: the lambdas below capture them.
  const std::pair<long, long> range = shard_range(options.trials, options.shard);
  const long first = range.first;
  const long last = range.second;
  // One block of results at a time: memory does not grow with the trials (unless kept).
  parallel_for_in_order<std::vector<TrialError>>(
      last - first, options.threads, options.progress,
      [&](long k) {
        const long trial = first + k;
        TrialRandom random = TrialRandom::for_trial(options.seed, trial);
        const Scene scene = generator(trial, random);
        std::vector<TrialError> errors(estimators.size());
        for (std::size_t e = 0; e < estimators.size(); ++e) {
          const auto start = std::chrono::steady_clock::now();
          const PoseEstimate estimate = estimators[e].solve(scene);
          const auto stop = std::chrono::steady_clock::now();
          errors[e] = trial_error(estimate, scene);
          errors[e].time_us = std::chrono::duration<double, std::micro>(stop - start).count();
        }
        return errors;
      },
      [&](long k, const std::vector<TrialError>& errors) {
        run.add_trial(first + k, errors, options.keep_trials);
        if (options.on_trial) options.on_trial(run, first + k, errors);
      });
  return run;
}

std::vector<EstimatorSummary> summarize(const MonteCarloRun& run) {
  std::vector<EstimatorSummary> summaries;
  for (const EstimatorAccumulator& a : run.accumulators) summaries.push_back(a.summary());
  return summaries;
}

MonteCarloRun merge_runs(const std::vector<MonteCarloRun>& shards,
                         const std::vector<std::string>& sources) {
  if (shards.empty()) throw InvalidArgument("merge: no shard given");
  VANTAGE_CHECK(sources.size() == shards.size(), "one source name per shard");
  const MonteCarloRun& head = shards.front();
  std::vector<std::pair<long, std::pair<std::size_t, std::size_t>>> order;
  for (std::size_t s = 0; s < shards.size(); ++s) {
    const MonteCarloRun& shard = shards[s];
    if (shard.seed != head.seed || shard.total_trials != head.total_trials ||
        shard.names != head.names) {
      throw InvalidArgument(sources[s] + ": not a shard of the same run as " + sources[0] +
                            " (seed, trials or estimators differ)");
    }
    for (std::size_t k = 0; k < shard.trial_index.size(); ++k) {
      order.push_back({shard.trial_index[k], {s, k}});
    }
  }
  std::sort(order.begin(), order.end());
  MonteCarloRun merged;
  merged.total_trials = head.total_trials;
  merged.seed = head.seed;
  merged.names = head.names;
  std::vector<TrialError> per_estimator(head.names.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i > 0 && order[i].first == order[i - 1].first) {
      throw InvalidArgument(sources[order[i].second.first] + ": trial " +
                            std::to_string(order[i].first) + " is also in " +
                            sources[order[i - 1].second.first] + " (overlapping shards)");
    }
    const auto [s, k] = order[i].second;
    for (std::size_t e = 0; e < head.names.size(); ++e) per_estimator[e] = shards[s].errors[e][k];
    merged.add_trial(order[i].first, per_estimator, true);
  }
  return merged;
}

}  // namespace vantage::simulate
