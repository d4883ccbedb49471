#pragma once

/// One call that runs the whole worst-viewpoint analysis of a set of data vectors: Theorem 6
/// (global, certified, every optimum up to sign), the paper's single LMI beside it, Eq. (30)
/// worst-case errors, the NLopt cross-check and Prop. 2 swap sensitivity. Statuses are the
/// library's enums; `vantage analyze --json` converts them (cli/analyze.cc, one place).

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "vantage/analysis/swap_sensitivity.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::sdp {

/// Options of analyze_vectors().
struct LayoutAnalysisOptions {
  WorstViewpointOptions worst_viewpoint;  ///< confirm_with_sdp is forced on by analyze_vectors
  CrossCheckOptions crosscheck;
  bool run_crosscheck = true;  ///< false skips NLopt (crosscheck.ran = false)
  int swap_count = 5;          ///< worst swap pairs reported, >= 1
  /// Called with the stage about to run ("cross-check", ...), e.g. to show progress.
  std::function<void(const std::string& stage)> progress;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Every data vector parallel to one line (|n_i x n_0| below this for unit vectors): collinear
/// points, or duplicated and antiparallel vectors. Then t = 1, p-bar_min = 0, the LUB scale is
/// undefined and the rotation about the common line is not determined.
constexpr double kParallelTolerance = 1e-12;

/// True when a layout with this p-bar_min and t = sqrt(1 - p-bar_min^2) is near-degenerate
/// (docs/math.md, "Near-degenerate layouts"): 1 - t <= certificate_tolerance, evaluated as
/// p-bar_min^2 / (1 + t) so that it keeps its digits where t has rounded to 1. t is a
/// second-order function of the angle asin(p-bar_min) by which the vectors leave a common line
/// (1 - t ~ p-bar_min^2 / 2), so a certificate of that width then includes t = 1, the value of
/// an exactly degenerate layout: p-bar_min <= sqrt(2 certificate_tolerance), 4.5e-5 at the
/// default 1e-9.
bool is_near_degenerate(double pbar_min, double t, double certificate_tolerance);

/// Everything `vantage analyze` reports for one set of vectors.
struct LayoutAnalysis {
  /// All data vectors are parallel (kParallelTolerance): the pose is not determined. The
  /// worst-case errors are then arccos(p-bar_min) = 90 degrees (not 0), and `message` says why.
  bool degenerate = false;
  /// Not degenerate, but is_near_degenerate(pbar_min, t, certificate_tolerance): every vector
  /// is so close to one line that the certificate cannot tell the layout from a degenerate one.
  /// The worst-case errors are Eq. (30) at the accurate p_i (close to 90 degrees), and `message`
  /// says why.
  bool near_degenerate = false;
  Eigen::Vector3d worst_viewpoint = Eigen::Vector3d::UnitZ();  ///< upper hemisphere
  std::vector<Eigen::Vector3d> worst_viewpoints;               ///< every global optimum up to sign
  double t = 0.0;                                              ///< max_a min_i |a.n_i| (Eq. 31)
  double pbar_min = 1.0;                                       ///< sqrt(1 - t^2) (Eq. 29 corrected)
  Eigen::VectorXd worst_case_errors_deg;  ///< Eq. (30) per vector at worst_viewpoint, degrees
  double max_worst_case_error_deg = 0.0;

  struct Certificate {
    double t_upper = 1.0;    ///< proven bound on t over the whole sphere
    double t_lower = 0.0;    ///< attained t
    bool certified = false;  ///< WorstViewpoint::certified(): the search's status is kCertified
  } certificate;

  struct PaperLmi {
    Eigen::Vector3d viewpoint = Eigen::Vector3d::UnitZ();
    double t = 0.0;
    double pbar_at = 1.0;  ///< p-bar(a) at `viewpoint`, as pbar_at() (>= the global pbar_min)
    /// kEmptyCell: the all-positive cell is empty and viewpoint/t/pbar mean nothing.
    CellViewpoint::Status status = CellViewpoint::Status::kSolverFailed;
  } paper_lmi;

  struct CrossCheckSummary {
    bool ran = false;     ///< false with run_crosscheck = false or without NLopt: fields unset
    std::string skipped;  ///< why it did not run, when it did not ("built without NLopt", ...)
    std::string method;   ///< "nlopt_multistart_cobyla" (when ran)
    double t = 0.0;
    bool agrees = false;
    std::string message;               ///< non-empty (loud) on disagreement
    int samples = 0;                   ///< CrossCheck::samples
    double sample_spacing = 0.0;       ///< CrossCheck::sample_spacing, rad
    bool samples_cover_cells = false;  ///< CrossCheck::samples_cover_cells
  } crosscheck;

  std::vector<SwapError> swaps;  ///< worst pairs, decreasing error_deg

  struct Solver {
    SdpBackend backend = SdpBackend::kCsdp;
    WorstViewpoint::Status status = WorstViewpoint::Status::kNotCertified;
    long cells_solved = 0;
    long patches = 0;
    SdpStatus sdp_status = SdpStatus::kBackendError;  ///< of the confirming cell LMI
  } solver;

  /// Certified, confirmed and (when run) the cross-check agrees: the numbers can be trusted.
  bool trusted() const;

  std::string message;  ///< empty when trusted and neither degenerate nor near-degenerate
};

/// Runs the analysis on data vectors (3 x m, m >= 2, non-zero finite columns; their lengths only
/// matter for the swap analysis) with weights (m positive entries or empty = all 1; used by the
/// swap analysis). Throws InvalidArgument on bad input or options.
LayoutAnalysis analyze_vectors(const Eigen::Matrix3Xd& vectors, const Eigen::VectorXd& weights = {},
                               const LayoutAnalysisOptions& options = {});

}  // namespace vantage::sdp
