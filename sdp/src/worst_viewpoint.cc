#include "vantage/sdp/worst_viewpoint.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "min_norm_point.h"
#include "vantage/analysis/common.h"

namespace vantage::sdp {
namespace {

// A circle this close to a patch's bounding cap (in sin of the angle) counts as crossing it.
constexpr double kCrossingSlack = 1e-15;
// A subset-cell optimum is exact for the full cell when the full objective at its point is
// within this of it (both are computed to ~1e-14).
constexpr double kCellExact = 1e-12;
// Viewpoints closer than this (1 - |a.b|) are the same optimum.
constexpr double kSameViewpoint = 1e-9;
// Attained values this close to the best are equal up to rounding (each is min_i |a.n_i|, dot
// products of unit vectors accurate to a few ulps): among them the reported viewpoint is the
// lexicographically first, so exactly symmetric layouts give a canonical answer. Far below any
// certificate_tolerance, and the only slack allowed between t_lower and the best attained value.
constexpr double kSameValue = 1e-14;
// Patches with an angular radius below this are not subdivided further.
constexpr double kMinPatchRadius = 1e-11;
// Initial grid per cube face (kGrid x kGrid patches).
constexpr int kGrid = 4;
// Recursion depth limit; patches halve per level, so kMinPatchRadius is reached long before.
constexpr int kMaxDepth = 120;

Eigen::Vector3d face_point(int face, double u, double v) {
  switch (face) {
    case 0:
      return Eigen::Vector3d(1.0, u, v).normalized();
    case 1:
      return Eigen::Vector3d(u, 1.0, v).normalized();
    default:
      return Eigen::Vector3d(u, v, 1.0).normalized();
  }
}

struct Candidate {
  Eigen::Vector3d a;
  double value;
};

// Branch and bound over cube-face patches, see global_worst_viewpoint().
class GlobalSearch {
 public:
  GlobalSearch(const Eigen::Matrix3Xd& n, const WorstViewpointOptions& options)
      : n_(n), m_(static_cast<int>(n.cols())), options_(options) {
    nt_ = n_.transpose();
    scratch_.resize(m_);
    cell_points_.resize(3, m_);
    // Reserved up front: sub-patch recursion must never reallocate the per-depth lists.
    lists_.reserve(kMaxDepth + 1);
    dots_.reserve(kMaxDepth + 1);
  }

  void run() {
    struct Root {
      int face;
      double u, v;
      double value;
    };
    std::vector<Root> roots;
    const double h = 1.0 / kGrid;
    for (int face = 0; face < 3; ++face) {
      for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
          const double u = -1.0 + (2 * i + 1) * h;
          const double v = -1.0 + (2 * j + 1) * h;
          roots.push_back({face, u, v, full_objective(face_point(face, u, v))});
        }
      }
    }
    std::sort(roots.begin(), roots.end(),
              [](const Root& a, const Root& b) { return a.value > b.value; });
    for (int s = 0; s < std::min<int>(4, static_cast<int>(roots.size())); ++s) {
      solve_full_cell(face_point(roots[s].face, roots[s].u, roots[s].v));
    }
    std::vector<int> all(m_);
    for (int i = 0; i < m_; ++i) all[i] = i;
    for (const Root& root : roots) process(root.face, root.u, root.v, h, all.data(), m_, 0);
  }

  double lower() const { return lower_; }
  double upper() const { return std::max(upper_, lower_); }
  long cells_solved() const { return cells_solved_; }
  long patches() const { return patches_; }
  bool exhausted() const { return exhausted_; }

  std::vector<Candidate> optima() const {
    std::vector<Candidate> kept;
    for (const Candidate& c : candidates_) {
      if (c.value < lower_ - options_.tie_tolerance) continue;
      bool duplicate = false;
      for (Candidate& k : kept) {
        if (1.0 - std::abs(k.a.dot(c.a)) <= kSameViewpoint) {
          duplicate = true;
          if (c.value > k.value) k = c;
        }
      }
      if (!duplicate) kept.push_back(c);
    }
    return kept;
  }

 private:
  double full_objective(const Eigen::Vector3d& a) {
    scratch_.noalias() = nt_ * a;
    return scratch_.cwiseAbs().minCoeff();
  }

  void offer(const Eigen::Vector3d& a, double value) {
    if (value < lower_ - options_.tie_tolerance) return;
    if (value > lower_) lower_ = value;
    candidates_.push_back({a, value});
  }

  // Exact optimum of the cell containing c (all circles); returns it and offers its point.
  double solve_full_cell(const Eigen::Vector3d& c) {
    scratch_.noalias() = nt_ * c;
    for (int i = 0; i < m_; ++i) {
      cell_points_.col(i) = scratch_(i) >= 0.0 ? n_.col(i) : Eigen::Vector3d(-n_.col(i));
    }
    ++cells_solved_;
    const internal::MinNormPoint p = internal::min_norm_point(cell_points_.data(), m_);
    if (p.contains_origin) return 0.0;
    const double t_cell = p.x.norm();
    const Eigen::Vector3d a = p.x / t_cell;
    offer(a, full_objective(a));
    return t_cell;
  }

  void process(int face, double u, double v, double h, const int* parent, int parent_count,
               int depth) {
    ++patches_;
    const Eigen::Vector3d c = face_point(face, u, v);
    double cos_r = 1.0;
    for (int corner = 0; corner < 4; ++corner) {
      const double cu = u + ((corner & 1) ? h : -h);
      const double cv = v + ((corner & 2) ? h : -h);
      cos_r = std::min(cos_r, c.dot(face_point(face, cu, cv)));
    }
    cos_r = std::clamp(cos_r, 0.0, 1.0);
    const double sin_r = std::sqrt(1.0 - cos_r * cos_r);

    if (static_cast<int>(lists_.size()) <= depth) {
      lists_.emplace_back(m_);
      dots_.emplace_back(m_);
    }
    std::vector<double>& dots = dots_[depth];
    double bound = 1.0;
    double centre_value = 1.0;
    for (int k = 0; k < parent_count; ++k) {
      const int i = parent[k];
      const double d = c.x() * n_(0, i) + c.y() * n_(1, i) + c.z() * n_(2, i);
      const double ad = std::abs(d);
      dots[k] = d;
      centre_value = std::min(centre_value, ad);
      if (ad < cos_r) {
        bound = std::min(bound, ad * cos_r + std::sqrt(std::max(0.0, 1.0 - ad * ad)) * sin_r);
      }
    }
    if (bound < lower_ - options_.tie_tolerance) return;  // pruned: bound < attained value

    if (centre_value > lower_ && full_objective(c) > lower_) solve_full_cell(c);

    // Circles whose minimum over the patch exceeds the attained value (or the bound) cannot
    // decide a prune of any sub-patch: drop them from the sub-patches' lists.
    std::vector<int>& list = lists_[depth];
    int count = 0;
    bool crossing = false;
    const double keep_below = std::min(lower_, bound);
    for (int k = 0; k < parent_count; ++k) {
      const double ad = std::abs(dots[k]);
      double low = 0.0;
      if (ad > sin_r + kCrossingSlack) {
        low = ad * cos_r - std::sqrt(std::max(0.0, 1.0 - ad * ad)) * sin_r;
      } else {
        crossing = true;
      }
      if (low <= keep_below) {
        list[count] = parent[k];
        dots[count] = dots[k];
        ++count;
      }
    }

    if (!crossing) {
      close_single_cell(c, list.data(), dots.data(), count);
      return;
    }
    if (std::asin(sin_r) < kMinPatchRadius || patches_ >= options_.max_patches ||
        depth >= kMaxDepth) {
      upper_ = std::max(upper_, bound);
      if (patches_ >= options_.max_patches) exhausted_ = true;
      return;
    }
    const double q = 0.5 * h;
    for (int child = 0; child < 4; ++child) {
      process(face, u + ((child & 1) ? q : -q), v + ((child & 2) ? q : -q), q, list.data(), count,
              depth + 1);
    }
  }

  // The patch lies in one cell: its optimum over the kept circles bounds the patch; it is the
  // exact cell optimum when the full objective attains it.
  void close_single_cell(const Eigen::Vector3d& c, const int* list, const double* dots, int count) {
    if (count == 0) {
      solve_full_cell_and_bound(c);
      return;
    }
    for (int k = 0; k < count; ++k) {
      const int i = list[k];
      cell_points_.col(k) = dots[k] >= 0.0 ? n_.col(i) : Eigen::Vector3d(-n_.col(i));
    }
    ++cells_solved_;
    const internal::MinNormPoint p = internal::min_norm_point(cell_points_.data(), count);
    const double t_sub = p.contains_origin ? 0.0 : p.x.norm();
    if (t_sub < lower_ - options_.tie_tolerance) {
      upper_ = std::max(upper_, std::min(t_sub, lower_));
      return;
    }
    const Eigen::Vector3d a = p.x / t_sub;
    const double value = full_objective(a);
    offer(a, value);
    if (value >= t_sub - kCellExact) {
      upper_ = std::max(upper_, t_sub);
      return;
    }
    solve_full_cell_and_bound(c);
  }

  void solve_full_cell_and_bound(const Eigen::Vector3d& c) {
    upper_ = std::max(upper_, solve_full_cell(c));
  }

  const Eigen::Matrix3Xd& n_;
  const int m_;
  const WorstViewpointOptions& options_;
  Eigen::Matrix<double, Eigen::Dynamic, 3> nt_;
  Eigen::VectorXd scratch_;
  Eigen::Matrix3Xd cell_points_;
  std::vector<std::vector<int>> lists_;
  std::vector<std::vector<double>> dots_;
  std::vector<Candidate> candidates_;
  double lower_ = 0.0;
  double upper_ = 0.0;
  long cells_solved_ = 0;
  long patches_ = 0;
  bool exhausted_ = false;
};

bool lexicographically_before(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  for (int k = 2; k >= 0; --k) {
    if (a(k) != b(k)) return a(k) > b(k);
  }
  return false;
}

}  // namespace

Eigen::Matrix3Xd normalized_columns(const Eigen::Matrix3Xd& vectors, const char* argument) {
  Eigen::Matrix3Xd n(3, vectors.cols());
  for (Eigen::Index i = 0; i < vectors.cols(); ++i) {
    const Eigen::Vector3d z = vectors.col(i);
    const double norm = z.norm();
    if (!z.allFinite() || !(norm > 0.0) || !std::isfinite(norm)) {
      std::ostringstream out;
      out << argument << ": column " << i << " is zero or not finite";
      throw InvalidArgument(out.str());
    }
    n.col(i) = z / norm;
  }
  return n;
}

double min_abs_projection(const Eigen::Matrix3Xd& unit_vectors, const Eigen::Vector3d& a) {
  return (unit_vectors.transpose() * a).cwiseAbs().minCoeff();
}

double pbar_from_t(double t) {
  const double c = std::clamp(t, 0.0, 1.0);
  return std::sqrt((1.0 - c) * (1.0 + c));
}

Eigen::Vector3d upper_hemisphere(const Eigen::Vector3d& a) {
  if (a.z() > 0.0) return a;
  if (a.z() < 0.0) return -a;
  if (a.y() > 0.0) return a;
  if (a.y() < 0.0) return -a;
  return a.x() >= 0.0 ? a : Eigen::Vector3d(-a);
}

Eigen::VectorXd upper_hemisphere_signs(const Eigen::Matrix3Xd& vectors) {
  Eigen::VectorXd signs(vectors.cols());
  for (Eigen::Index i = 0; i < vectors.cols(); ++i) {
    const Eigen::Vector3d z = vectors.col(i);
    signs(i) = upper_hemisphere(z) == z ? 1.0 : -1.0;
  }
  return signs;
}

const char* to_string(CellViewpoint::Status status) {
  switch (status) {
    case CellViewpoint::Status::kOk:
      return "ok";
    case CellViewpoint::Status::kEmptyCell:
      return "empty_cell";
    case CellViewpoint::Status::kSolverFailed:
      return "solver_failed";
  }
  return "unknown";
}

const char* to_string(WorstViewpoint::Status status) {
  switch (status) {
    case WorstViewpoint::Status::kCertified:
      return "certified";
    case WorstViewpoint::Status::kNotCertified:
      return "not_certified";
    case WorstViewpoint::Status::kSdpDisagrees:
      return "sdp_disagrees";
  }
  return "unknown";
}

CellViewpoint solve_cell_lmi(const Eigen::Matrix3Xd& vectors, const Eigen::VectorXd& signs,
                             const SdpOptions& options) {
  if (vectors.cols() < 1) throw InvalidArgument("solve_cell_lmi: vectors has no column");
  if (signs.size() != vectors.cols()) {
    throw InvalidArgument("solve_cell_lmi: signs must have one entry per column of vectors");
  }
  for (Eigen::Index i = 0; i < signs.size(); ++i) {
    if (signs(i) != 1.0 && signs(i) != -1.0) {
      throw InvalidArgument("solve_cell_lmi: signs(" + std::to_string(i) + ") is not +1 or -1");
    }
  }
  const Eigen::Matrix3Xd n = normalized_columns(vectors, "solve_cell_lmi: vectors");
  const int m = static_cast<int>(n.cols());
  // y = [a_x, a_y, a_z, t]; minimise -t.
  LmiProblem problem(4);
  problem.set_objective(3, -1.0);
  for (int i = 0; i < m; ++i) {
    const int b = problem.add_dense_block(2);
    for (int k = 0; k < 3; ++k) {
      const double p = signs(i) * n(k, i);
      if (p == 0.0) continue;
      problem.add_variable_entry(k, b, 0, 0, p);
      problem.add_variable_entry(k, b, 1, 1, p);
    }
    problem.add_variable_entry(3, b, 0, 1, 1.0);
  }
  const int ball = problem.add_dense_block(4);
  for (int k = 0; k < 3; ++k) problem.add_variable_entry(k, ball, k, 3, 1.0);
  for (int k = 0; k < 4; ++k) problem.add_constant_entry(ball, k, k, -1.0);

  CellViewpoint result;
  result.sdp = solve_lmi(problem, options);
  if (!has_solution(result.sdp.status)) {
    result.status = CellViewpoint::Status::kSolverFailed;
    result.message =
        std::string("cell LMI: ") + to_string(result.sdp.status) + ": " + result.sdp.message;
    return result;
  }
  // The SDP's t is accurate to its tolerance only; report what the normalised viewpoint attains
  // in the cell, min_i s_i a.n_i, so that t never exceeds a value some viewpoint achieves.
  const Eigen::Vector3d a = result.sdp.y.head<3>();
  const double t_sdp = result.sdp.y(3);
  if (t_sdp <= CellViewpoint::kEmptyCellT || !(a.norm() > 0.0)) {
    result.t = t_sdp;
    result.pbar = pbar_from_t(std::max(0.0, t_sdp));
    result.status = CellViewpoint::Status::kEmptyCell;
    result.message = "the sign cell is empty: 0 is in conv{s_i n_i}";
    return result;
  }
  const Eigen::Vector3d unit_a = a.normalized();
  result.t = (signs.asDiagonal() * (n.transpose() * unit_a)).minCoeff();
  result.pbar = pbar_from_t(std::max(0.0, result.t));
  result.viewpoint = upper_hemisphere(unit_a);
  result.status = CellViewpoint::Status::kOk;
  return result;
}

Eigen::VectorXd paper_signs(const Eigen::Matrix3Xd& vectors) {
  const Eigen::Matrix3Xd unit = normalized_columns(vectors, "vectors");
  const internal::MinNormPoint hull =
      internal::min_norm_point(unit.data(), static_cast<int>(unit.cols()));
  if (!hull.contains_origin) return Eigen::VectorXd::Ones(unit.cols());
  return upper_hemisphere_signs(unit);
}

CellViewpoint paper_worst_viewpoint(const Eigen::Matrix3Xd& vectors, const SdpOptions& options) {
  return solve_cell_lmi(vectors, paper_signs(vectors), options);
}

bool WorstViewpointOptions::is_valid(std::string* why) const {
  auto fail = [why](const char* text) {
    if (why != nullptr) *why = text;
    return false;
  };
  if (!(certificate_tolerance >= 1e-15 && certificate_tolerance <= 1e-3)) {
    return fail("WorstViewpointOptions::certificate_tolerance must be in [1e-15, 1e-3]");
  }
  if (!(tie_tolerance >= 0.0 && tie_tolerance <= 1e-3)) {
    return fail("WorstViewpointOptions::tie_tolerance must be in [0, 1e-3]");
  }
  if (max_patches < 1) return fail("WorstViewpointOptions::max_patches must be >= 1");
  std::string sdp_why;
  if (!sdp.is_valid(&sdp_why)) {
    if (why != nullptr) *why = "WorstViewpointOptions::sdp: " + sdp_why;
    return false;
  }
  return true;
}

WorstViewpoint global_worst_viewpoint(const Eigen::Matrix3Xd& vectors,
                                      const WorstViewpointOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("global_worst_viewpoint: options: " + why);
  if (vectors.cols() < 2) {
    throw InvalidArgument("global_worst_viewpoint: vectors must have at least 2 columns, got " +
                          std::to_string(vectors.cols()));
  }
  const Eigen::Matrix3Xd n = normalized_columns(vectors, "global_worst_viewpoint: vectors");
  GlobalSearch search(n, options);
  search.run();

  WorstViewpoint result;
  std::vector<Candidate> optima = search.optima();
  VANTAGE_CHECK(!optima.empty(), "the branch and bound found no attained viewpoint");
  // The reported viewpoint must attain the best value found: t_upper is certified against that
  // value, so reporting another tie (up to tie_tolerance below it) would widen the certificate by
  // up to tie_tolerance. Only values equal to the best up to rounding are ordered
  // lexicographically; the other ties follow by decreasing value. The group is fixed before
  // sorting, so the comparison is a strict weak ordering.
  double best = 0.0;
  for (Candidate& c : optima) {
    c.a = upper_hemisphere(c.a);
    best = std::max(best, c.value);
  }
  std::sort(optima.begin(), optima.end(), [&](const Candidate& a, const Candidate& b) {
    const bool a_best = a.value >= best - kSameValue;
    const bool b_best = b.value >= best - kSameValue;
    if (a_best != b_best) return a_best;
    if (!a_best && a.value != b.value) return a.value > b.value;
    return lexicographically_before(a.a, b.a);
  });
  result.viewpoint = optima.front().a;
  for (const Candidate& c : optima) result.viewpoints.push_back(c.a);
  result.t = min_abs_projection(n, result.viewpoint);
  result.t_lower = result.t;
  result.t_upper = std::max(search.upper(), result.t);
  result.pbar = pbar_from_t(result.t);
  result.cells_solved = search.cells_solved();
  result.patches = search.patches();
  const bool certified =
      !search.exhausted() && result.t_upper - result.t_lower <= options.certificate_tolerance;
  result.status =
      certified ? WorstViewpoint::Status::kCertified : WorstViewpoint::Status::kNotCertified;
  if (!certified) {
    std::ostringstream out;
    out << "not certified: t_upper - t_lower = " << result.t_upper - result.t_lower << " after "
        << result.patches << " patches";
    result.message = out.str();
  }
  if (options.confirm_with_sdp) {
    Eigen::VectorXd signs(n.cols());
    for (Eigen::Index i = 0; i < n.cols(); ++i) {
      signs(i) = n.col(i).dot(result.viewpoint) >= 0.0 ? 1.0 : -1.0;
    }
    result.confirmation = solve_cell_lmi(n, signs, options.sdp);
    result.sdp_confirmed = true;
    const bool agrees = result.confirmation.status == CellViewpoint::Status::kOk &&
                        std::abs(result.confirmation.t - result.t) <= WorstViewpoint::kSdpAgreement;
    if (!agrees) {
      std::ostringstream out;
      out << "SDP confirmation disagrees: cell LMI " << to_string(result.confirmation.status)
          << " t = " << result.confirmation.t << " vs t = " << result.t;
      if (!result.message.empty()) result.message += "; ";
      result.message += out.str();
      if (certified) result.status = WorstViewpoint::Status::kSdpDisagrees;
    }
  }
  return result;
}

}  // namespace vantage::sdp
