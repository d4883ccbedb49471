// The one JSON writer of the layout report: the object `vantage analyze --json` prints and
// vantage.LayoutReport.to_dict() returns (README, "vantage analyze").

#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "vantage/report/json_number.h"
#include "vantage/report/layout_report.h"
#include "visibility_report_json.h"

namespace vantage::report {
namespace {

using Json = nlohmann::ordered_json;

Json list(const Eigen::VectorXd& v) {
  Json out = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(json_number(v(i)));
  return out;
}

Json viewpoints(const std::vector<Eigen::Vector3d>& viewpoints) {
  Json out = Json::array();
  for (const Eigen::Vector3d& a : viewpoints) out.push_back(list(a));
  return out;
}

Json crosscheck(const sdp::LayoutAnalysis::CrossCheckSummary& c) {
  if (!c.ran) return {{"method", "skipped"}, {"skipped", c.skipped}};
  return {{"method", c.method},
          {"t", c.t},
          {"agrees", c.agrees},
          {"samples", c.samples},
          {"sample_spacing_rad", c.sample_spacing},
          {"samples_cover_cells", c.samples_cover_cells}};
}

Json swaps(const LayoutReport& report) {
  Json out = Json::array();
  for (const SwapError& s : report.analysis.swaps) {
    Json swap = {{"i", s.i}, {"j", s.j}, {"error_deg", s.error_deg}, {"ambiguous", s.ambiguous}};
    if (!report.data.pairs.empty()) {
      swap["pair_i"] = {report.data.pairs[s.i].first, report.data.pairs[s.i].second};
      swap["pair_j"] = {report.data.pairs[s.j].first, report.data.pairs[s.j].second};
    }
    out.push_back(swap);
  }
  return out;
}

Json dropout(const DropoutAnalysis& dropout) {
  Json out = Json::array();
  for (const DropoutEntry& e : dropout.entries) {
    out.push_back({{"index", e.index},
                   {"pbar_min", e.worst.pbar_min},
                   {"max_worst_case_error_deg", e.worst.max_worst_case_error_deg},
                   {"worst_viewpoint", list(e.worst.viewpoint)},
                   {"n_vectors", e.n_vectors},
                   {"certified", e.worst.certified}});
  }
  return out;
}

Json pair(const std::pair<int, int>& p) {
  if (p.first < 0) return nullptr;
  return {p.first, p.second};
}

Json difference(const tracker::DistanceDifference& d) {
  return {{"min_distance_difference", json_number(d.value)},
          {"pair_a", pair(d.pair_a)},
          {"pair_b", pair(d.pair_b)}};
}

Json dropout_difference(const tracker::DropoutDifference& e) {
  Json out = {{"lost", e.lost}};
  out.update(difference(e.difference));
  return out;
}

// docs/math.md §24; README "vantage analyze" names the fields.
Json identification(const tracker::IdentificationMargins& m) {
  Json out = difference(m.distance_difference);
  out["min_marker_separation"] = json_number(m.separation.value);
  out["separation_pair"] = pair(m.separation.pair);
  out["mirror_rms"] = m.mirror.rms;
  out["mirror_rms_lower"] = m.mirror.rms_lower;
  out["mirror_certified"] = m.mirror.certified;
  out["own_mirror"] = m.mirror.own_mirror;
  out["mirror_assignment"] = m.mirror.assignment;
  Json entries = Json::array();
  for (const tracker::DropoutDifference& e : m.under_dropout)
    entries.push_back(dropout_difference(e));
  out["under_dropout"] = entries;
  out["worst_under_dropout"] =
      dropout_difference(m.under_dropout[static_cast<std::size_t>(m.worst_under_dropout)]);
  return out;
}

Json mesh(const MeshReport& m) {
  return {{"triangles", m.triangles},
          {"vertices", m.vertices},
          {"closed", m.closed},
          {"manifold", m.manifold},
          {"consistently_wound", m.consistently_wound},
          {"boundary_edges", m.boundary_edges},
          {"non_manifold_edges", m.non_manifold_edges},
          {"inconsistent_edges", m.inconsistent_edges},
          {"triangles_against_neighbours", m.triangles_against_neighbours},
          {"degenerate_triangles", m.degenerate_triangles},
          {"bounding_box_size", list(m.bounding_box_size)},
          {"units_hint", to_string(m.units_hint)}};
}

}  // namespace

std::string to_json(const LayoutReport& report) {
  const sdp::LayoutAnalysis& r = report.analysis;
  Json out;
  out["name"] = report.layout.name;
  out["mode"] = to_string(report.layout.mode);
  out["n_vectors"] = report.data.vectors.cols();
  out["worst_viewpoint"] = list(r.worst_viewpoint);
  out["worst_viewpoints"] = viewpoints(r.worst_viewpoints);
  out["t"] = r.t;
  out["pbar_min"] = r.pbar_min;
  out["ceiling"] = report.ceiling;
  out["degenerate"] = r.degenerate;
  out["near_degenerate"] = r.near_degenerate;
  out["worst_case_errors_deg"] = list(r.worst_case_errors_deg);
  out["max_worst_case_error_deg"] = r.max_worst_case_error_deg;
  out["certificate"] = {{"t_upper", r.certificate.t_upper},
                        {"t_lower", r.certificate.t_lower},
                        {"certified", r.certificate.certified}};
  out["paper_lmi"] = {{"viewpoint", list(r.paper_lmi.viewpoint)},
                      {"t", r.paper_lmi.t},
                      {"pbar", r.paper_lmi.pbar_at},
                      {"status", to_string(r.paper_lmi.status)}};
  out["crosscheck"] = crosscheck(r.crosscheck);
  out["swaps"] = swaps(report);
  out["solver"] = {{"backend", to_string(r.solver.backend)},
                   {"status", to_string(r.solver.status)},
                   {"cells_solved", r.solver.cells_solved},
                   {"patches", r.solver.patches},
                   {"sdp_status", to_string(r.solver.sdp_status)}};
  out["coplanarity"] = {{"smallest_singular_value", report.coplanarity.smallest_singular_value},
                        {"normal", list(report.coplanarity.normal)},
                        {"nearly_coplanar", report.coplanarity.nearly_coplanar},
                        {"threshold", report.coplanarity.threshold}};
  if (report.identification) out["identification"] = identification(*report.identification);
  if (report.dropout) out["dropout"] = dropout(*report.dropout);
  if (report.visibility) out["visibility"] = internal::visibility_json(*report.visibility);
  if (report.mesh) out["mesh"] = mesh(*report.mesh);
  out["usable"] = report.is_usable();
  const std::string message = report.message();
  if (!message.empty()) out["message"] = message;
  // Names need not be UTF-8 (a CSV's bytes): invalid bytes become U+FFFD rather than fail.
  return out.dump(2, ' ', false, Json::error_handler_t::replace);
}

}  // namespace vantage::report
