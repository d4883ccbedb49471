#pragma once

// The JSON object of `vantage ident --json` (issue 20; README, "vantage ident"; docs/math.md
// §24), from the one ToolLibraryMatches of vantage::tracker::match_tool_library(): min_visible
// (the k every tool shares, or null), tools [{file, name, markers, min_visible}], pairs [{a, b,
// self, verdict, min_visible, mismatch, subset, assignment, transform, proper_rms, improper_rms,
// certified, mismatch_lower}], closest and closest_distinct ({a, b, mismatch} or null), matrix
// (n x n mismatches), certified.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/tracker/tool_match.h"

namespace vantage::ident_json {

using Json = nlohmann::ordered_json;

/// One pair: the tools' indices, the match and its markers by index and by name.
Json pair(const tracker::ToolPairMatch& pair, const std::vector<Layout>& tools);

/// The whole report; `files` names each tool's file, in the order of `tools`.
Json report(const tracker::ToolLibraryMatches& matches, const std::vector<Layout>& tools,
            const std::vector<std::string>& files);

/// report() with "pairs" an empty array, for a front end that fills it one pair() at a time: the
/// JSON tree of every pair took 4.8 KB per pair, 24 times the matches themselves (issue 36).
Json report_without_pairs(const tracker::ToolLibraryMatches& matches,
                          const std::vector<Layout>& tools, const std::vector<std::string>& files);

}  // namespace vantage::ident_json
