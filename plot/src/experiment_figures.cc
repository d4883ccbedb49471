#include "vantage/plot/experiment_figures.h"

#include <algorithm>

#include "experiment_plotting.h"
#include "vantage/analysis/common.h"

namespace vantage::plot {
namespace {

// Haralick's knee plot: where does the mean rotation error cross 1° as the SNR drops?
void write_haralick_knee(const std::filesystem::path& sweep_csv, const std::string& problem,
                         std::vector<FigureFiles>& files, const FigureOptions& options) {
  internal::write_sweep_figure(
      {sweep_csv, sweep_csv.stem().string() + "_knee",
       "Haralick " + problem + ": where does the error cross 1°?",
       "mean rotation error against SNR, one line per number of pairs n and noise model", "snr_db",
       "SNR (dB)", "rot_err_deg_mean", "mean rotation error (degrees, log scale)", 1e-4, true},
      options, files);
}

}  // namespace

std::vector<std::string> experiment_figure_names() {
  return {"bound",         "mcinroy-orientation", "mcinroy-pose", "haralick-2d2d",
          "haralick-3d3d", "haralick-two-view",   "wu-points",    "wu-snr"};
}

std::vector<FigureFiles> write_experiment_figures(const std::string& name,
                                                  const std::filesystem::path& directory,
                                                  const FigureOptions& options) {
  const std::vector<std::string> names = experiment_figure_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    throw InvalidArgument("name: no figures for experiment \"" + name + "\"");
  }
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options." + why);
  if (!std::filesystem::is_directory(directory)) {
    throw InvalidArgument("directory: " + directory.string() + " is not a directory");
  }
  std::vector<FigureFiles> files;
  if (name == "bound") internal::write_bound_figure(directory, options, files);
  if (name == "mcinroy-orientation") {
    internal::write_error_cdf_figure(
        {directory / "mcinroy_orientation_trials.csv", "mcinroy_orientation",
         "Orientation from one affine image: error distribution",
         "fraction of trials with rotation error ≤ x, standard vs new estimator (vantage "
         "experiment mcinroy-orientation)"},
        options, files);
  }
  if (name == "mcinroy-pose") {
    internal::write_error_cdf_figure(
        {directory / "mcinroy_pose_trials.csv", "mcinroy_pose",
         "Pose at the certified worst viewpoint: error distribution",
         "fraction of layouts with rotation error ≤ x, one line per estimator (vantage "
         "experiment mcinroy-pose)"},
        options, files);
  }
  if (name == "haralick-2d2d")
    write_haralick_knee(directory / "haralick_2d2d.csv", "2D-2D", files, options);
  if (name == "haralick-3d3d")
    write_haralick_knee(directory / "haralick_3d3d.csv", "3D-3D", files, options);
  if (name == "wu-points") {
    const std::filesystem::path csv = directory / "wu_points.csv";
    internal::write_sweep_figure(
        {csv, "wu_points_accuracy", "Wu & Wu: accuracy against the number of points",
         "mean rotation error of each estimator (vantage experiment wu-points)", "n",
         "number of points n", "rot_err_deg_mean", "mean rotation error (degrees, log scale)", 1e-4,
         true},
        options, files);
    internal::write_sweep_figure(
        {csv, "wu_points_time", "Wu & Wu: time per solve against the number of points",
         "median time per solve of each estimator (vantage experiment wu-points)", "n",
         "number of points n", "time_us_median", "median time per solve (µs, log scale)", 1e-2,
         false},
        options, files);
  }
  if (name == "wu-snr") {
    internal::write_sweep_figure(
        {directory / "wu_snr.csv", "wu_snr_accuracy", "Wu & Wu: accuracy against SNR",
         "mean rotation error of each estimator (vantage experiment wu-snr)", "snr_db", "SNR (dB)",
         "rot_err_deg_mean", "mean rotation error (degrees, log scale)", 1e-4, true},
        options, files);
  }
  if (name == "haralick-two-view") {
    std::vector<std::filesystem::path> sweeps;
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
      const std::string file = entry.path().filename().string();
      if (file.rfind("haralick_two_view_", 0) == 0 && entry.path().extension() == ".csv" &&
          file.find("_knee") == std::string::npos) {
        sweeps.push_back(entry.path());
      }
    }
    if (sweeps.empty()) {
      throw InvalidArgument(directory.string() +
                            ": no haralick_two_view_*.csv (run `vantage "
                            "experiment haralick-two-view` first)");
    }
    std::sort(sweeps.begin(), sweeps.end());
    for (const auto& sweep : sweeps) {
      const std::string stem = sweep.stem().string();
      write_haralick_knee(sweep,
                          "two-view, " + stem.substr(std::string("haralick_two_view_").size()),
                          files, options);
    }
  }
  return files;
}

}  // namespace vantage::plot
