#include "vantage/commands/design_json.h"

#include <cmath>
#include <string>
#include <vector>

#include "vantage/commands/pose_json.h"
#include "vantage/report/json_number.h"
#include "vantage/tracker/identification.h"

namespace vantage::design_json {
namespace {

// Lists of numbers as pose_json writes them (null for a non-finite entry, never NaN).
Json list(const Eigen::VectorXd& v) { return pose_json::finite_list(v); }

Json points(const std::vector<Eigen::Vector3d>& points) {
  Json out = Json::array();
  for (const Eigen::Vector3d& p : points) out.push_back(list(p));
  return out;
}

Json worst(const design::WorstCase& worst, int n_vectors) {
  Json out;
  out["pbar_min"] = worst.pbar_min;
  out["worst_viewpoints"] = points(worst.viewpoints);
  out["max_worst_case_error_deg"] = worst.max_worst_case_error_deg;
  out["ceiling"] = design::pbar_ceiling(n_vectors);
  out["n_vectors"] = n_vectors;
  out["t"] = worst.t;
  out["certified"] = worst.certified;
  return out;
}

Json step(const design::AugmentStep& st, LayoutMode mode, const std::string& name) {
  Json out;
  out["added"] = list(st.added);
  out["name"] = name;
  out["pbar_min"] = st.worst.pbar_min;
  out["worst_viewpoints"] = points(st.worst.viewpoints);
  out["max_worst_case_error_deg"] = st.worst.max_worst_case_error_deg;
  out["ceiling"] = st.ceiling;
  out["n_vectors"] = st.vector_count;
  out["improved"] = st.improved;
  out["note"] = st.note;
  if (st.candidate_index >= 0) out["candidate_index"] = st.candidate_index;
  out["single_vector_can_improve"] = st.single_vector_can_improve;
  if (mode == LayoutMode::kVectors) {
    out["best_kill_level"] = st.best_kill_level;
    out["angle_from_worst_plane_deg"] = st.angle_from_worst_plane_deg;
  } else if (st.search_solves > 0) {
    out["search"] = {{"t_lower", st.search_t_lower},
                     {"closed", st.search_closed},
                     {"unresolved_cells", st.search_unresolved},
                     {"solves", st.search_solves}};
  }
  out["t"] = st.worst.t;
  out["certified"] = st.worst.certified;
  out["global_solves"] = st.global_solves;
  return out;
}

Json direct(const design::DirectResult& d) {
  Json out;
  out["pbar_min"] = d.worst.pbar_min;
  out["added"] = points(d.added);
  out["method"] = d.method;
  if (!d.candidate_indices.empty()) out["candidate_indices"] = d.candidate_indices;
  out["worst_viewpoints"] = points(d.worst.viewpoints);
  out["max_worst_case_error_deg"] = d.worst.max_worst_case_error_deg;
  out["certified"] = d.worst.certified;
  out["global_solves"] = d.global_solves;
  return out;
}

Json suggestion(const design::WeightsSuggestion& s) {
  Json out;
  out["kind"] = design::to_string(s.kind);
  out["text"] = s.text;
  if (s.kind == design::WeightsSuggestion::Kind::kSymmetricPartner) {
    out["index"] = s.index;
    out["added"] = list(s.added);
  } else if (s.kind == design::WeightsSuggestion::Kind::kBalancingEntry) {
    out["added"] = list(s.added);
  } else {
    out["shift"] = list(s.shift);
  }
  out["min_weight"] = s.min_weight;
  out["weights"] = list(s.weights);
  return out;
}

}  // namespace

Json design(const Json& source, const Layout& layout, bool direct_asked,
            const design::AugmentResult& r) {
  Json out;
  out["layout"] = source;
  out["name"] = layout.name;
  out["mode"] = to_string(layout.mode);
  out["status"] = design::to_string(r.status);
  if (!r.message.empty()) out["message"] = r.message;
  out["initial"] = worst(r.initial, r.initial_vector_count);
  Json steps = Json::array();
  // The additions are the augmented layout's last entries, named there ("added1", or "p5" in
  // an unnamed layout).
  const Eigen::Index first_added = r.augmented.entries.cols() - r.steps.size();
  for (std::size_t s = 0; s < r.steps.size(); ++s) {
    steps.push_back(step(r.steps[s], layout.mode,
                         r.augmented.entry_name(first_added + static_cast<Eigen::Index>(s))));
  }
  out["steps"] = steps;
  out["final_pbar_min"] = r.final_pbar_min;
  out["min_distance_difference"] = r.min_distance_difference;
  if (layout.mode == LayoutMode::kPoints) {
    // Eq. (24.1) of the final markers; null with fewer than two pairs.
    const double achieved = tracker::min_distance_difference(r.augmented.entries).value;
    out["final_distance_difference"] = report::json_number(achieved);
  }
  if (r.direct.status == design::DirectResult::Status::kOk) {
    out["direct"] = direct(r.direct);
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

Json weights(const Json& source, const Layout& layout, const design::Weights& w) {
  Json out;
  out["layout"] = source;
  out["mode"] = to_string(layout.mode);
  out["n"] = layout.entries.cols();
  if (!layout.names.empty()) out["names"] = layout.names;
  out["feasible"] = w.feasible;
  out["status"] = design::to_string(w.status);
  out["weights"] = list(w.weights);
  out["residual"] = w.residual;
  out["min_weight"] = w.min_weight;
  out["lp_optimum"] = w.lp_optimum;
  if (!w.zero_forced.empty()) out["zero_forced"] = w.zero_forced;
  if (!w.suggestions.empty()) {
    out["suggestion"] = suggestion(w.suggestions.front());
    Json all = Json::array();
    for (const design::WeightsSuggestion& s : w.suggestions) all.push_back(suggestion(s));
    out["suggestions"] = all;
  }
  out["message"] = w.message;
  return out;
}

Layout layout_to_write(const design::AugmentResult& result) { return result.augmented; }

std::optional<std::string> unused_visibility_warning(const Layout& layout) {
  if (!layout.visibility && !layout.workspace) return std::nullopt;
  return "the layout has a visibility model (normals, cones, body or workspace) that the search "
         "does not use: every marker counts as seen from every direction, and an added marker "
         "gets a normal away from the markers' centroid and the widest cone, not a surface normal";
}

}  // namespace vantage::design_json
