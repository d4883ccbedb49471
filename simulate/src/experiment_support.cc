#include "experiment_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "vantage/analysis/common.h"
#include "vantage/simulate/progress.h"
#include "vantage/simulate/report_json.h"

namespace vantage::simulate::internal {

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& header)
    : path_(path), out_(path) {
  if (!out_) throw InvalidArgument(path + ": cannot write file");
  for (const std::string& h : header) *this << h;
  end_row();
}

void CsvWriter::separator() {
  if (!first_) out_ << ',';
  first_ = false;
}

CsvWriter& CsvWriter::operator<<(double value) {
  separator();
  if (std::isfinite(value)) {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.17g", value);
    out_ << buffer;
  }
  return *this;
}

CsvWriter& CsvWriter::operator<<(long value) {
  separator();
  out_ << value;
  return *this;
}

CsvWriter& CsvWriter::operator<<(const std::string& value) {
  separator();
  out_ << value;
  return *this;
}

void CsvWriter::end_row() {
  out_ << '\n';
  first_ = true;
}

std::string output_path(const ExperimentOptions& options, const std::string& name) {
  return (std::filesystem::path(options.out_dir) / name).string();
}

}  // namespace vantage::simulate::internal

namespace vantage::simulate {

double snr_knee(const std::vector<double>& snr, const std::vector<double>& error,
                double threshold) {
  const std::size_t n = snr.size();
  if (n == 0) return std::nan("");
  std::size_t first_good = n;  // every grid SNR from here on is below the threshold
  for (std::size_t k = n; k-- > 0;) {
    if (!(error[k] < threshold)) break;
    first_good = k;
  }
  if (first_good == n) return std::nan("");
  if (first_good == 0) return snr[0];
  const std::size_t bad = first_good - 1;
  const double e0 = std::log10(error[bad]);
  const double e1 = std::log10(error[first_good]);
  const double target = std::log10(threshold);
  if (!std::isfinite(e0) || !(e0 > e1)) return snr[first_good];
  return snr[bad] + (snr[first_good] - snr[bad]) * (e0 - target) / (e0 - e1);
}

}  // namespace vantage::simulate

namespace vantage::simulate::internal {

std::vector<SweepCell> run_sweep(const std::vector<int>& ns, const std::vector<NoiseKind>& noises,
                                 const std::vector<double>& snrs, const CellScene& scene,
                                 const std::vector<std::string>& estimators, long trials,
                                 const ExperimentOptions& options) {
  std::vector<SweepCell> cells;
  const long total = static_cast<long>(ns.size() * noises.size() * snrs.size());
  ProgressBar bar(total, options.progress, "cells");
  for (int n : ns) {
    for (NoiseKind noise : noises) {
      for (double snr : snrs) {
        const SceneGenerator generator = scene(n, noise, snr);
        TrialRandom probe_random = TrialRandom::for_trial(options.seed, 0);
        const Scene probe = generator(0, probe_random);
        std::vector<Estimator> selected;
        for (const Estimator& e : estimator_registry()) {
          const bool named = estimators.empty() || std::find(estimators.begin(), estimators.end(),
                                                             e.name) != estimators.end();
          if (named && e.applies(probe)) selected.push_back(e);
        }
        MonteCarloOptions mc;
        mc.trials = trials;
        mc.seed = options.seed;
        mc.threads = options.threads;
        SweepCell c;
        c.n = n;
        c.noise = noise;
        c.snr_db = snr;
        c.summaries = summarize(run_monte_carlo(generator, selected, mc));
        cells.push_back(std::move(c));
        bar.update(static_cast<long>(cells.size()));
      }
    }
  }
  return cells;
}

std::vector<double> grid(double lo, double hi, double step) {
  std::vector<double> values;
  for (int k = 0; lo + k * step <= hi + 1e-9; ++k) values.push_back(lo + k * step);
  return values;
}

std::string cell(double value, int digits) {
  if (!std::isfinite(value)) return "—";
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
  return buffer;
}

const EstimatorSummary* find_summary(const SweepCell& c, const std::string& name) {
  for (const EstimatorSummary& s : c.summaries) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

void write_sweep_csv(const std::string& path, const std::vector<SweepCell>& cells) {
  CsvWriter csv(path,
                {"n", "noise", "snr_db", "estimator", "trials", "rot_err_deg_mean",
                 "rot_err_deg_median", "rot_err_deg_p95", "trans_err_mean", "trans_err_rel_mean",
                 "trans_err_deg_mean", "time_us_median", "failures", "wrong_but_ok"});
  for (const SweepCell& c : cells) {
    for (const EstimatorSummary& s : c.summaries) {
      csv << c.n << to_string(c.noise) << c.snr_db << s.name << s.trials << s.rot_err_deg.mean
          << s.rot_err_deg.median << s.rot_err_deg.p95 << s.trans_err.mean << s.trans_err_rel.mean
          << s.trans_err_deg.mean << s.time_us.median << s.failures << s.wrong_but_ok;
      csv.end_row();
    }
  }
}

}  // namespace vantage::simulate::internal
