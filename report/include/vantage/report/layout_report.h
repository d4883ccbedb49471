#pragma once

/// The one layout report: everything `vantage analyze` reports about a layout, computed by one
/// library call (the style of Ceres' Solve + Summary). The CLI, the Python package, the viewer
/// and the figures all call analyze_layout() and only format its result.
///
/// What the numbers promise (docs/math.md §11-§13, README "How to read the report"): under the
/// affine camera with the LUB scale of Lemma 7, every data vector's reconstruction error at any
/// viewpoint is at most arccos(p-bar_min) (Eq. 30). It is a bound per data vector, not on any
/// estimator's pose error, and it does not depend on units (only on directions).

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/free_vectors.h"
#include "vantage/analysis/layout.h"
#include "vantage/analysis/mesh_report.h"
#include "vantage/report/dropout.h"
#include "vantage/sdp/layout_analysis.h"
#include "vantage/sdp/layout_measures.h"
#include "vantage/tracker/identification.h"
#include "vantage/visibility/visibility_report.h"

namespace vantage::report {

/// Options of analyze_layout().
struct LayoutReportOptions {
  /// Point mode: the weight of the free vector z_j - z_i from the markers' weights.
  PairWeighting pair_weighting = PairWeighting::kGeometricMean;
  /// The worst viewpoint, its cross-check, the swap sensitivity and the progress callback.
  sdp::LayoutAnalysisOptions analysis;
  /// Also analyse the layout without each of its entries (dropout_analysis()).
  bool dropout = false;
  DropoutOptions dropout_options;
  /// smallest_singular_value below which the data vectors count as nearly coplanar, >= 0.
  double coplanarity_threshold = 0.1;
  /// The analysis on the body, for a layout with normals (Layout::visibility); its `dropout`
  /// follows `dropout` above.
  visibility::VisibilityReportOptions visibility;
  /// Point mode: the identification margins (docs/math.md §24), their mirror search's budget.
  tracker::IdentificationOptions identification;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// The report of one layout.
struct LayoutReport {
  Layout layout;     ///< the layout analysed (validated)
  DataVectors data;  ///< its data vectors (free vectors in point mode)
  /// The layout seen whole: the worst viewpoint over the sphere (Theorem 6, global and
  /// certified), Eq. (30) errors, the paper's single LMI, the cross-check, swap sensitivity.
  sdp::LayoutAnalysis analysis;
  double ceiling = 1.0;          ///< sdp::pbar_ceiling(m) for the m data vectors
  sdp::Coplanarity coplanarity;  ///< of the data vectors
  /// The layout without each entry (when LayoutReportOptions::dropout).
  std::optional<DropoutAnalysis> dropout;
  /// The layout on its body (docs/math.md §20), for a layout with normals: the worst viewpoint
  /// over the trackable directions of the workspace, the coverage, the dropout under visibility.
  std::optional<visibility::VisibilityReport> visibility;
  /// The body's mesh, when the layout has one: its size, whether it is closed and consistently
  /// wound (informative, not part of is_usable(); MeshReport::warning() says what is wrong).
  std::optional<MeshReport> mesh;
  /// Point mode: how a tracker tells the markers apart by their distances and how far the layout
  /// is from its mirror image (docs/math.md §24); informative, not part of is_usable().
  std::optional<tracker::IdentificationMargins> identification;

  /// True when the numbers can be relied on: the worst viewpoint is certified and confirmed on
  /// the SDP, the cross-check (when run) agrees, the layout is not degenerate, and the dropout
  /// analysis (when run) is certified. `message` gives every reason when it is false.
  bool is_usable() const;
  /// Every reason the report is not usable, joined by "; " (empty when it is).
  std::string message() const;

  /// The verdict in a few lines: p-bar_min against the ceiling, the worst-case error, the
  /// worst viewpoint and the certificate (the head of `vantage analyze`'s text report).
  std::string brief_report() const;

  /// "v3" for data vector 3 in direction mode, "p2-p7" for the free vector from marker 2 to
  /// marker 7 in point mode (the markers' names when the layout has them).
  std::string vector_label(long k) const;
  /// "v3" or "p3" (or the marker's name) for entry k of the layout.
  std::string entry_label(long k) const;
};

/// The whole analysis of `layout` (see the file comment). Throws InvalidArgument on an invalid
/// layout (Layout::validate(), naming the file's fields: "points", "vectors", "weights") or
/// options; a numerical outcome (not certified, degenerate) is in the report.
LayoutReport analyze_layout(const Layout& layout, const LayoutReportOptions& options = {});

/// The report as the one JSON object `vantage analyze --json` prints (README, "vantage
/// analyze"), two-space indented; `vantage.LayoutReport.to_dict()` is this object.
std::string to_json(const LayoutReport& report);

}  // namespace vantage::report
