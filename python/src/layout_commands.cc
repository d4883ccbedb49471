// vantage.analyze, vantage.design and vantage.weights: the library calls behind `vantage
// analyze`, `design` and `weights`, returning the fields of their --json output.

#include "layout_commands.h"

#include <pybind11/stl.h>

#include <mutex>

#include "analysis_json.h"
#include "arrays.h"
#include "layouts.h"
#include "results.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/free_vectors.h"
#include "vantage/design/augment.h"
#include "vantage/design/weights.h"
#include "vantage/sdp/layout_analysis.h"

namespace vantage::python {

namespace {

// analyze, design and weights run one at a time: two concurrent analyze_vectors calls abort the
// process (seen with three Python threads on note3; the non-reentrant part, CSDP's confirming
// solve or the NLopt cross-check, is not yet pinned down). Other Python threads keep running.
std::mutex solver_mutex;

template <typename F>
auto serialised(F&& f) {
  return without_gil([&] {
    const std::lock_guard<std::mutex> lock(solver_mutex);
    return f();
  });
}

Json json_list(const Eigen::VectorXd& v) {
  Json list = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) list.push_back(v(i));
  return list;
}

Json json_points(const std::vector<Eigen::Vector3d>& points) {
  Json list = Json::array();
  for (const Eigen::Vector3d& p : points) list.push_back(json_list(p));
  return list;
}

Json source_json(const std::string& source) {
  return source.empty() ? Json(nullptr) : Json(source);
}

py::object analyze(const py::object& layout_arg, const py::object& vectors,
                   const py::object& points, const py::object& weights, int swaps, bool crosscheck,
                   const std::string& pair_weighting, const py::kwargs& kwargs) {
  if (swaps < 1) throw InvalidArgument("swaps: must be >= 1");
  if (pair_weighting != "geometric" && pair_weighting != "arithmetic") {
    throw InvalidArgument("pair_weighting: expected geometric or arithmetic");
  }
  std::string source;
  const Layout layout =
      layout_from_arguments(layout_arg, vectors, points, weights, py::none(), kwargs, &source);
  const DataVectors data =
      data_vectors(layout, pair_weighting == "arithmetic" ? PairWeighting::kArithmeticMean
                                                          : PairWeighting::kGeometricMean);
  sdp::LayoutAnalysisOptions options;
  options.swap_count = swaps;
  options.run_crosscheck = crosscheck;
  const sdp::LayoutAnalysis report =
      serialised([&] { return sdp::analyze_vectors(data.vectors, data.weights, options); });
  const bool certified = report.solver.status == sdp::WorstViewpoint::Status::kCertified;
  const std::string status = report.degenerate ? "degenerate"
                             : !certified      ? sdp::to_string(report.solver.status)
                                               : "crosscheck_disagrees";
  const Json out = analysis_json::analysis(
      layout, data, report, design::pbar_ceiling(static_cast<int>(data.vectors.cols())));
  return result_or_raise(!report.trusted() || report.degenerate, status, report.message, out);
}

Json worst_json(const design::WorstCase& worst, int n_vectors) {
  Json out;
  out["pbar_min"] = worst.pbar_min;
  out["worst_viewpoints"] = json_points(worst.worst_viewpoints);
  out["max_worst_case_error_deg"] = worst.max_worst_case_error_deg;
  out["ceiling"] = design::pbar_ceiling(n_vectors);
  out["n_vectors"] = n_vectors;
  out["t"] = worst.t;
  out["certified"] = worst.certified;
  return out;
}

Json step_json(const design::AugmentStep& st, LayoutMode mode) {
  Json step;
  step["added"] = json_list(st.added);
  step["pbar_min"] = st.worst.pbar_min;
  step["worst_viewpoints"] = json_points(st.worst.worst_viewpoints);
  step["max_worst_case_error_deg"] = st.worst.max_worst_case_error_deg;
  step["ceiling"] = st.ceiling;
  step["n_vectors"] = st.vector_count;
  step["improved"] = st.improved;
  step["note"] = st.note;
  if (st.candidate_index >= 0) step["candidate_index"] = st.candidate_index;
  step["single_vector_can_improve"] = st.single_vector_can_improve;
  if (mode == LayoutMode::kVectors) {
    step["best_kill_level"] = st.best_kill_level;
    step["angle_from_worst_plane_deg"] = st.angle_from_worst_plane_deg;
  }
  step["t"] = st.worst.t;
  step["certified"] = st.worst.certified;
  step["global_solves"] = st.global_solves;
  return step;
}

Json design_json(const std::string& source, const Layout& layout, bool direct_asked,
                 const design::AugmentResult& r) {
  Json out;
  out["layout"] = source_json(source);
  out["name"] = layout.name;
  out["mode"] = to_string(layout.mode);
  out["status"] = design::to_string(r.status);
  if (!r.message.empty()) out["message"] = r.message;
  out["initial"] = worst_json(r.initial, r.initial_vector_count);
  Json steps = Json::array();
  for (const design::AugmentStep& st : r.steps) steps.push_back(step_json(st, layout.mode));
  out["steps"] = steps;
  out["final_pbar_min"] = r.final_pbar_min;
  if (r.direct.status == design::DirectResult::Status::kOk) {
    Json direct;
    direct["pbar_min"] = r.direct.worst.pbar_min;
    direct["added"] = json_points(r.direct.added);
    direct["method"] = r.direct.method;
    if (!r.direct.candidate_indices.empty()) {
      direct["candidate_indices"] = r.direct.candidate_indices;
    }
    direct["worst_viewpoints"] = json_points(r.direct.worst.worst_viewpoints);
    direct["max_worst_case_error_deg"] = r.direct.worst.max_worst_case_error_deg;
    direct["certified"] = r.direct.worst.certified;
    direct["global_solves"] = r.direct.global_solves;
    out["direct"] = direct;
  } else if (direct_asked) {
    out["direct_message"] = r.direct.message;
  }
  out["coplanarity"] = {
      {"initial", r.initial_coplanarity.smallest_singular_value},
      {"final", r.final_coplanarity.smallest_singular_value},
      {"nearly_coplanar", r.final_coplanarity.nearly_coplanar},
      {"threshold", design::AugmentOptions{}.coplanarity_threshold},
  };
  out["global_solves"] = r.global_solves;
  return out;
}

/// The augmented layout as `vantage design --write` writes it: the additions appended, the
/// candidates that were used dropped.
Layout layout_without_used_candidates(const design::AugmentResult& result) {
  Layout out = result.augmented;
  std::vector<bool> used(out.candidates.cols(), false);
  for (const design::AugmentStep& step : result.steps) {
    if (step.candidate_index >= 0) used[step.candidate_index] = true;
  }
  Eigen::Index count = 0;
  for (Eigen::Index c = 0; c < out.candidates.cols(); ++c) {
    if (!used[c]) out.candidates.col(count++) = out.candidates.col(c);
  }
  out.candidates.conservativeResize(3, count);
  return out;
}

py::object design_layout(const py::object& layout_arg, const py::object& vectors,
                         const py::object& points, const py::object& weights,
                         const py::object& candidates, int add, bool candidates_only, double margin,
                         bool direct, const py::kwargs& kwargs) {
  std::string source;
  const Layout layout =
      layout_from_arguments(layout_arg, vectors, points, weights, candidates, kwargs, &source);
  if (add < 1) throw InvalidArgument("add: must be >= 1, got " + std::to_string(add));
  design::AugmentOptions options;
  options.add = add;
  options.candidates_only = candidates_only;
  options.margin = margin;
  options.run_direct = direct;
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument(why);
  const design::AugmentResult r =
      serialised([&] { return design::augment_layout(layout, options); });
  const bool ok = r.status == design::AugmentResult::Status::kOk;
  py::object result = result_or_raise(!ok, design::to_string(r.status), r.message,
                                      design_json(source, layout, direct, r));
  result["augmented"] = py::cast(layout_without_used_candidates(r));
  return result;
}

Json suggestion_json(const design::WeightsSuggestion& s) {
  Json out;
  out["kind"] = design::to_string(s.kind);
  out["text"] = s.text;
  if (s.kind == design::WeightsSuggestion::Kind::kSymmetricPartner) {
    out["index"] = s.index;
    out["added"] = json_list(s.added);
  } else if (s.kind == design::WeightsSuggestion::Kind::kBalancingEntry) {
    out["added"] = json_list(s.added);
  } else {
    out["shift"] = json_list(s.shift);
  }
  out["min_weight"] = s.min_weight;
  out["weights"] = json_list(s.weights);
  return out;
}

py::object layout_weights(const py::object& layout_arg, const py::object& vectors,
                          const py::object& points, const py::kwargs& kwargs) {
  std::string source;
  const Layout layout =
      layout_from_arguments(layout_arg, vectors, points, py::none(), py::none(), kwargs, &source);
  const design::Weights w = serialised([&] { return design::layout_weights(layout); });
  Json out;
  out["layout"] = source_json(source);
  out["mode"] = to_string(layout.mode);
  out["n"] = layout.entries.cols();
  out["feasible"] = w.feasible;
  out["status"] = design::to_string(w.status);
  out["weights"] = json_list(w.weights);
  out["residual"] = w.residual;
  out["min_weight"] = w.min_weight;
  out["lp_optimum"] = w.lp_optimum;
  if (!w.zero_forced.empty()) out["zero_forced"] = w.zero_forced;
  if (!w.suggestions.empty()) {
    out["suggestion"] = suggestion_json(w.suggestions.front());
    Json all = Json::array();
    for (const design::WeightsSuggestion& s : w.suggestions) all.push_back(suggestion_json(s));
    out["suggestions"] = all;
  }
  out["message"] = w.message;
  return result_or_raise(w.status == design::Weights::Status::kSolverFailed,
                         design::to_string(w.status), w.message, out);
}

}  // namespace

void bind_layout_commands(py::module_& module) {
  module.def("analyze", &analyze, py::arg("layout") = py::none(), py::kw_only(),
             py::arg("vectors") = py::none(), py::arg("points") = py::none(),
             py::arg("weights") = py::none(), py::arg("swaps") = 5, py::arg("crosscheck") = true,
             py::arg("pair_weighting") = "geometric",
             "Worst viewpoint of a layout (as `vantage analyze --json`): a vantage.Layout, a "
             "layout file (format=, tag_points=, bundle=) or vectors=/points= (n x 3) with "
             "weights=. Raises NumericalError when the result is not certified.");
  module.def("design", &design_layout, py::arg("layout") = py::none(), py::kw_only(),
             py::arg("vectors") = py::none(), py::arg("points") = py::none(),
             py::arg("weights") = py::none(), py::arg("candidates") = py::none(),
             py::arg("add") = 1, py::arg("candidates_only") = false,
             py::arg("margin") = design::AugmentOptions{}.margin, py::arg("direct") = true,
             "Add `add` markers or directions where the worst viewpoint is weakest (as `vantage "
             "design --json`); the result's `augmented` is the new vantage.Layout.");
  module.def("weights", &layout_weights, py::arg("layout") = py::none(), py::kw_only(),
             py::arg("vectors") = py::none(), py::arg("points") = py::none(),
             "Non-negative weights with sum_i w_i z_i = 0 (Prop. 3, Eq. 11), as `vantage weights "
             "--json`.");
}

}  // namespace vantage::python
