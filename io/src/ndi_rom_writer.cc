// ndi_rom_of_layout(), ndi_rom_dropped_fields() and ndi_rom_bytes(): NDI tool definitions
// written by the byte map of ndi_rom.h (ndi_rom_map.h).

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>

#include "ndi_rom_map.h"
#include "number_text.h"
#include "vantage/analysis/common.h"
#include "vantage/io/ndi_rom.h"

namespace vantage::io {

namespace {

namespace rom = internal::rom;

// The image of a new tool: "NDI", the constant byte 8 and the bytes every real file in the test
// data holds where the byte map names no field of ours (the float at 64, no LEDs, a tool-in-port
// diode, byte 612); zeros elsewhere. The date and sequence number (bytes 20-23) stay zero, so a
// tool written twice is the same file.
std::string new_image() {
  std::string image(kNdiRomBytes, '\0');
  image.replace(0, 3, "NDI");
  image[8] = 1;
  rom::put_word(image, rom::kUnknownFloat, 0x41200000u, 4);  // 10.0f
  for (std::size_t k = 0; k < 4; ++k) image[rom::kLeds + k] = 31;
  image[rom::kToolInPort] = 9;
  image[rom::kByte612] = 9;
  return image;
}

void put_float(std::string& bytes, std::size_t offset, double value, const std::string& field) {
  if (!std::isfinite(value) || std::abs(value) > std::numeric_limits<float>::max()) {
    throw InvalidArgument(field + ": " + internal::round_trip_number(value) +
                          " is not a finite float32 (a .rom holds single precision)");
  }
  const auto single = static_cast<float>(value);
  std::uint32_t word = 0;
  std::memcpy(&word, &single, sizeof word);
  rom::put_word(bytes, offset, word, 4);
}

void put_vector(std::string& bytes, std::size_t offset, const Eigen::Vector3d& v,
                const std::string& field) {
  for (int r = 0; r < 3; ++r)
    put_float(bytes, offset + 4 * static_cast<std::size_t>(r), v(r), field);
}

void put_byte(std::string& bytes, std::size_t offset, int value, const std::string& field) {
  if (value < 0 || value > 255) {
    throw InvalidArgument(field + ": " + std::to_string(value) +
                          " does not fit one byte (0 to 255)");
  }
  bytes[offset] = static_cast<char>(value);
}

// What a .rom's text fields hold: printable ASCII (32 to 126).
bool printable_ascii(const std::string& text) {
  return std::all_of(text.begin(), text.end(), [](char c) {
    return static_cast<unsigned char>(c) >= 32 && static_cast<unsigned char>(c) <= 126;
  });
}

// Writes `text` NUL padded, unless the bytes already hold it (up to their first NUL): a text
// read from a file keeps its bytes, whatever follows its NUL.
void put_text(std::string& bytes, std::size_t offset, std::size_t size, const std::string& text,
              const std::string& field) {
  const std::string_view held = std::string_view(bytes).substr(offset, size);
  if (held.substr(0, held.find('\0')) == text) return;
  if (!printable_ascii(text)) throw InvalidArgument(field + ": printable ASCII only");
  if (text.size() > size) {
    throw InvalidArgument(field + ": at most " + std::to_string(size) + " characters, got " +
                          std::to_string(text.size()));
  }
  bytes.replace(offset, size, std::string(size, '\0'));
  bytes.replace(offset, text.size(), text);
}

void put_per_marker(std::string& bytes, std::size_t table, const std::vector<int>& values,
                    long count, const std::string& field) {
  if (static_cast<long>(values.size()) != count) {
    throw InvalidArgument(field + ": " + std::to_string(values.size()) + " entries for " +
                          std::to_string(count) + " markers");
  }
  for (long k = 0; k < count; ++k) {
    put_byte(bytes, table + static_cast<std::size_t>(k), values[static_cast<std::size_t>(k)],
             field + "[" + std::to_string(k) + "]");
  }
}

// The one cone half-angle of `visibility`: an integer number of degrees shared by every marker.
int one_cone_deg(const MarkerVisibility& visibility) {
  const Eigen::VectorXd& cones = visibility.cone_half_angle_deg;
  const double angle = cones(0);
  if ((cones.array() != angle).any()) {
    throw InvalidArgument(
        "visibility.cone_half_angle_deg: a .rom holds one maximum marker angle for every marker, "
        "the cones differ");
  }
  if (angle != std::round(angle) || angle < 1 || angle > 180) {
    throw InvalidArgument(
        "visibility.cone_half_angle_deg: a .rom holds a whole number of degrees "
        "in [1, 180], got " +
        internal::round_trip_number(angle));
  }
  return static_cast<int>(angle);
}

}  // namespace

std::vector<std::string> ndi_rom_dropped_fields(const Layout& layout) {
  std::vector<std::string> dropped;
  for (std::size_t k = 0; k < layout.names.size(); ++k) {
    if (layout.names[k] != rom::marker_letter(static_cast<long>(k))) {
      dropped.push_back("names");
      break;
    }
  }
  if ((layout.weights.array() != 1.0).any()) dropped.push_back("weights");
  if (layout.visibility && !layout.visibility->body_path.empty()) dropped.push_back("body");
  if (layout.workspace) dropped.push_back("workspace");
  if (layout.placement) dropped.push_back("placement");
  if (layout.sensor) dropped.push_back("sensor");
  if (!layout.description.empty()) dropped.push_back("description");
  return dropped;
}

NdiRom ndi_rom_of_layout(const Layout& layout) {
  layout.validate();
  if (layout.mode != LayoutMode::kPoints) {
    throw InvalidArgument(
        "vectors: a .rom holds marker positions, not direction vectors; write .json");
  }
  if (layout.candidates.cols() > 0) {
    throw InvalidArgument("candidates: a .rom cannot hold the " +
                          std::to_string(layout.candidates.cols()) +
                          " candidates; write .json to keep them");
  }
  const long n = layout.entries.cols();
  if (n < 3 || n > kNdiRomMaxMarkers) {
    throw InvalidArgument("points: a .rom holds 3 to 20 markers, the layout has " +
                          std::to_string(n));
  }
  NdiRom tool;
  tool.layout = layout;
  tool.normals = Eigen::Matrix3Xd::Zero(3, n);
  if (layout.visibility) {
    tool.max_marker_angle_deg = one_cone_deg(*layout.visibility);
    const int min_visible = layout.visibility->min_visible;
    if (min_visible < 3 || min_visible > n) {
      throw InvalidArgument("visibility.min_visible: a .rom holds 3 to " + std::to_string(n) +
                            " minimum markers, got " + std::to_string(min_visible));
    }
    tool.min_markers = min_visible;
    tool.normals = layout.visibility->normals;
    const Eigen::Vector3d sum = tool.normals.rowwise().sum();
    if (sum.norm() > 0) tool.face_normals.col(0) = sum.normalized();
  }
  if (printable_ascii(layout.name) && layout.name.size() <= rom::kPartNumberSize) {
    tool.part_number = layout.name;
  }
  for (long k = 0; k < n; ++k) {
    tool.firing_sequence.push_back(static_cast<int>(k));
    tool.marker_faces.push_back(1);
    tool.marker_groups.push_back(1);
  }
  return tool;
}

std::string ndi_rom_bytes(const NdiRom& tool) {
  std::string bytes = tool.image.empty() ? new_image() : tool.image;
  if (bytes.size() != kNdiRomBytes || bytes.compare(0, 3, "NDI") != 0) {
    throw InvalidArgument("image: " + std::to_string(kNdiRomBytes) +
                          " bytes starting with \"NDI\", or empty for a new tool");
  }
  const Layout& layout = tool.layout;
  const long n = layout.entries.cols();
  if (layout.mode != LayoutMode::kPoints || n < 3 || n > kNdiRomMaxMarkers) {
    throw InvalidArgument("points: a .rom holds 3 to 20 marker positions, the layout has " +
                          std::to_string(n) + " " + layout.entries_field());
  }
  if (tool.normals.cols() != n) {
    throw InvalidArgument("normals: " + std::to_string(tool.normals.cols()) + " columns for " +
                          std::to_string(n) + " markers");
  }
  const long zero_normals = (tool.normals.colwise().squaredNorm().array() == 0.0).count();
  if (zero_normals != 0 && zero_normals != n) {
    throw InvalidArgument("normals: a .rom holds a normal for every marker or for none; " +
                          std::to_string(n - zero_normals) + " of the " + std::to_string(n) +
                          " have one");
  }
  if (zero_normals == 0 && (tool.max_marker_angle_deg < 1 || tool.max_marker_angle_deg > 180)) {
    throw InvalidArgument("max_marker_angle_deg: 1 to 180 degrees with normals, got " +
                          std::to_string(tool.max_marker_angle_deg));
  }
  if (tool.min_markers < 3 || tool.min_markers > n) {
    throw InvalidArgument("min_markers: 3 to the " + std::to_string(n) + " markers, got " +
                          std::to_string(tool.min_markers));
  }
  // A count that changed leaves no markers of the old one behind: the slots past it are zeroed.
  if (static_cast<long>(rom::byte_at(bytes, rom::kCount)) != n) {
    const std::size_t past = static_cast<std::size_t>(n);
    for (std::size_t table : {rom::kPositions, rom::kNormals}) {
      bytes.replace(table + 12 * past, 12 * (kNdiRomMaxMarkers - past),
                    12 * (kNdiRomMaxMarkers - past), '\0');
    }
    for (std::size_t table : {rom::kFiring, rom::kFaces, rom::kGroups}) {
      bytes.replace(table + past, kNdiRomMaxMarkers - past, kNdiRomMaxMarkers - past, '\0');
    }
  }
  put_byte(bytes, rom::kCount, static_cast<int>(n), "points");
  for (long k = 0; k < n; ++k) {
    const std::size_t slot = 12 * static_cast<std::size_t>(k);
    put_vector(bytes, rom::kPositions + slot, layout.entries.col(k),
               "points[" + std::to_string(k) + "]");
    put_vector(bytes, rom::kNormals + slot, tool.normals.col(k),
               "normals[" + std::to_string(k) + "]");
  }
  put_byte(bytes, rom::kMaxAngle, tool.max_marker_angle_deg, "max_marker_angle_deg");
  put_byte(bytes, rom::kMinMarkers, tool.min_markers, "min_markers");
  put_float(bytes, rom::kMaxError, tool.max_marker_error_mm, "max_marker_error_mm");
  put_text(bytes, rom::kManufacturer, rom::kManufacturerSize, tool.manufacturer, "manufacturer");
  put_text(bytes, rom::kPartNumber, rom::kPartNumberSize, tool.part_number, "part_number");
  put_byte(bytes, rom::kMainType, tool.tool_main_type, "tool_main_type");
  put_byte(bytes, rom::kSubType, tool.tool_sub_type, "tool_sub_type");
  if (tool.tool_revision < 0 || tool.tool_revision > 0xFFFF) {
    throw InvalidArgument("tool_revision: " + std::to_string(tool.tool_revision) +
                          " does not fit two bytes (0 to 65535)");
  }
  rom::put_word(bytes, rom::kRevision, static_cast<std::uint32_t>(tool.tool_revision), 2);
  put_per_marker(bytes, rom::kFiring, tool.firing_sequence, n, "firing_sequence");
  put_per_marker(bytes, rom::kFaces, tool.marker_faces, n, "marker_faces");
  put_per_marker(bytes, rom::kGroups, tool.marker_groups, n, "marker_groups");
  put_byte(bytes, rom::kAlgorithmFlags, tool.algorithm_flags, "algorithm_flags");
  put_byte(bytes, rom::kMarkerType, tool.marker_type, "marker_type");
  for (int f = 0; f < kNdiRomMaxFaces; ++f) {
    put_vector(bytes, rom::kFaceNormals + 12 * static_cast<std::size_t>(f),
               tool.face_normals.col(f), "face_normals[" + std::to_string(f) + "]");
  }
  rom::put_word(bytes, rom::kChecksum, rom::checksum_of(bytes), 2);
  // What is written reads back: rounding to float32 must not make markers coincide (a layout
  // 1e-100 across) or normals vanish.
  try {
    parse_ndi_rom_layout(bytes, "the tool as written");
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("points: rounded to float32, a .rom's precision: ") +
                          e.what());
  }
  return bytes;
}

}  // namespace vantage::io
