#pragma once

/// Reading NDI tool definition files (.rom; Polaris, Vicra, Vega), read only. NDI does not
/// publish the format; this reader follows the byte map that jhu-lcsr/optical-tracker-utilities
/// (ndi_tool.py) documents from files NDI's tools write, whose count and position offsets
/// rajkundu/rom-parser confirms independently. It reads only these fields (little endian):
///
///   bytes 0-2     "NDI"
///   byte  24      maximum marker angle, degrees (the cone half-angle of every marker)
///   byte  28      marker count n, 3 to 20
///   byte  32      minimum markers to track, 3 to n
///   bytes 72-311  marker positions: 20 x (x, y, z) float32, mm; the first n are the markers
///   bytes 312-551 marker normals: 20 x (x, y, z) float32; all zero for a tool without them
///
/// The rest (checksum at bytes 4-5, tool type, part number, firing sequence, faces, marker
/// type) is not read; the checksum is not checked, because only one source describes it. The
/// file must hold at least the 552 bytes above (NDI's files hold 752).
///
/// The result is a point-mode layout named after the file's stem, markers "A", "B", ... (NDI's
/// letters), weights 1. With normals (every one of the n nonzero), the layout's visibility has
/// them (normalised), every cone the maximum marker angle and min_visible the minimum markers;
/// without (all n zero), it has none. Every error is one line
/// "<source>: byte <k> (<field>): <problem>" or "<source>: marker <L> (bytes a-b): <problem>"
/// in a vantage::InvalidArgument.

#include <cstddef>
#include <string>
#include <string_view>

#include "vantage/analysis/layout.h"

namespace vantage::io {

/// The bytes a tool definition must hold: through the marker normals.
constexpr std::size_t kNdiRomMinBytes = 552;
/// Most markers a tool definition holds.
constexpr int kNdiRomMaxMarkers = 20;

/// Parses the bytes of a .rom file; `source` names it in errors. Throws InvalidArgument for
/// fewer than kNdiRomMinBytes bytes, no "NDI" at the start, a marker count outside [3, 20], a
/// non-finite position or normal, normals given for some markers but not all, and (with
/// normals) a maximum marker angle outside [1, 180] or minimum markers outside [3, n]; and for
/// the checks of Layout::validate() (coincident markers).
Layout parse_ndi_rom_layout(std::string_view bytes, const std::string& source);

}  // namespace vantage::io
