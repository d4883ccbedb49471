#pragma once

// vantage.place: K marker sites on a body (a mesh's surface, or given sites with normals), every
// workspace direction trackable and the certified worst case under visibility best
// (design::place_markers(), docs/math.md §21), as the fields of `vantage place --json`: the same
// checks, placement and JSON writer as the CLI (commands/include/vantage/commands/place_json.h).

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/commands/place_json.h"

namespace vantage::python {

/// The keyword of a CLI flag the shared checks name: "--min-separation" -> "min_separation",
/// "--target" -> "targets", "BODY" and "BODY/--sites" -> "body"; any other field is kept.
InvalidArgument place_renamed(const InvalidArgument& e);

/// The objective and the camera's or the tracker's settings of place's and design's keywords
/// (None: the CLI's default), in a request of `vantage place`.
place_json::Request objective_request(
    const std::string& objective, const std::optional<double>& distance,
    const std::optional<std::vector<double>>& distances, const std::optional<double>& focal,
    const std::optional<double>& noise_px, const std::string& statistic,
    const std::optional<int>& crb_samples, const pybind11::object& aim,
    const pybind11::object& targets, const std::optional<double>& fle_rms,
    const pybind11::object& fle_sigma);

/// Registers place on `module`.
void bind_place_command(pybind11::module_& module);

}  // namespace vantage::python
