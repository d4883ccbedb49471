// parse_ndi_rom_layout() and parse_ndi_rom(): NDI tool definition files, read by the byte map of
// ndi_rom.h (ndi_rom_map.h).

#include "vantage/io/ndi_rom.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <vector>

#include "entry_labels.h"
#include "json_fields.h"
#include "ndi_rom_map.h"
#include "vantage/analysis/common.h"
#include "vantage/io/text_file.h"

namespace vantage::io {

namespace {

using internal::fail;
namespace rom = internal::rom;

constexpr std::size_t kMaxAngleByte = rom::kMaxAngle;
constexpr std::size_t kCountByte = rom::kCount;
constexpr std::size_t kMinMarkersByte = rom::kMinMarkers;
constexpr std::size_t kPositionsByte = rom::kPositions;
constexpr std::size_t kNormalsByte = rom::kNormals;

/// The little-endian float32 at `offset`, whatever the host's byte order.
double rom_float(std::string_view bytes, std::size_t offset) {
  const std::uint32_t word = rom::word_at(bytes, offset, 4);
  float value = 0;
  std::memcpy(&value, &word, sizeof value);
  return value;
}

std::string byte_range(std::size_t first, std::size_t size) {
  return "bytes " + std::to_string(first) + "-" + std::to_string(first + size - 1);
}

/// Vector k of the 20 at `table`, checked finite.
Eigen::Vector3d rom_vector(std::string_view bytes, std::size_t table, long k, const char* what,
                           const std::string& source) {
  const std::size_t first = table + 12 * static_cast<std::size_t>(k);
  Eigen::Vector3d v;
  for (int r = 0; r < 3; ++r) v(r) = rom_float(bytes, first + 4 * static_cast<std::size_t>(r));
  if (!v.allFinite()) {
    fail(source, "marker " + rom::marker_letter(k) + " (" + byte_range(first, 12) + "): " + what +
                     " not finite");
  }
  return v;
}

int rom_byte(std::string_view bytes, std::size_t offset) {
  return static_cast<int>(rom::byte_at(bytes, offset));
}

// The NUL-terminated ASCII text of `size` bytes at `offset`.
std::string rom_text(std::string_view bytes, std::size_t offset, std::size_t size) {
  const std::string_view field = bytes.substr(offset, size);
  return std::string(field.substr(0, field.find('\0')));
}

std::vector<int> per_marker(std::string_view bytes, std::size_t table, long count) {
  std::vector<int> out;
  for (long k = 0; k < count; ++k)
    out.push_back(rom_byte(bytes, table + static_cast<std::size_t>(k)));
  return out;
}

void check_byte(int value, int low, int high, std::size_t offset, const char* field,
                const std::string& source) {
  if (value < low || value > high) {
    fail(source, "byte " + std::to_string(offset) + " (" + field + "): expected " +
                     std::to_string(low) + " to " + std::to_string(high) + ", got " +
                     std::to_string(value));
  }
}

}  // namespace

Layout parse_ndi_rom_layout(std::string_view bytes, const std::string& source) {
  if (bytes.size() < kNdiRomMinBytes) {
    fail(source, "an NDI tool definition holds at least " + std::to_string(kNdiRomMinBytes) +
                     " bytes, this file " + std::to_string(bytes.size()));
  }
  if (bytes.substr(0, 3) != "NDI") {
    fail(source, "bytes 0-2: not \"NDI\", so not an NDI tool definition (.rom)");
  }
  const int count = rom_byte(bytes, kCountByte);
  check_byte(count, 3, kNdiRomMaxMarkers, kCountByte, "marker count", source);
  Layout layout;
  layout.name = std::filesystem::path(source).stem().string();
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, count);
  layout.weights = Eigen::VectorXd::Ones(count);
  layout.candidates.resize(3, 0);
  Eigen::Matrix3Xd normals(3, count);
  std::vector<std::string> labels;
  long with_normal = 0;
  for (long k = 0; k < count; ++k) {
    layout.entries.col(k) = rom_vector(bytes, kPositionsByte, k, "position", source);
    normals.col(k) = rom_vector(bytes, kNormalsByte, k, "normal", source);
    if (!normals.col(k).isZero(0.0)) ++with_normal;
    layout.names.push_back(rom::marker_letter(k));
    labels.push_back("marker " + rom::marker_letter(k) + " (" +
                     byte_range(kPositionsByte + 12 * static_cast<std::size_t>(k), 12) + ")");
  }
  if (with_normal != 0 && with_normal != count) {
    for (long k = 0; k < count; ++k) {
      if (normals.col(k).isZero(0.0)) {
        fail(source, "marker " + rom::marker_letter(k) + " (" +
                         byte_range(kNormalsByte + 12 * static_cast<std::size_t>(k), 12) +
                         "): no normal, while " + std::to_string(with_normal) + " of the " +
                         std::to_string(count) + " markers have one");
      }
    }
  }
  if (with_normal == count) {
    const int angle = rom_byte(bytes, kMaxAngleByte);
    check_byte(angle, 1, 180, kMaxAngleByte, "maximum marker angle, degrees", source);
    const int min_markers = rom_byte(bytes, kMinMarkersByte);
    check_byte(min_markers, 3, count, kMinMarkersByte, "minimum markers", source);
    MarkerVisibility visibility;
    visibility.normals.resize(3, count);
    for (long k = 0; k < count; ++k) visibility.normals.col(k) = unit_normal(normals.col(k));
    visibility.cone_half_angle_deg = Eigen::VectorXd::Constant(count, angle);
    visibility.min_visible = min_markers;
    layout.visibility = visibility;
  }
  internal::validate_labelled(layout, source, labels);
  return layout;
}

NdiRom parse_ndi_rom(std::string_view bytes, const std::string& source) {
  if (bytes.size() < kNdiRomBytes) {
    fail(source, "an NDI tool definition holds " + std::to_string(kNdiRomBytes) +
                     " bytes, this file " + std::to_string(bytes.size()));
  }
  NdiRom tool;
  tool.layout = parse_ndi_rom_layout(bytes, source);
  const std::uint32_t stored = rom::word_at(bytes, rom::kChecksum, 2);
  const std::uint32_t sum = rom::checksum_of(bytes);
  if (stored != sum) {
    fail(source, "bytes 4-5 (checksum): " + std::to_string(stored) +
                     ", while the sum of bytes 6-751 modulo 65536 is " + std::to_string(sum) +
                     " (a damaged file)");
  }
  const long count = tool.layout.entries.cols();
  tool.normals.resize(3, count);
  for (long k = 0; k < count; ++k) {
    tool.normals.col(k) = rom_vector(bytes, kNormalsByte, k, "normal", source);
  }
  tool.max_marker_angle_deg = rom_byte(bytes, rom::kMaxAngle);
  tool.min_markers = rom_byte(bytes, rom::kMinMarkers);
  tool.max_marker_error_mm = rom_float(bytes, rom::kMaxError);
  tool.manufacturer = rom_text(bytes, rom::kManufacturer, rom::kManufacturerSize);
  tool.part_number = rom_text(bytes, rom::kPartNumber, rom::kPartNumberSize);
  tool.tool_main_type = rom_byte(bytes, rom::kMainType);
  tool.tool_sub_type = rom_byte(bytes, rom::kSubType);
  tool.tool_revision = static_cast<int>(rom::word_at(bytes, rom::kRevision, 2));
  tool.firing_sequence = per_marker(bytes, rom::kFiring, count);
  tool.marker_faces = per_marker(bytes, rom::kFaces, count);
  tool.marker_groups = per_marker(bytes, rom::kGroups, count);
  tool.algorithm_flags = rom_byte(bytes, rom::kAlgorithmFlags);
  tool.marker_type = rom_byte(bytes, rom::kMarkerType);
  for (int f = 0; f < kNdiRomMaxFaces; ++f) {
    const std::size_t first = rom::kFaceNormals + 12 * static_cast<std::size_t>(f);
    for (int r = 0; r < 3; ++r) {
      tool.face_normals(r, f) = rom_float(bytes, first + 4 * static_cast<std::size_t>(r));
    }
    if (!tool.face_normals.col(f).allFinite()) {
      fail(source,
           "face " + std::to_string(f + 1) + " (" + byte_range(first, 12) + "): normal not finite");
    }
  }
  if (!std::isfinite(tool.max_marker_error_mm)) {
    fail(source, "bytes 36-39 (maximum marker error): not finite");
  }
  tool.image = std::string(bytes.substr(0, kNdiRomBytes));
  tool.trailing_bytes = bytes.size() - kNdiRomBytes;
  return tool;
}

NdiRom read_ndi_rom(const std::string& path) {
  return parse_ndi_rom(read_text_file(path, kMaxFileBytes), path);
}

int ndi_rom_min_markers(std::string_view bytes, const std::string& source, long markers) {
  if (bytes.size() < kNdiRomMinBytes) {
    fail(source, "an NDI tool definition holds at least " + std::to_string(kNdiRomMinBytes) +
                     " bytes, this file " + std::to_string(bytes.size()));
  }
  const int min_markers = rom_byte(bytes, kMinMarkersByte);
  check_byte(min_markers, 3, static_cast<int>(markers), kMinMarkersByte, "minimum markers", source);
  return min_markers;
}

}  // namespace vantage::io
