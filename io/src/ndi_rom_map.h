#pragma once

// Private to the .rom reader and writer: the byte offsets of ndi_rom.h's map, and the
// little-endian words at them (whatever the host's byte order).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace vantage::io::internal::rom {

constexpr std::size_t kChecksum = 4;  // uint16, the sum of bytes 6-751 modulo 2^16
constexpr std::size_t kChecksummedFrom = 6;
constexpr std::size_t kSubType = 12;
constexpr std::size_t kMainType = 15;
constexpr std::size_t kRevision = 16;  // uint16
constexpr std::size_t kMaxAngle = 24;
constexpr std::size_t kCount = 28;
constexpr std::size_t kMinMarkers = 32;
constexpr std::size_t kMaxError = 36;   // float32
constexpr std::size_t kMinSpread = 40;  // 3 x float32 (kept as read)
constexpr std::size_t kPositions = 72;  // 20 x 3 x float32
constexpr std::size_t kNormals = 312;   // 20 x 3 x float32
constexpr std::size_t kFiring = 552;    // 20 x uint8
constexpr std::size_t kLeds = 572;      // 4 x uint8, 31 = none (kept as read)
constexpr std::size_t kToolInPort = 576;
constexpr std::size_t kManufacturer = 580;
constexpr std::size_t kManufacturerSize = 12;
constexpr std::size_t kPartNumber = 592;
constexpr std::size_t kPartNumberSize = 20;
constexpr std::size_t kByte612 = 612;  // 9 in NDI's current files, 17 in older ones
constexpr std::size_t kFaces = 613;    // 20 x uint8
constexpr std::size_t kGroups = 633;   // 20 x uint8
constexpr std::size_t kAlgorithmFlags = 653;
constexpr std::size_t kMarkerType = 655;
constexpr std::size_t kFaceNormals = 656;  // 8 x 3 x float32
constexpr std::size_t kUnknownFloat = 64;  // float32: 10 in every real file (kept as read)

// NDI's name of marker k: "A", "B", ...
inline std::string marker_letter(long k) { return std::string(1, static_cast<char>('A' + k)); }

inline unsigned byte_at(std::string_view bytes, std::size_t offset) {
  return static_cast<unsigned char>(bytes[offset]);
}

inline std::uint32_t word_at(std::string_view bytes, std::size_t offset, int size) {
  std::uint32_t word = 0;
  for (int b = size - 1; b >= 0; --b) {
    word = (word << 8) | byte_at(bytes, offset + static_cast<std::size_t>(b));
  }
  return word;
}

inline void put_word(std::string& bytes, std::size_t offset, std::uint32_t word, int size) {
  for (int b = 0; b < size; ++b) {
    bytes[offset + static_cast<std::size_t>(b)] = static_cast<char>((word >> (8 * b)) & 0xFFu);
  }
}

// The sum of bytes 6-751, modulo 2^16: what bytes 4-5 hold.
inline std::uint32_t checksum_of(std::string_view bytes) {
  std::uint32_t sum = 0;
  for (std::size_t k = kChecksummedFrom; k < 752; ++k) sum += byte_at(bytes, k);
  return sum & 0xFFFFu;
}

}  // namespace vantage::io::internal::rom
