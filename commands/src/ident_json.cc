// The JSON object of `vantage ident --json` (ident_json.h).

#include "vantage/commands/ident_json.h"

#include <algorithm>
#include <cmath>

#include "vantage/report/json_number.h"

namespace vantage::ident_json {
namespace {

using report::json_number;

Json names(const Layout& tool, const std::vector<int>& markers) {
  Json out = Json::array();
  for (int i : markers) out.push_back(tool.entry_name(i));
  return out;
}

}  // namespace

Json pair(const tracker::ToolPairMatch& p, const std::vector<Layout>& tools) {
  const tracker::ToolMatch& m = p.match;
  const Layout& a = tools[static_cast<std::size_t>(p.a)];
  const Layout& b = tools[static_cast<std::size_t>(p.b)];
  return {{"a", p.a},
          {"b", p.b},
          {"self", p.a == p.b},
          {"verdict", to_string(p.verdict)},
          {"min_visible", p.min_visible},
          {"mismatch", json_number(m.mismatch)},
          {"subset", m.subset},
          {"assignment", m.assignment},
          {"subset_names", names(a, m.subset)},
          {"assignment_names", names(b, m.assignment)},
          {"transform", to_string(m.transform)},
          {"proper_rms", m.proper_rms},
          {"improper_rms", m.improper_rms},
          {"certified", m.certified},
          {"mismatch_lower", json_number(m.mismatch_lower)},
          {"comparisons", m.comparisons}};
}

Json report(const tracker::ToolLibraryMatches& matches, const std::vector<Layout>& tools,
            const std::vector<std::string>& files) {
  Json out = report_without_pairs(matches, tools, files);
  Json& pairs = out["pairs"];
  for (const tracker::ToolPairMatch& p : matches.pairs) pairs.push_back(pair(p, tools));
  return out;
}

Json report_without_pairs(const tracker::ToolLibraryMatches& matches,
                          const std::vector<Layout>& tools, const std::vector<std::string>& files) {
  Json out;
  const std::vector<int>& k = matches.min_visible;
  const bool shared = std::all_of(k.begin(), k.end(), [&](int v) { return v == k.front(); });
  out["min_visible"] = shared ? Json(k.front()) : Json(nullptr);
  Json list = Json::array();
  for (std::size_t t = 0; t < tools.size(); ++t) {
    list.push_back({{"file", files[t]},
                    {"name", tools[t].name},
                    {"markers", tools[t].entries.cols()},
                    {"min_visible", k[t]}});
  }
  out["tools"] = list;
  out["pairs"] = Json::array();
  auto pair_summary = [&](int index) {
    if (index < 0) return Json(nullptr);
    const tracker::ToolPairMatch& p = matches.pairs[static_cast<std::size_t>(index)];
    return Json{{"a", p.a}, {"b", p.b}, {"mismatch", json_number(p.match.mismatch)}};
  };
  out["closest"] = pair_summary(matches.closest);
  out["closest_distinct"] = pair_summary(matches.closest_distinct);
  const Eigen::MatrixXd matrix = matches.mismatch_matrix();
  Json rows = Json::array();
  for (Eigen::Index a = 0; a < matrix.rows(); ++a) {
    Json row = Json::array();
    for (Eigen::Index b = 0; b < matrix.cols(); ++b) row.push_back(json_number(matrix(a, b)));
    rows.push_back(row);
  }
  out["matrix"] = rows;
  out["certified"] = matches.certified;
  return out;
}

}  // namespace vantage::ident_json
