#pragma once

/// Marker dropout: which marker (point mode) or direction (direction mode) can a layout not
/// afford to lose? Markers get occluded; for each entry of the layout, the global worst viewpoint
/// (Theorem 6 over all sign cells, certified) of the layout without it.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/sdp/certified_worst.h"

namespace vantage::report {

/// Options of dropout_analysis().
struct DropoutOptions {
  sdp::WorstViewpointOptions worst_viewpoint;  ///< of each global solve
  int threads = 0;  ///< solves run in parallel on this many threads; 0 = all cores, >= 0

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// The layout without one of its entries.
struct DropoutEntry {
  int index = 0;      ///< the removed entry: a marker (point mode) or a vector (direction mode)
  int n_vectors = 0;  ///< data vectors left (free vectors not touching the marker in point mode)
  /// The certified worst case of the vectors left, its error as `vantage analyze` reports it.
  /// With one vector left it is seen end-on: t = 1, p-bar_min = 0 and the error is the limit
  /// 90 degrees (sdp::certified_worst_end_on, docs/math.md §11), always certified.
  sdp::CertifiedWorst worst;
};

/// Result of dropout_analysis().
struct DropoutAnalysis {
  enum class Status {
    kCertified,     ///< every entry's global solve is certified
    kNotCertified,  ///< at least one entry's certificate did not close (see message)
  };
  Status status = Status::kNotCertified;
  std::vector<DropoutEntry> entries;  ///< one per layout entry, by index
  /// Entry indices by decreasing harm: increasing pbar_min, ties by increasing index.
  std::vector<int> by_harm;
  std::string message;  ///< empty when certified
};

/// "certified" or "not_certified".
const char* to_string(DropoutAnalysis::Status status);

/// For every entry k of the layout, the global worst viewpoint of the data vectors that remain
/// without it: direction mode drops vector k; point mode drops marker k and with it the free
/// vectors z_j - z_i touching it (Prop. 8). Removing an entry never raises p-bar_min, so every
/// entry's pbar_min is <= the intact layout's. Deterministic for any thread count.
/// Throws InvalidArgument on an invalid layout (Layout::validate) or options.
DropoutAnalysis dropout_analysis(const Layout& layout, const DropoutOptions& options = {});

}  // namespace vantage::report
