#include "vantage/plot/experiment_figures.h"

#include <algorithm>

#include "experiment_plotting.h"
#include "vantage/analysis/common.h"

namespace vantage::plot {

std::vector<std::string> experiment_figure_names() {
  return {"bound", "mcinroy-orientation", "haralick-2d2d", "haralick-3d3d", "haralick-two-view"};
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
    internal::write_mcinroy_orientation_figure(directory, options, files);
  }
  if (name == "haralick-2d2d") {
    internal::write_haralick_figure(directory / "haralick_2d2d.csv", "haralick_2d2d_knee",
                                    "Haralick 2D-2D: where does the error cross 1°?", options,
                                    files);
  }
  if (name == "haralick-3d3d") {
    internal::write_haralick_figure(directory / "haralick_3d3d.csv", "haralick_3d3d_knee",
                                    "Haralick 3D-3D: where does the error cross 1°?", options,
                                    files);
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
      internal::write_haralick_figure(
          sweep, stem + "_knee",
          "Haralick two-view (" + stem.substr(std::string("haralick_two_view_").size()) + ")",
          options, files);
    }
  }
  return files;
}

}  // namespace vantage::plot
