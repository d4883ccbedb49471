// NDI tool definitions written by NDI's and others' tools (VANTAGE_REAL_INPUTS_DIR/ndi-rom, the
// folder of real-inputs/README.md): every 752-byte file reads and is written back byte for byte;
// a tool written from its fields alone equals the file except where the format keeps what the
// byte map does not name; the tools decode to NDI's published coordinates; the 760-byte and the
// 0-byte files get their documented verdicts.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/io/ndi_rom.h"

namespace vantage {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path kRoms = std::filesystem::path(VANTAGE_REAL_INPUTS_DIR) / "ndi-rom";

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The .rom files of the folder that hold a whole tool (752 bytes).
std::vector<std::filesystem::path> whole_tools() {
  std::vector<std::filesystem::path> out;
  for (const auto& entry : std::filesystem::directory_iterator(kRoms)) {
    if (entry.path().extension() == ".rom" && entry.file_size() == io::kNdiRomBytes) {
      out.push_back(entry.path());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(NdiRomRealInputs, EveryToolIsWrittenBackByteForByte) {
  const std::vector<std::filesystem::path> tools = whole_tools();
  EXPECT_EQ(tools.size(), 18u);  // README: 15 from PlusLibData, 3 from sawNDITracker
  for (const std::filesystem::path& path : tools) {
    const std::string bytes = file_bytes(path);
    const io::NdiRom tool = io::parse_ndi_rom(bytes, path.string());
    EXPECT_EQ(io::ndi_rom_bytes(tool), bytes) << path;
  }
}

// The writer's own encoding of every field: the tool rebuilt from its fields over a new image
// (no bytes of the file) equals the file, except the checksum (it covers the date), the
// sequence number and date (bytes 20-23, which a new tool leaves zero) and the slots past the
// marker count (positions, normals, firing sequence, faces and groups of markers the tool does
// not have: one real file holds leftovers there).
TEST(NdiRomRealInputs, ToolsRebuiltFromTheirFieldsAreTheFiles) {
  for (const std::filesystem::path& path : whole_tools()) {
    const std::string bytes = file_bytes(path);
    io::NdiRom rebuilt = io::parse_ndi_rom(bytes, path.string());
    rebuilt.image.clear();
    const std::string written = io::ndi_rom_bytes(rebuilt);
    const std::size_t n = static_cast<std::size_t>(rebuilt.layout.entries.cols());
    auto past_count = [n](std::size_t k, std::size_t table, std::size_t width) {
      return k >= table + width * n && k < table + width * 20;
    };
    for (std::size_t k = 0; k < bytes.size(); ++k) {
      const bool kept = (k >= 4 && k < 6) || (k >= 20 && k < 24) || past_count(k, 72, 12) ||
                        past_count(k, 312, 12) || past_count(k, 552, 1) || past_count(k, 613, 1) ||
                        past_count(k, 633, 1);
      if (!kept) {
        EXPECT_EQ(written[k], bytes[k]) << path << " byte " << k;
      }
    }
  }
}

// NDI's published marker coordinates (derived/ndi-published-geometry.csv, printed to 0.01 mm) are
// what the tools' files decode to.
TEST(NdiRomRealInputs, ToolsDecodeToNdisPublishedCoordinates) {
  constexpr double kPrinted = 0.005;  // half the published 0.01 mm
  std::ifstream csv(std::filesystem::path(VANTAGE_REAL_INPUTS_DIR) / "derived" /
                    "ndi-published-geometry.csv");
  std::string line;
  int rows = 0;
  while (std::getline(csv, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("part,", 0) == 0) continue;
    std::istringstream fields(line);
    std::string part, marker, x, y, z;
    std::getline(fields, part, ',');
    std::getline(fields, marker, ',');
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    std::getline(fields, z, ',');
    const std::string bytes = file_bytes(kRoms / ("PlusLibData__" + part + ".rom"));
    const Layout tool = io::parse_ndi_rom_layout(bytes, part + ".rom");
    const Eigen::Vector3d published(std::stod(x), std::stod(y), std::stod(z));
    EXPECT_LE((tool.entries.col(std::stoi(marker)) - published).cwiseAbs().maxCoeff(), kPrinted)
        << part << " marker " << marker;
    ++rows;
  }
  EXPECT_EQ(rows, 12);
}

TEST(NdiRomRealInputs, TheLongAndTheEmptyFilesGetTheirVerdicts) {
  // 760 bytes: a valid tool (its checksum matches) and 8 bytes after it, which are not written.
  const std::string longer = file_bytes(kRoms / "CustusX__Lap_REFERENCE_frame_small.rom");
  ASSERT_EQ(longer.size(), 760u);
  const io::NdiRom tool = io::parse_ndi_rom(longer, "long.rom");
  EXPECT_EQ(tool.trailing_bytes, 8u);
  EXPECT_EQ(io::ndi_rom_bytes(tool), longer.substr(0, io::kNdiRomBytes));
  // 0 bytes: refused, by the layout reader and the tool reader alike.
  const std::string empty = file_bytes(kRoms / "CustusX__Lab_USProbe_Spectra_30092008_8700449.rom");
  ASSERT_TRUE(empty.empty());
  try {
    io::parse_ndi_rom_layout(empty, "empty.rom");
    ADD_FAILURE() << "the empty file was read";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(e.what(), HasSubstr("empty.rom: an NDI tool definition holds at least 552 bytes, "
                                    "this file 0"));
  }
  EXPECT_THROW(io::parse_ndi_rom(empty, "empty.rom"), InvalidArgument);
}

}  // namespace
}  // namespace vantage
