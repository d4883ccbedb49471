// parse_ndi_rom_layout(): NDI tool definition files, read by the byte map of ndi_rom.h.

#include "vantage/io/ndi_rom.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <vector>

#include "entry_labels.h"
#include "json_fields.h"
#include "vantage/analysis/common.h"

namespace vantage::io {

namespace {

using internal::fail;

constexpr std::size_t kMaxAngleByte = 24;
constexpr std::size_t kCountByte = 28;
constexpr std::size_t kMinMarkersByte = 32;
constexpr std::size_t kPositionsByte = 72;
constexpr std::size_t kNormalsByte = 312;

/// The little-endian float32 at `offset`, whatever the host's byte order.
double rom_float(std::string_view bytes, std::size_t offset) {
  std::uint32_t word = 0;
  for (int b = 3; b >= 0; --b) {
    word = (word << 8) | static_cast<unsigned char>(bytes[offset + static_cast<std::size_t>(b)]);
  }
  float value = 0;
  std::memcpy(&value, &word, sizeof value);
  return value;
}

std::string byte_range(std::size_t first, std::size_t size) {
  return "bytes " + std::to_string(first) + "-" + std::to_string(first + size - 1);
}

std::string marker_letter(long k) { return std::string(1, static_cast<char>('A' + k)); }

/// Vector k of the 20 at `table`, checked finite.
Eigen::Vector3d rom_vector(std::string_view bytes, std::size_t table, long k, const char* what,
                           const std::string& source) {
  const std::size_t first = table + 12 * static_cast<std::size_t>(k);
  Eigen::Vector3d v;
  for (int r = 0; r < 3; ++r) v(r) = rom_float(bytes, first + 4 * static_cast<std::size_t>(r));
  if (!v.allFinite()) {
    fail(source, "marker " + marker_letter(k) + " (" + byte_range(first, 12) + "): " + what +
                     " not finite");
  }
  return v;
}

int rom_byte(std::string_view bytes, std::size_t offset) {
  return static_cast<unsigned char>(bytes[offset]);
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
    layout.names.push_back(marker_letter(k));
    labels.push_back("marker " + marker_letter(k) + " (" +
                     byte_range(kPositionsByte + 12 * static_cast<std::size_t>(k), 12) + ")");
  }
  if (with_normal != 0 && with_normal != count) {
    for (long k = 0; k < count; ++k) {
      if (normals.col(k).isZero(0.0)) {
        fail(source, "marker " + marker_letter(k) + " (" +
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

}  // namespace vantage::io
