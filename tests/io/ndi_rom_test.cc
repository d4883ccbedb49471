#include "vantage/io/ndi_rom.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
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
