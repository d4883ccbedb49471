#include "analysis_json.h"

#include <vector>

#include "pose_json.h"

namespace vantage::analysis_json {
namespace {

Json viewpoints(const std::vector<Eigen::Vector3d>& viewpoints) {
  Json list = Json::array();
  for (const Eigen::Vector3d& a : viewpoints) list.push_back(pose_json::finite_list(a));
  return list;
}

}  // namespace

Json analysis(const Layout& layout, const DataVectors& data, const sdp::LayoutAnalysis& r,
              double ceiling) {
  Json out;
  out["name"] = layout.name;
  out["mode"] = to_string(layout.mode);
  out["n_vectors"] = data.vectors.cols();
  out["worst_viewpoint"] = pose_json::finite_list(r.worst_viewpoint);
  out["worst_viewpoints"] = viewpoints(r.worst_viewpoints);
  out["t"] = r.t;
  out["pbar_min"] = r.pbar_min;
  out["ceiling"] = ceiling;
  out["degenerate"] = r.degenerate;
  out["near_degenerate"] = r.near_degenerate;
  out["worst_case_errors_deg"] = pose_json::finite_list(r.worst_case_errors_deg);
  out["max_worst_case_error_deg"] = r.max_worst_case_error_deg;
  out["certificate"] = {{"t_upper", r.certificate.t_upper},
                        {"t_lower", r.certificate.t_lower},
                        {"certified", r.certificate.certified}};
  out["paper_lmi"] = {{"viewpoint", pose_json::finite_list(r.paper_lmi.viewpoint)},
                      {"t", r.paper_lmi.t},
                      {"pbar", r.paper_lmi.pbar},
                      {"status", sdp::to_string(r.paper_lmi.status)}};
  if (r.crosscheck.ran) {
    out["crosscheck"] = {{"method", r.crosscheck.method},
                         {"t", r.crosscheck.t},
                         {"agrees", r.crosscheck.agrees},
                         {"samples", r.crosscheck.samples},
                         {"sample_spacing_rad", r.crosscheck.sample_spacing},
                         {"samples_cover_cells", r.crosscheck.samples_cover_cells}};
  } else {
    out["crosscheck"] = {{"method", "skipped"}};
  }
  Json swaps = Json::array();
  for (const SwapError& s : r.swaps) {
    Json swap = {{"i", s.i}, {"j", s.j}, {"error_deg", s.error_deg}, {"ambiguous", s.ambiguous}};
    if (!data.pairs.empty()) {
      swap["pair_i"] = {data.pairs[s.i].first, data.pairs[s.i].second};
      swap["pair_j"] = {data.pairs[s.j].first, data.pairs[s.j].second};
    }
    swaps.push_back(swap);
  }
  out["swaps"] = swaps;
  out["solver"] = {{"backend", sdp::to_string(r.solver.backend)},
                   {"status", sdp::to_string(r.solver.status)},
                   {"cells_solved", r.solver.cells_solved},
                   {"patches", r.solver.patches},
                   {"sdp_status", sdp::to_string(r.solver.sdp_status)}};
  if (!r.message.empty()) out["message"] = r.message;
  return out;
}

}  // namespace vantage::analysis_json
