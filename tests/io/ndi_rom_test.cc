#include "vantage/io/ndi_rom.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/io/layout_formats.h"

namespace vantage::io {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// The coordinates are float32 in the file and chosen exactly representable (multiples of 1/64),
// so the layout holds the same numbers.
constexpr double kExact = 0.0;

// A 752-byte tool definition built from the byte map of optical-tracker-utilities (ndi_tool.py),
// written byte by byte here independently of the reader: "NDI", maximum marker angle (byte 24),
// marker count (28), minimum markers (32), 20 positions from byte 72 and 20 normals from byte
// 312, float32 little endian. The rest (checksum, types, part number) is filled with noise that
// the reader must ignore.
class RomBytes {
 public:
  RomBytes() : bytes_(752, '\0') {
    for (std::size_t k = 3; k < bytes_.size(); ++k) bytes_[k] = static_cast<char>(k * 37 % 251);
    bytes_.replace(0, 3, "NDI");
    for (std::size_t k = 72; k < 552; ++k) bytes_[k] = '\0';
  }
  RomBytes& byte(std::size_t offset, int value) {
    bytes_[offset] = static_cast<char>(value);
    return *this;
  }
  RomBytes& float32(std::size_t offset, float value) {
    std::uint32_t word = 0;
    std::memcpy(&word, &value, sizeof word);
    for (int b = 0; b < 4; ++b) bytes_[offset + b] = static_cast<char>((word >> (8 * b)) & 0xFF);
    return *this;
  }
  RomBytes& position(int k, float x, float y, float z) { return vector(72, k, x, y, z); }
  RomBytes& normal(int k, float x, float y, float z) { return vector(312, k, x, y, z); }
  const std::string& str() const { return bytes_; }

 private:
  RomBytes& vector(std::size_t table, int k, float x, float y, float z) {
    const std::size_t first = table + 12 * static_cast<std::size_t>(k);
    return float32(first, x).float32(first + 4, y).float32(first + 8, z);
  }
  std::string bytes_;
};

// A passive 4-sphere tool: markers in the z = 0 plane facing +z.
RomBytes four_spheres() {
  RomBytes rom;
  rom.byte(24, 90).byte(28, 4).byte(32, 3);
  rom.position(0, 0, 0, 0).position(1, 0, 50, 0).position(2, 40.25f, 88.5f, 0);
  rom.position(3, -36.015625f, 120, 0);
  return rom;
}

TEST(NdiRom, ReadsPositionsOfAToolWithoutNormals) {
  const Layout layout = parse_ndi_rom_layout(four_spheres().str(), "tools/8700339.rom");
  EXPECT_EQ(layout.name, "8700339");
  EXPECT_EQ(layout.mode, LayoutMode::kPoints);
  EXPECT_THAT(layout.names, ElementsAre("A", "B", "C", "D"));
  Eigen::Matrix3Xd expected(3, 4);
  expected << 0, 0, 40.25, -36.015625,  //
      0, 50, 88.5, 120,                 //
      0, 0, 0, 0;
  EXPECT_EIGEN_NEAR(layout.entries, expected, kExact);
  EXPECT_FALSE(layout.visibility.has_value());
}

TEST(NdiRom, ReadsNormalsAngleAndMinimumMarkers) {
  RomBytes rom = four_spheres();
  rom.byte(24, 75).byte(32, 4);
  for (int k = 0; k < 4; ++k) rom.normal(k, 0, 0, 2);  // not unit: the reader normalises
  const Layout layout = parse_ndi_rom_layout(rom.str(), "tool.rom");
  ASSERT_TRUE(layout.visibility.has_value());
  const MarkerVisibility& v = *layout.visibility;
  EXPECT_EIGEN_NEAR(
      v.normals,
      (Eigen::Matrix3Xd(3, 4) << Eigen::MatrixXd::Zero(2, 4), Eigen::RowVectorXd::Ones(4))
          .finished(),
      kExact);
  EXPECT_EIGEN_NEAR(v.cone_half_angle_deg, Eigen::VectorXd::Constant(4, 75.0), kExact);
  EXPECT_EQ(v.min_visible, 4);
}

TEST(NdiRom, TwentyMarkersAndLoadLayoutByExtension) {
  RomBytes rom;
  rom.byte(28, 20);
  for (int k = 0; k < 20; ++k) rom.position(k, static_cast<float>(k), static_cast<float>(k * k), 1);
  const Layout layout = parse_layout_as(rom.str(), "big.ROM");
  ASSERT_EQ(layout.entries.cols(), 20);
  EXPECT_EQ(layout.names.back(), "T");
  EXPECT_EIGEN_NEAR(layout.entries.col(19), Eigen::Vector3d(19, 361, 1), kExact);
}

// The sum of bytes 6-751 modulo 2^16, written into bytes 4-5 (the file's checksum).
std::string with_checksum(std::string bytes) {
  unsigned sum = 0;
  for (std::size_t k = 6; k < 752; ++k) sum += static_cast<unsigned char>(bytes[k]);
  bytes[4] = static_cast<char>(sum & 0xFFu);
  bytes[5] = static_cast<char>((sum >> 8) & 0xFFu);
  return bytes;
}

// A whole tool: four_spheres() with normals, a finite maximum error and face normals (the noise
// elsewhere stays: the writer must keep it).
std::string whole_tool() {
  RomBytes rom = four_spheres();
  for (int k = 0; k < 4; ++k) rom.normal(k, 0, 0.6f, 0.8f);
  rom.float32(36, 0.75f);
  for (std::size_t k = 656; k < 752; k += 4) rom.float32(k, 0.0f);
  rom.float32(660, 0.6f).float32(664, 0.8f);
  return with_checksum(rom.str());
}

float float_at(const std::string& bytes, std::size_t offset) {
  std::uint32_t word = 0;
  for (int b = 3; b >= 0; --b) word = (word << 8) | static_cast<unsigned char>(bytes[offset + b]);
  float value = 0;
  std::memcpy(&value, &word, sizeof value);
  return value;
}

TEST(NdiRom, AToolReadIsWrittenBackByteForByte) {
  const std::string bytes = whole_tool();
  const NdiRom tool = parse_ndi_rom(bytes, "tool.rom");
  EXPECT_EQ(tool.max_marker_angle_deg, 90);
  EXPECT_EQ(tool.min_markers, 3);
  EXPECT_EQ(tool.max_marker_error_mm, 0.75);
  EXPECT_EIGEN_NEAR(tool.face_normals.col(0), Eigen::Vector3d(0, 0.6f, 0.8f), kExact);
  EXPECT_EQ(tool.trailing_bytes, 0u);
  EXPECT_EQ(ndi_rom_bytes(tool), bytes);
  // A longer file: the 752 are the tool, the rest is counted and not written.
  const NdiRom longer = parse_ndi_rom(bytes + "12345678", "long.rom");
  EXPECT_EQ(longer.trailing_bytes, 8u);
  EXPECT_EQ(ndi_rom_bytes(longer), bytes);
}

TEST(NdiRom, AMovedMarkerChangesItsBytesAndTheChecksumOnly) {
  const std::string bytes = whole_tool();
  NdiRom tool = parse_ndi_rom(bytes, "tool.rom");
  tool.layout.entries(1, 1) = 51.5;  // marker B's y: bytes 88-91
  const std::string moved = ndi_rom_bytes(tool);
  ASSERT_EQ(moved.size(), bytes.size());
  for (std::size_t k = 0; k < bytes.size(); ++k) {
    const bool may_change = (k >= 4 && k < 6) || (k >= 88 && k < 92);
    if (!may_change) {
      EXPECT_EQ(moved[k], bytes[k]) << "byte " << k;
    }
  }
  EXPECT_EQ(float_at(moved, 88), 51.5f);
  EXPECT_EQ(with_checksum(moved), moved);
}

TEST(NdiRom, ANewToolHoldsTheLayoutAtTheDocumentedOffsets) {
  Layout layout = parse_ndi_rom_layout(four_spheres().str(), "tools/probe.rom");
  MarkerVisibility visibility;
  visibility.normals = Eigen::Matrix3Xd::Zero(3, 4);
  visibility.normals.row(2).setOnes();
  visibility.cone_half_angle_deg = Eigen::VectorXd::Constant(4, 70.0);
  visibility.min_visible = 4;
  layout.visibility = visibility;
  const std::string bytes = ndi_rom_bytes(ndi_rom_of_layout(layout));
  ASSERT_EQ(bytes.size(), 752u);
  EXPECT_EQ(bytes.substr(0, 3), "NDI");
  EXPECT_EQ(bytes[24], 70);
  EXPECT_EQ(bytes[28], 4);
  EXPECT_EQ(bytes[32], 4);
  EXPECT_EQ(float_at(bytes, 36), 2.0f);  // the default maximum marker error
  for (int k = 0; k < 4; ++k) {
    for (int r = 0; r < 3; ++r) {
      EXPECT_EQ(float_at(bytes, 72 + 12 * k + 4 * r), static_cast<float>(layout.entries(r, k)));
      EXPECT_EQ(float_at(bytes, 312 + 12 * k + 4 * r), r == 2 ? 1.0f : 0.0f);
    }
    EXPECT_EQ(bytes[552 + k], k);  // fired in order
    EXPECT_EQ(bytes[613 + k], 1);  // face 1
    EXPECT_EQ(bytes[633 + k], 1);  // group 1
  }
  EXPECT_EQ(bytes.substr(592, 6), std::string("probe") + '\0');
  EXPECT_EQ(float_at(bytes, 664), 1.0f);  // face 1's normal: the markers' common direction
  EXPECT_EQ(with_checksum(bytes), bytes);
  const NdiRom back = parse_ndi_rom(bytes, "probe.rom");
  EXPECT_EIGEN_NEAR(back.layout.entries, layout.entries, kExact);
  ASSERT_TRUE(back.layout.visibility.has_value());
  EXPECT_EQ(back.layout.visibility->min_visible, 4);
  EXPECT_EIGEN_NEAR(back.layout.visibility->cone_half_angle_deg, visibility.cone_half_angle_deg,
                    kExact);
  EXPECT_TRUE(ndi_rom_dropped_fields(layout).empty());
}

// What a .rom cannot hold is refused, naming the field.
TEST(NdiRom, WritingRefusesWhatTheFormatCannotHold) {
  const Layout four = parse_ndi_rom_layout(four_spheres().str(), "four.rom");
  auto refused = [](const std::function<void()>& write) {
    try {
      write();
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  Layout cones = four;
  cones.visibility = MarkerVisibility{};
  cones.visibility->normals = Eigen::Matrix3Xd::Zero(3, 4);
  cones.visibility->normals.row(2).setOnes();
  cones.visibility->cone_half_angle_deg = Eigen::Vector4d(80, 80, 80, 70);
  EXPECT_THAT(refused([&] { ndi_rom_of_layout(cones); }),
              HasSubstr("visibility.cone_half_angle_deg: a .rom holds one maximum marker angle"));
  cones.visibility->cone_half_angle_deg.setConstant(80.5);
  EXPECT_THAT(refused([&] { ndi_rom_of_layout(cones); }),
              HasSubstr("visibility.cone_half_angle_deg: a .rom holds a whole number of degrees"));
  Layout far = four;
  far.entries *= 1e37;  // marker B's y, 5e38, is past the largest float32 (3.4e38)
  EXPECT_THAT(refused([&] { ndi_rom_bytes(ndi_rom_of_layout(far)); }),
              HasSubstr("points[1]: 5e+38 is not a finite float32"));
  Layout tiny = four;
  tiny.entries *= 1e-100;  // distinct in double, all 0 in float32
  EXPECT_THAT(refused([&] { ndi_rom_bytes(ndi_rom_of_layout(tiny)); }),
              HasSubstr("points: rounded to float32, a .rom's precision: the tool as written: "
                        "marker B"));
  Layout many;
  many.mode = LayoutMode::kPoints;
  many.entries = Eigen::Matrix3Xd::Random(3, 21);
  many.weights = Eigen::VectorXd::Ones(21);
  EXPECT_THAT(refused([&] { ndi_rom_of_layout(many); }),
              HasSubstr("points: a .rom holds 3 to 20 markers, the layout has 21"));
  NdiRom named = ndi_rom_of_layout(four);
  named.part_number = std::string(21, 'p');
  EXPECT_THAT(refused([&] { ndi_rom_bytes(named); }),
              HasSubstr("part_number: at most 20 characters, got 21"));
  // A tool read and cut down so that the file would be refused on reading.
  NdiRom cut = parse_ndi_rom(whole_tool(), "tool.rom");
  cut.min_markers = 4;
  cut.layout.entries.conservativeResize(3, 3);
  cut.normals.conservativeResize(3, 3);
  cut.firing_sequence.resize(3);
  cut.marker_faces.resize(3);
  cut.marker_groups.resize(3);
  EXPECT_THAT(refused([&] { ndi_rom_bytes(cut); }),
              HasSubstr("min_markers: 3 to the 3 markers, got 4"));
  cut.min_markers = 3;
  const std::string three = ndi_rom_bytes(cut);
  for (std::size_t k = 72 + 36; k < 312; ++k) EXPECT_EQ(three[k], '\0') << "byte " << k;
  EXPECT_EQ(parse_ndi_rom(three, "three.rom").layout.entries.cols(), 3);
  cut.normals.col(1).setZero();
  EXPECT_THAT(refused([&] { ndi_rom_bytes(cut); }),
              HasSubstr("normals: a .rom holds a normal for every marker or for none"));
  // A damaged file: the checksum is not the sum.
  std::string damaged = whole_tool();
  damaged[4] = static_cast<char>(damaged[4] + 1);
  EXPECT_THAT(refused([&] { parse_ndi_rom(damaged, "damaged.rom"); }),
              HasSubstr("damaged.rom: bytes 4-5 (checksum): "));
  EXPECT_THAT(refused([&] { parse_ndi_rom(damaged.substr(0, 751), "short.rom"); }),
              HasSubstr("short.rom: an NDI tool definition holds 752 bytes, this file 751"));
}

struct BadRom {
  const char* name;
  std::string bytes;
  const char* expected;
};

class BadRomFile : public ::testing::TestWithParam<BadRom> {};

TEST_P(BadRomFile, GivesOneLineNamingTheBytes) {
  std::string message;
  try {
    parse_ndi_rom_layout(GetParam().bytes, "bad.rom");
  } catch (const InvalidArgument& e) {
    message = e.what();
  }
  ASSERT_FALSE(message.empty()) << "accepted: " << GetParam().name;
  EXPECT_THAT(message, HasSubstr("bad.rom: "));
  EXPECT_THAT(message, HasSubstr(GetParam().expected));
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

std::string without_magic() {
  std::string bytes = four_spheres().str();
  bytes[1] = 'X';
  return bytes;
}

const BadRom kBadRoms[] = {
    {"Short", four_spheres().str().substr(0, 551), "holds at least 552 bytes, this file 551"},
    {"NoMagic", without_magic(), "bytes 0-2: not \"NDI\""},
    {"TwoMarkers", four_spheres().byte(28, 2).str(),
     "byte 28 (marker count): expected 3 to 20, got 2"},
    {"TwentyOneMarkers", four_spheres().byte(28, 21).str(), "byte 28 (marker count)"},
    {"NaNPosition", four_spheres().float32(76, std::nanf("")).str(),
     "marker A (bytes 72-83): position not finite"},
    {"SomeNormals", four_spheres().normal(0, 0, 0, 1).normal(1, 0, 0, 1).str(),
     "marker C (bytes 336-347): no normal, while 2 of the 4 markers have one"},
    {"ZeroAngle",
     four_spheres()
         .byte(24, 0)
         .normal(0, 0, 0, 1)
         .normal(1, 0, 0, 1)
         .normal(2, 0, 0, 1)
         .normal(3, 0, 0, 1)
         .str(),
     "byte 24 (maximum marker angle, degrees): expected 1 to 180, got 0"},
    {"MinimumAboveCount",
     four_spheres()
         .byte(32, 5)
         .normal(0, 0, 0, 1)
         .normal(1, 0, 0, 1)
         .normal(2, 0, 0, 1)
         .normal(3, 0, 0, 1)
         .str(),
     "byte 32 (minimum markers): expected 3 to 4, got 5"},
    {"Coincident", four_spheres().position(1, 0, 0, 0).str(), "marker B (bytes 84-95)"},
};

INSTANTIATE_TEST_SUITE_P(NdiRom, BadRomFile, ::testing::ValuesIn(kBadRoms),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace vantage::io
