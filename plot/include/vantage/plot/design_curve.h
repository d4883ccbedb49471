#pragma once

/// Figure `design`: p_bar_min of the inductive augmenter (vantage design) after each step
/// against the number m of data vectors, the direct optimiser's answer and the ceiling
/// cos(pi / (2 m)) (docs/math.md §15).

#include <filesystem>
#include <string>
#include <vector>

#include "vantage/design/augment.h"
#include "vantage/plot/figure.h"

namespace vantage::plot {

/// The numbers of a design run, from design::AugmentResult or from `vantage design --json`.
struct DesignCurve {
  std::string layout_name;
  /// Greedy path: entry 0 is the initial layout, entry k the layout after step k.
  std::vector<int> n_vectors;    ///< m, data vectors (free vectors in point mode), >= 1
  std::vector<double> pbar_min;  ///< global p_bar_min, in [0, 1]
  bool has_direct = false;       ///< the direct optimiser ran
  int direct_n_vectors = 0;      ///< m of the directly optimised layout
  double direct_pbar_min = 0.0;

  /// True when the fields are consistent (equal non-empty lengths, m >= 1, p_bar in [0, 1]);
  /// otherwise *why names the field.
  bool is_valid(std::string* why = nullptr) const;
};

/// The curve of an augment_layout() result.
DesignCurve design_curve(const design::AugmentResult& result, const std::string& layout_name);

/// Writes design.<ext> and design.csv (columns series,step,n_vectors,pbar_min: series "greedy"
/// with step 0..K, "direct" with step K, "ceiling" cos(pi/(2m)) with step -1 for every m of
/// the plotted range) into `directory`. Throws InvalidArgument on an invalid curve or options,
/// RenderError when drawing or writing fails.
FigureFiles write_design_curve(const DesignCurve& curve, const std::filesystem::path& directory,
                               const FigureOptions& options = {});

}  // namespace vantage::plot
