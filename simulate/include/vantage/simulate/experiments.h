#pragma once

/// The seed papers' simulation experiments, reproduced: each writes its per-trial or per-cell
/// CSV files (the numbers a figure draws, one tidy row per point) and a summary table
/// (summary.md, summary.json) into an output directory. `vantage experiment NAME` runs them.
///
///  mcinroy-orientation  Figs. 4-5: Lemma 7 ("new") vs Theorem 1 with v_z = 0 ("standard"),
///                       n = 3 and 5 random data vectors, random rotations, noise-free.
///  mcinroy-pose         Fig. 6 table: full 3-D vs standard 2-D vs new 2-D at the paper's
///                       geometry (4 points, p = [0.369, 0.179, 1e5], worst viewpoint).
///  bound                the bound check over example and random layouts.
///  haralick-2d2d, haralick-3d3d, haralick-two-view
///                       error vs SNR and the SNR knees (Haralick et al. Secs. 2-4, Table 1).
///  wu-points, wu-snr    Wu & Wu Sec. 3: accuracy and time vs number of points and vs SNR.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace vantage::simulate {

/// A layout handed to an experiment (the bound experiment's example layouts).
struct NamedLayout {
  std::string name;
  Eigen::Matrix3Xd entries;  ///< points (vectors = false) or data vectors
  bool vectors = false;
};

/// Options of an experiment run.
struct ExperimentOptions {
  std::string out_dir;     ///< existing or creatable directory; files are replaced
  long trials = 0;         ///< trials per cell (per layout for bound); 0 = the default, >= 0
  std::uint64_t seed = 1;  ///< run seed
  bool quick = false;      ///< a tiny version (for tests): few cells, few trials
  int threads = 0;         ///< worker threads, >= 0 (0 = all cores)
  bool progress = false;   ///< progress bar on stderr (only on a terminal)
  std::vector<NamedLayout> layouts;  ///< bound: the example layouts to check

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// What an experiment produced.
struct ExperimentResult {
  std::string name;
  nlohmann::ordered_json summary;  ///< also written to out_dir/summary.json
  std::string table;               ///< markdown; also written to out_dir/summary.md
  std::vector<std::string> files;  ///< every file written, paths
  long trials_per_cell = 0;
  double seconds = 0.0;  ///< wall-clock time of the run
};

/// A registered experiment.
struct Experiment {
  std::string name;
  std::string description;
  long default_trials = 0;  ///< trials per cell without --trials
  std::function<ExperimentResult(const ExperimentOptions&, long trials)> run;
};

/// Every experiment, in the order of the file comment.
const std::vector<Experiment>& experiment_registry();

/// The registered names joined by ", ".
std::string experiment_names();

/// The SNR knee of an error curve (Haralick et al. Table 1: "SNR for error mean in 1 degree"):
/// the lowest SNR from which on (every larger grid SNR included) the error stays below
/// `threshold`, interpolated linearly in log10(error) between the last grid SNR at or above the
/// threshold and the next one. snr ascending, one error per SNR. NaN when the error at the largest
/// SNR is not below; the smallest SNR when every error is below (a knee at or below the grid).
double snr_knee(const std::vector<double>& snr, const std::vector<double>& error, double threshold);

/// Runs the named experiment: validates the options, creates out_dir, runs, writes
/// summary.json and summary.md. Throws InvalidArgument (naming the option) for an unknown name,
/// invalid options or an output directory that cannot be created.
ExperimentResult run_experiment(const std::string& name, const ExperimentOptions& options);

}  // namespace vantage::simulate
