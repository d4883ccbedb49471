#include "vantage/simulate/experiments.h"

#include <chrono>
#include <filesystem>
#include <fstream>

#include "experiment_support.h"
#include "vantage/analysis/common.h"

namespace vantage::simulate {

bool ExperimentOptions::is_valid(std::string* why) const {
  const auto fail = [&](const char* message) {
    if (why) *why = message;
    return false;
  };
  if (out_dir.empty()) return fail("out_dir: must not be empty");
  if (trials < 0) return fail("trials: must be >= 0 (0 = the experiment's default)");
  if (threads < 0) return fail("threads: must be >= 0");
  return true;
}

const std::vector<Experiment>& experiment_registry() {
  using namespace internal;
  static const std::vector<Experiment> registry = {
      {"mcinroy-orientation",
       "Figs. 4-5: Lemma 7 vs the standard approach, n = 3 and 5 random vectors", 20000,
       run_mcinroy_orientation},
      {"mcinroy-pose", "Fig. 6 table: full 3-D vs standard 2-D vs new 2-D at the worst viewpoint",
       2000, run_mcinroy_pose},
      {"bound", "the bound check (Eq. 26, Eq. 30) over example and 100 random layouts", 200,
       run_bound},
      {"haralick-2d2d", "Haralick Sec. 2: 2D-2D rotation/translation error vs SNR and pairs", 1000,
       run_haralick_2d2d},
      {"haralick-3d3d", "Haralick Sec. 3: 3D-3D rotation error vs SNR and pairs", 1000,
       run_haralick_3d3d},
      {"haralick-two-view", "Haralick Sec. 4, Table 1: two-view SNR knees, three scenes", 300,
       run_haralick_two_view},
      {"wu-points", "Wu & Wu Sec. 3: accuracy and time vs number of points (60 dB)", 500,
       run_wu_points},
      {"wu-snr", "Wu & Wu Sec. 3: accuracy and time vs SNR (10 points)", 500, run_wu_snr},
  };
  return registry;
}

std::string experiment_names() {
  std::string names;
  for (const Experiment& e : experiment_registry()) names += (names.empty() ? "" : ", ") + e.name;
  return names;
}

ExperimentResult run_experiment(const std::string& name, const ExperimentOptions& options) {
  const Experiment* experiment = nullptr;
  for (const Experiment& e : experiment_registry()) {
    if (e.name == name) experiment = &e;
  }
  if (!experiment) {
    throw InvalidArgument("NAME: unknown experiment '" + name + "' (known: " + experiment_names() +
                          ")");
  }
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument(why);
  std::error_code error;
  std::filesystem::create_directories(options.out_dir, error);
  if (error || !std::filesystem::is_directory(options.out_dir)) {
    throw InvalidArgument("--out: cannot create directory '" + options.out_dir + "'");
  }
  const long trials = options.trials > 0 ? options.trials
                      : options.quick    ? std::min<long>(experiment->default_trials, 20)
                                         : experiment->default_trials;
  const auto start = std::chrono::steady_clock::now();
  ExperimentResult result = experiment->run(options, trials);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.name = name;
  result.trials_per_cell = trials;
  result.summary["experiment"] = name;
  result.summary["trials_per_cell"] = trials;
  result.summary["seed"] = options.seed;
  result.summary["quick"] = options.quick;
  result.summary["seconds"] = result.seconds;
  const std::string json_path = internal::output_path(options, "summary.json");
  const std::string md_path = internal::output_path(options, "summary.md");
  std::ofstream(json_path) << result.summary.dump(2) << "\n";
  std::ofstream(md_path) << result.table;
  result.files.push_back(json_path);
  result.files.push_back(md_path);
  return result;
}

}  // namespace vantage::simulate
