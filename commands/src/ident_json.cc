// The JSON object of `vantage ident --json` (ident_json.h).

#include "vantage/commands/ident_json.h"

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
  out["min_visible"] = matches.min_visible;
  Json list = Json::array();
  for (std::size_t t = 0; t < tools.size(); ++t) {
    list.push_back(
        {{"file", files[t]}, {"name", tools[t].name}, {"markers", tools[t].entries.cols()}});
  }
  out["tools"] = list;
  out["pairs"] = Json::array();
  const tracker::ToolPairMatch& closest = matches.pairs[static_cast<std::size_t>(matches.closest)];
  out["closest"] = {
      {"a", closest.a}, {"b", closest.b}, {"mismatch", json_number(closest.match.mismatch)}};
  out["certified"] = matches.certified;
  return out;
}

}  // namespace vantage::ident_json
