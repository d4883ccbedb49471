#pragma once

/// NDI tool definition files (.rom; Polaris, Vicra, Vega), read and written. NDI does not
/// publish the format; this follows the byte map that jhu-lcsr/optical-tracker-utilities
/// (ndi_tool.py) documents from files NDI's tools write, whose count and position offsets
/// rajkundu/rom-parser confirms independently, and which every real file in the test data holds
/// (README "NDI tool definitions"). A file is 752 bytes, little endian:
///
///   bytes 0-2     "NDI"
///   bytes 4-5     checksum: the sum of bytes 6-751, modulo 2^16 (uint16)
///   byte  12      tool sub type;  byte 15: tool main type;  bytes 16-17: tool revision (uint16)
///   byte  24      maximum marker angle, degrees (the cone half-angle of every marker)
///   byte  28      marker count n, 3 to 20
///   byte  32      minimum markers to track, 3 to n
///   bytes 36-39   maximum marker error, mm (float32)
///   bytes 72-311  marker positions: 20 x (x, y, z) float32, mm; the first n are the markers
///   bytes 312-551 marker normals: 20 x (x, y, z) float32; all zero for a tool without them
///   bytes 552-571 firing sequence (uint8 per marker)
///   bytes 580-591 tool manufacturer, bytes 592-611 part number (ASCII, NUL padded)
///   bytes 613-632 marker faces, bytes 633-652 marker groups (uint8 per marker)
///   byte  653     algorithm flags;  byte 655: marker type (41 passive sphere)
///   bytes 656-751 face normals: 8 x (x, y, z) float32
///
/// The other bytes (the sequence number and date at 20-23, minimum spreads, LEDs, switches and
/// those the byte map does not name) are kept as read, so a tool read and written again is the
/// same file byte for byte.
///
/// The layout of a file is a point-mode layout named after the file's stem, markers "A", "B",
/// ... (NDI's letters), weights 1. With normals (every one of the n nonzero), the layout's
/// visibility has them (normalised), every cone the maximum marker angle and min_visible the
/// minimum markers; without (all n zero), it has none. Every error is one line
/// "<source>: byte <k> (<field>): <problem>" or "<source>: marker <L> (bytes a-b): <problem>"
/// in a vantage::InvalidArgument.

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "vantage/analysis/layout.h"

namespace vantage::io {

/// The bytes of a tool definition.
constexpr std::size_t kNdiRomBytes = 752;
/// The fewest bytes the layout reader accepts: through the marker normals.
constexpr std::size_t kNdiRomMinBytes = 552;
/// Most markers a tool definition holds.
constexpr int kNdiRomMaxMarkers = 20;
/// Faces a tool definition holds normals for.
constexpr int kNdiRomMaxFaces = 8;

/// Parses the bytes of a .rom file into its layout; `source` names it in errors. The checksum
/// is not checked here (parse_ndi_rom() checks it), so a layout can be read from a file whose
/// other bytes were edited by hand. Throws InvalidArgument for
/// fewer than kNdiRomMinBytes bytes, no "NDI" at the start, a marker count outside [3, 20], a
/// non-finite position or normal, normals given for some markers but not all, and (with
/// normals) a maximum marker angle outside [1, 180] or minimum markers outside [3, n]; and for
/// the checks of Layout::validate() (coincident markers).
Layout parse_ndi_rom_layout(std::string_view bytes, const std::string& source);

/// Every field of a tool definition that the byte map names, and the file's other bytes.
struct NdiRom {
  /// The tool's layout, as parse_ndi_rom_layout() reads it.
  Layout layout;
  /// The normals as the file holds them (3 x n; zero columns for a tool without normals).
  Eigen::Matrix3Xd normals;
  int max_marker_angle_deg = 90;     ///< byte 24, [0, 255]
  int min_markers = 3;               ///< byte 32, [0, 255] (a tool without normals may hold any)
  double max_marker_error_mm = 2.0;  ///< bytes 36-39 (float32)
  std::string manufacturer;          ///< bytes 580-591, up to 12 ASCII characters
  std::string part_number;           ///< bytes 592-611, up to 20 ASCII characters
  int tool_main_type = 4;            ///< byte 15 (4: user defined)
  int tool_sub_type = 3;             ///< byte 12
  int tool_revision = 0;             ///< bytes 16-17
  std::vector<int> firing_sequence;  ///< per marker (byte 552 + k)
  std::vector<int> marker_faces;     ///< per marker, 1-based (byte 613 + k)
  std::vector<int> marker_groups;    ///< per marker (byte 633 + k)
  int algorithm_flags = 128;         ///< byte 653 (bit 7: unique geometry)
  int marker_type = 41;              ///< byte 655 (41: passive sphere)
  /// The 8 face normals as the file holds them (3 x 8; zero columns for faces not used).
  Eigen::Matrix<double, 3, kNdiRomMaxFaces> face_normals =
      Eigen::Matrix<double, 3, kNdiRomMaxFaces>::Zero();
  /// The file's 752 bytes; ndi_rom_bytes() writes the fields above over them.
  std::string image;
  /// Bytes after the 752 of a longer file (read, not part of the tool; never written).
  std::size_t trailing_bytes = 0;
};

/// Parses a whole tool definition (at least kNdiRomBytes bytes; more are counted in
/// trailing_bytes and ignored) with the layout checks of parse_ndi_rom_layout(). Also throws
/// when the checksum at bytes 4-5 is not the sum of bytes 6-751 (a damaged file).
NdiRom parse_ndi_rom(std::string_view bytes, const std::string& source);

/// Reads and parses the .rom file at `path` (parse_ndi_rom(); errors name the path).
NdiRom read_ndi_rom(const std::string& path);

/// The minimum markers (byte 32) of a tool definition's `bytes` (at least kNdiRomMinBytes, as
/// parse_ndi_rom_layout() accepted them, its layout having `markers` markers), which the tracker
/// needs in view to report the tool, whether or not the file has normals
/// (parse_ndi_rom_layout() keeps it only with normals, as min_visible). Throws InvalidArgument
/// "<source>: byte 32 (minimum markers): ..." outside [3, markers].
int ndi_rom_min_markers(std::string_view bytes, const std::string& source, long markers);

/// A new tool definition for `layout` (point mode, 3 to 20 markers): positions (rounded to
/// float32), with a visibility model its normals, its one cone half-angle (an integer number of
/// degrees, the same for every marker) and min_visible; without one, zero normals, a maximum
/// marker angle of 90 and minimum markers 3. The part number is the layout's name when it is
/// ASCII and at most 20 characters (else empty); the other fields hold the defaults above, and
/// every marker is on face 1, in group 1, fired in order. With normals, face 1's normal is the
/// normalised sum of the marker normals (a choice: NDI's own files differ). Throws
/// InvalidArgument naming the layout field the format cannot hold: "vectors" (direction mode),
/// "points" (count outside [3, 20]), "candidates", "visibility.cone_half_angle_deg" (cones that
/// differ or are not an integer in [1, 180]), "visibility.min_visible" (outside [3, n]); a
/// coordinate beyond float32 is ndi_rom_bytes()'s "points[k]".
NdiRom ndi_rom_of_layout(const Layout& layout);

/// The layout's fields a tool definition cannot hold and ndi_rom_of_layout() leaves out, by
/// their layout-file names: "names" (unless "A", "B", ...), "weights" (unless all 1), "body",
/// "workspace", "description", "placement", "sensor". Empty when the file holds the whole layout.
std::vector<std::string> ndi_rom_dropped_fields(const Layout& layout);

/// The 752 bytes of `tool`: its image (NDI's "NDI" header and zeros when empty) with every field
/// above written over it (a text field only when it differs from the image's: a text read
/// keeps its bytes) and the checksum recomputed. The markers come from tool.layout (its
/// positions rounded to float32) and tool.normals; slots past the marker count keep the image's
/// bytes when the count is the image's, and are zeroed when it changed. Throws InvalidArgument
/// when a field does not fit its bytes or would make a file parse_ndi_rom() refuses (names it:
/// "part_number", "max_marker_error_mm", "points[k]", "normals" for some but not all,
/// "min_markers" outside [3, n], "max_marker_angle_deg" outside [1, 180] with normals, ...;
/// "points: rounded to float32 ..." when the bytes would not read back, e.g. markers that
/// coincide once rounded).
std::string ndi_rom_bytes(const NdiRom& tool);

}  // namespace vantage::io
