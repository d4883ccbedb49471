#pragma once

// The JSON object of `vantage analyze --json` (the contract is the "vantage analyze" section of
// README.md). Shared by the `vantage` command and the Python module (vantage.analyze), so that
// both print exactly the same fields.

#include <nlohmann/json.hpp>

#include "vantage/analysis/layout.h"
#include "vantage/sdp/layout_analysis.h"

namespace vantage::analysis_json {

using Json = nlohmann::ordered_json;

/// The report of `layout` (its data vectors `data`, analysed into `r`; `ceiling` is
/// cos(pi / (2m)) for its m data vectors).
Json analysis(const Layout& layout, const DataVectors& data, const sdp::LayoutAnalysis& r,
              double ceiling);

}  // namespace vantage::analysis_json
