#pragma once

// Private helpers of the experiments: CSV files, SNR sweeps and knees.

#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "vantage/simulate/experiments.h"
#include "vantage/simulate/monte_carlo.h"
#include "vantage/simulate/noise.h"

namespace vantage::simulate::internal {

using Json = nlohmann::ordered_json;

/// A CSV file written row by row; numbers with 17 significant digits, NaN as empty fields.
class CsvWriter {
 public:
  CsvWriter(const std::string& path, const std::vector<std::string>& header);
  CsvWriter& operator<<(double value);
  CsvWriter& operator<<(long value);
  CsvWriter& operator<<(int value) { return *this << static_cast<long>(value); }
  CsvWriter& operator<<(const std::string& value);
  CsvWriter& operator<<(const char* value) { return *this << std::string(value); }
  void end_row();
  const std::string& path() const { return path_; }

 private:
  void separator();
  std::string path_;
  std::ofstream out_;
  bool first_ = true;
};

/// out_dir / name.
std::string output_path(const ExperimentOptions& options, const std::string& name);

/// One cell of an SNR sweep: its parameters and the statistics of every estimator.
struct SweepCell {
  int n = 0;
  NoiseKind noise = NoiseKind::kGaussian;
  double snr_db = 0.0;
  std::vector<EstimatorSummary> summaries;
};

/// Scene of one cell: (n, noise, snr_db) -> generator.
using CellScene = std::function<SceneGenerator(int n, NoiseKind noise, double snr_db)>;

/// Runs every (n, noise, snr) cell with `trials` trials and the same seed (common random
/// numbers: a trial's geometry is the same in every SNR cell), with the named estimators
/// that apply (all applicable when empty).
std::vector<SweepCell> run_sweep(const std::vector<int>& ns, const std::vector<NoiseKind>& noises,
                                 const std::vector<double>& snrs, const CellScene& scene,
                                 const std::vector<std::string>& estimators, long trials,
                                 const ExperimentOptions& options);

/// The grid lo, lo + step, ..., <= hi.
std::vector<double> grid(double lo, double hi, double step);

/// A number for a markdown table: "%.*g", or "—" when not finite.
std::string cell(double value, int digits = 3);

/// The summary of one estimator in a cell (nullptr when it did not run there).
const EstimatorSummary* find_summary(const SweepCell& cell, const std::string& name);

/// Writes one row per (cell, estimator) with the cell parameters and error statistics.
void write_sweep_csv(const std::string& path, const std::vector<SweepCell>& cells);

/// The experiments (one function each, in their own files).
ExperimentResult run_mcinroy_orientation(const ExperimentOptions& options, long trials);
ExperimentResult run_mcinroy_pose(const ExperimentOptions& options, long trials);
ExperimentResult run_bound(const ExperimentOptions& options, long trials);
ExperimentResult run_haralick_2d2d(const ExperimentOptions& options, long trials);
ExperimentResult run_haralick_3d3d(const ExperimentOptions& options, long trials);
ExperimentResult run_haralick_two_view(const ExperimentOptions& options, long trials);
ExperimentResult run_wu_points(const ExperimentOptions& options, long trials);
ExperimentResult run_wu_snr(const ExperimentOptions& options, long trials);

}  // namespace vantage::simulate::internal
