#pragma once

/// Figures of a `vantage experiment NAME --out DIR` directory, drawn from the CSV files the
/// experiment wrote there:
///   bound               bound.<ext>: per-vector orientation error and the affine estimator's
///                       rotation error against p̄(a), under the curve arccos p̄(a) (Eq. 30)
///   mcinroy-orientation mcinroy_orientation.<ext>: empirical CDF of the rotation error of the
///                       standard and the new (affine) estimator for each n
///   mcinroy-pose        mcinroy_pose.<ext>: the same for the pose estimators at the certified
///                       worst viewpoint
///   haralick-2d2d, haralick-3d3d
///                       haralick_2d2d_knee.<ext> / haralick_3d3d_knee.<ext>: mean rotation error
///                       against SNR, one line per number of pairs and noise, with the 1° line
///   haralick-two-view   haralick_two_view_<scene>_knee.<ext>, the same for every scene file
///   wu-points           wu_points_accuracy.<ext> and wu_points_time.<ext>: mean rotation
///                       error and median time per solve against the number of points, one
///                       line per estimator
///   wu-snr              wu_snr_accuracy.<ext>: mean rotation error against SNR, one line per
///                       estimator
/// No figure overwrites the experiment's own CSV files.
/// Each figure also writes <figure>.csv with the numbers it draws.

#include <filesystem>
#include <string>
#include <vector>

#include "vantage/plot/figure.h"

namespace vantage::plot {

/// The experiments that have figures (names as `vantage experiment` takes them).
std::vector<std::string> experiment_figure_names();

/// Reads the CSV files of experiment `name` from `directory` and writes its figures there.
/// Throws InvalidArgument for an unknown name, invalid options or a missing or malformed CSV
/// (naming the file and the column or line), RenderError when drawing or writing fails.
std::vector<FigureFiles> write_experiment_figures(const std::string& name,
                                                  const std::filesystem::path& directory,
                                                  const FigureOptions& options = {});

}  // namespace vantage::plot
