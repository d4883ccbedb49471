#pragma once

// `vantage place`: its arguments, the placed layout built from the chosen sites, and its text and
// JSON reports (README, "vantage place"; docs/math.md §21).

#include <cstdint>
#include <string>
#include <vector>

#include "command.h"
#include "layout_input.h"
#include "vantage/analysis/layout.h"
#include "vantage/design/placement.h"
#include "vantage/design/placement_layout.h"
#include "vantage/sdp/layout_report.h"

namespace vantage::cli {

struct PlaceArgs {
  std::string body;   ///< mesh to sample (positional), or empty
  std::string sites;  ///< --sites file, or empty
  int candidates = 500;
  bool candidates_given = false;
  int markers = 0;
  std::string out;
  LayoutInput input;  ///< --format of --sites and the visibility options
  double min_separation = 0.0;
  std::string keep;
  bool robust_dropout = false;
  double min_distance_difference = 0.0;
  std::uint64_t seed = 1;
  int threads = 0;
  int random_trials = 1000;
  long exhaustive_limit = 5000;
  double certificate_tolerance = sdp::VisibilitySearchOptions{}.certificate_tolerance;
  bool overwrite = false;
  bool json = false;
  bool quiet = false;
};

/// The chosen markers as a layout on the body, and `vantage analyze`'s report of it.
struct PlacedLayout {
  Layout layout;
  sdp::LayoutReport report;
  std::vector<std::string> site_names;  ///< the name of every site and kept marker
};

/// The layout of result.chosen (sites first, kept markers last, in index order) with the
/// visibility block, workspace and placement record, and its analysis.
PlacedLayout placed_layout(const PlaceArgs& args, const Layout& sites, int n_candidates,
                           const design::PlacementResult& result);

/// Why the placement is not written.
std::string failure_message(const design::PlacementResult& result, const PlacedLayout& placed);

Json place_json(const PlaceArgs& args, int n_candidates, int drawn,
                const design::PlacementResult& result, const PlacedLayout& placed, bool written);
void print_place_report(const PlaceArgs& args, int n_candidates, int drawn,
                        const design::PlacementResult& result, const PlacedLayout& placed,
                        bool written);

}  // namespace vantage::cli
