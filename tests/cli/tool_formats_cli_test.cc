// Tracker tool files (issue 20): `vantage layout convert` writes an Atracsys geometry .ini and
// reads it back to the same positions; every command reads .ini and .rom tools; bad tool files
// and names are refused with one line and nothing written.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_runner.h"

namespace vantage {
namespace {

using ::testing::ElementsAre;
using testing::expect_bad_input;
using ::testing::HasSubstr;
using testing::run_json;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kTool = std::string(VANTAGE_SOURCE_DIR) + "/examples/tools/passive4_150.ini";

// Digits no decimal round trip loses (1/3 needs all 17), names the .ini cannot keep.
constexpr const char* kToolJson = R"({
  "name": "pointer",
  "points": [[0, 0, 0], [0, 50.333333333333336, 0], [40.1, 90, 1e-3], [-45, 115, -2.5]],
  "names": ["tip side", "B", "C", "D"]
})";

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(ToolFormatsCli, JsonToIniToJsonKeepsThePositionsBitForBit) {
  ScratchDir scratch;
  scratch.write("pointer.json", kToolJson);
  const auto to_ini = run_json("layout convert pointer.json --out geometry150.ini", scratch);
  EXPECT_EQ(to_ini["output_format"], "atracsys");
  EXPECT_EQ(to_ini["geometry_id"], 150);
  EXPECT_EQ(to_ini["entries"], 4);
  EXPECT_THAT(to_ini["dropped"], ElementsAre("names"));
  const auto to_json = run_json("layout convert geometry150.ini --out back.json", scratch);
  EXPECT_EQ(to_json["input_format"], "atracsys");
  EXPECT_TRUE(to_json["dropped"].empty());
  const nlohmann::json original = read_json(scratch.path("pointer.json"));
  const nlohmann::json back = read_json(scratch.path("back.json"));
  ASSERT_EQ(back["points"].size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    for (std::size_t r = 0; r < 3; ++r) {
      EXPECT_EQ(back["points"][k][r].get<double>(), original["points"][k][r].get<double>())
          << "point " << k << ", coordinate " << r;
    }
  }
  EXPECT_THAT(back["names"], ElementsAre("fiducial0", "fiducial1", "fiducial2", "fiducial3"));
  // The readable report says what was left out.
  const auto report = run_vantage("layout convert pointer.json --out tool_7.ini", scratch);
  EXPECT_EQ(report.status, 0) << report.err;
  EXPECT_THAT(report.out, HasSubstr("geometry id 7"));
  EXPECT_THAT(report.out, HasSubstr("left out (the format cannot hold them): names"));
}

TEST(ToolFormatsCli, AnalyzeReadsTheIniAsItsJson) {
  ScratchDir scratch;
  const auto from_ini = run_json("analyze '" + kTool + "'", scratch);
  EXPECT_EQ(from_ini["mode"], "points");
  run_json("layout convert '" + kTool + "' --out tool.json", scratch);
  const auto from_json = run_json("analyze tool.json", scratch);
  EXPECT_EQ(from_ini["pbar_min"].get<double>(), from_json["pbar_min"].get<double>());
  EXPECT_EQ(from_ini["n_vectors"], 6);
  // --format atracsys reads any extension.
  std::filesystem::copy_file(kTool, scratch.path("tool.txt"));
  const auto forced = run_json("analyze tool.txt --format atracsys", scratch);
  EXPECT_EQ(forced["pbar_min"].get<double>(), from_ini["pbar_min"].get<double>());
}

TEST(ToolFormatsCli, AnalyzeReadsAnNdiRom) {
  ScratchDir scratch;
  // Four markers of examples/tools/passive4_150.ini at the documented offsets (ndi_rom.h).
  std::string rom(752, '\0');
  rom.replace(0, 3, "NDI");
  rom[28] = 4;
  const float points[4][3] = {{0, 0, 0}, {0, 50, 0}, {40, 90, 0}, {-45, 115, 0}};
  for (int k = 0; k < 4; ++k) {
    for (int r = 0; r < 3; ++r) {
      std::memcpy(&rom[72 + 12 * k + 4 * r], &points[k][r], 4);  // x86-64 and ARM: little endian
    }
  }
  std::ofstream(scratch.path("tool.rom"), std::ios::binary) << rom;
  const auto from_rom = run_json("analyze tool.rom", scratch);
  const auto from_ini = run_json("analyze '" + kTool + "'", scratch);
  EXPECT_EQ(from_rom["pbar_min"].get<double>(), from_ini["pbar_min"].get<double>());
}

// A .rom written from a layout reads back to the same markers (positions exactly representable
// in float32), normals, cone and minimum markers; the bytes at the documented offsets (ndi_rom.h)
// hold them, and bytes 4-5 hold the sum of bytes 6-751 (computed here, independently).
TEST(ToolFormatsCli, WritesAnNdiRomThatReadsBack) {
  ScratchDir scratch;
  scratch.write("probe.json",
                R"({"name": "probe7", "points": [[0,0,0],[0,50.25,0],[40,90,-1.5],[-45,115,0.125]],
    "normals": [[0,0,1],[0,0.6,0.8],[0,0,1],[0.6,0,0.8]],
    "visibility": {"cone_half_angle_deg": 75, "min_visible": 4}})");
  const auto report = run_vantage("layout convert probe.json --out probe.rom", scratch);
  ASSERT_EQ(report.status, 0) << report.err;
  EXPECT_THAT(report.out, HasSubstr("(ndi)"));
  std::ifstream in(scratch.path("probe.rom"), std::ios::binary);
  const std::string rom((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_EQ(rom.size(), 752u);
  EXPECT_EQ(rom.substr(0, 3), "NDI");
  EXPECT_EQ(rom[24], 75);
  EXPECT_EQ(rom[28], 4);
  EXPECT_EQ(rom[32], 4);
  EXPECT_EQ(rom.substr(592, 7), std::string("probe7") + '\0');
  unsigned sum = 0;
  for (std::size_t k = 6; k < 752; ++k) sum += static_cast<unsigned char>(rom[k]);
  EXPECT_EQ(static_cast<unsigned char>(rom[4]) + 256u * static_cast<unsigned char>(rom[5]),
            sum % 65536u);
  float y1 = 0;
  std::memcpy(&y1, &rom[72 + 12 + 4], 4);  // marker B's y, little endian
  EXPECT_EQ(y1, 50.25f);
  const auto from_json = run_json("analyze probe.json", scratch);
  const auto from_rom = run_json("analyze probe.rom", scratch);
  EXPECT_EQ(from_rom["pbar_min"].get<double>(), from_json["pbar_min"].get<double>());
  EXPECT_EQ(from_rom["visibility"]["pbar_min"].get<double>(),
            from_json["visibility"]["pbar_min"].get<double>());
  // A tool written again from the .rom is the same file, byte for byte.
  run_json("layout convert probe.rom --out again.rom", scratch);
  EXPECT_EQ(testing::read_file(scratch.path("again.rom")), rom);
  // Bytes after the 752 are not part of the tool: read, warned about, not written.
  scratch.write("long.rom", rom + "trailing");
  const auto longer = run_vantage("layout convert long.rom --out short.rom", scratch);
  EXPECT_EQ(longer.status, 0) << longer.err;
  EXPECT_THAT(longer.err, HasSubstr("vantage: warning: layout convert: long.rom: the 8 bytes "
                                    "after the tool's 752 are not part of it and are not "
                                    "written"));
  EXPECT_EQ(testing::read_file(scratch.path("short.rom")), rom);
  // What a .rom cannot hold is listed.
  scratch.write("pointer.json", kToolJson);
  const auto dropped = run_json("layout convert pointer.json --out pointer.rom", scratch);
  EXPECT_THAT(dropped["dropped"], ElementsAre("names"));
  EXPECT_EQ(dropped["output_format"], "ndi");
}

TEST(ToolFormatsCli, BadToolsAndNamesWriteNothing) {
  ScratchDir scratch;
  scratch.write("pointer.json", kToolJson);
  expect_bad_input(run_vantage("layout convert pointer.json --out tool.ini", scratch),
                   "--out: tool.ini: cannot tell the geometry id from the file name");
  std::string many = R"({"points": [)";
  for (int k = 0; k < 21; ++k)
    many += (k ? ",[" : "[") + std::to_string(k) + "," + std::to_string(k * k) + ",0]";
  scratch.write("many.json", many + "]}");
  expect_bad_input(run_vantage("layout convert many.json --out tool.rom", scratch),
                   "tool.rom: points: a .rom holds 3 to 20 markers, the layout has 21");
  scratch.write("cones.json", R"({"points": [[0,0,0],[50,0,0],[0,60,0],[30,30,0]],
    "normals": [[0,0,1],[0,0,1],[0,0,1],[0,0,1]], "visibility": {"cone_half_angle_deg": 72.5}})");
  expect_bad_input(run_vantage("layout convert cones.json --out tool.rom", scratch),
                   "visibility.cone_half_angle_deg: a .rom holds a whole number of degrees");
  // design --write to a .rom counts the additions before the search.
  std::string nineteen = R"({"points": [)";
  for (int k = 0; k < 19; ++k) {
    nineteen += (k ? ",[" : "[") + std::to_string(k) + "," + std::to_string(k * k % 7) + "," +
                std::to_string(k % 3) + "]";
  }
  scratch.write("nineteen.json", nineteen + "]}");
  expect_bad_input(run_vantage("design nineteen.json --add 2 --write big.rom", scratch),
                   "a .rom holds 3 to 20 markers, the layout has 21");
  scratch.write("empty.rom", "");
  expect_bad_input(run_vantage("layout convert empty.rom --out out.json", scratch),
                   "empty.rom: an NDI tool definition holds at least 552 bytes, this file 0");
  scratch.write("bad150.ini", "[geometry]\ncount=3\nid=150\n[fiducial0]\nx=0\ny=zero\nz=0\n");
  expect_bad_input(run_vantage("analyze bad150.ini", scratch),
                   "bad150.ini: line 6, [fiducial0] y: expected a finite number (mm)");
  expect_bad_input(run_vantage("layout convert bad150.ini --out out.json", scratch),
                   "line 6, [fiducial0] y");
  scratch.write("seven.json",
                R"({"points": [[0,0,0],[1,0,0],[0,1,0],[0,0,1],[1,1,0],[1,0,1],[0,1,1]]})");
  expect_bad_input(run_vantage("layout convert seven.json --out geometry7.ini", scratch),
                   "holds 3 to 6 fiducials, the layout has 7");
  for (const char* name : {"tool.ini", "tool.rom", "out.json", "geometry7.ini", "big.rom"}) {
    EXPECT_FALSE(std::filesystem::exists(scratch.path(name))) << name;
  }
}

}  // namespace
}  // namespace vantage
