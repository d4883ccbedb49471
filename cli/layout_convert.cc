// `vantage layout convert IN --out OUT [--format F] [--tag-points ...] [--bundle NAME]
// [--overwrite] [--allow-large] [--json]`: reads a layout in any format (io::load_layout) and
// writes it in the format of OUT's extension (io::save_layout): JSON, CSV, an Atracsys geometry
// .ini, whose id the name of OUT ends in, or an NDI tool definition .rom (a .rom read is written
// back byte for byte: io::read_ndi_rom). What OUT's format cannot hold is either refused (CSV:
// candidates, direction vectors; .ini and .rom: direction vectors, candidates, too many
// markers) or, for an .ini or a .rom, left out and listed (names, weights, normals, ...).

#include <filesystem>
#include <iostream>
#include <memory>

#include "layout_convert.h"
#include "layout_input.h"
#include "vantage/analysis/common.h"
#include "vantage/io/atracsys_geometry.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/ndi_rom.h"
#include "vantage/io/printable.h"
#include "vantage/io/text_file.h"

namespace vantage::cli {

namespace {

struct ConvertArgs {
  std::string in;
  std::string out;
  LayoutInput input;
  bool overwrite = false;
  bool allow_large = false;
  bool json = false;
};

int run_convert(const ConvertArgs& args) {
  io::LayoutFormat out_format = io::LayoutFormat::kJson;
  try {
    out_format = io::layout_write_format(args.out);
    io::check_write_target(args.out, args.overwrite);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("--out: ") + e.what());
  }
  const io::LayoutFormat chosen = io::layout_format_from_string(args.input.format, "--format");
  const io::LayoutFormat in_format =
      chosen == io::LayoutFormat::kAuto ? io::layout_format_of(args.in) : chosen;
  const Layout layout = args.input.read(args.in, args.allow_large);
  std::vector<std::string> dropped;
  if (out_format == io::LayoutFormat::kAtracsys) dropped = io::atracsys_dropped_fields(layout);
  std::error_code size_error;
  const bool whole_rom = in_format == io::LayoutFormat::kNdiRom &&
                         std::filesystem::file_size(args.in, size_error) >= io::kNdiRomBytes;
  if (in_format == io::LayoutFormat::kNdiRom && !whole_rom && out_format == in_format) {
    std::cerr << "vantage: warning: layout convert: " << io::printable(args.in)
              << ": fewer than a tool's " << io::kNdiRomBytes
              << " bytes; written as a new tool from its markers" << std::endl;
  }
  if (out_format == io::LayoutFormat::kNdiRom && whole_rom) {
    // A tool to a tool: every byte of the 752 is kept, so an unchanged tool is the same file.
    const io::NdiRom tool = io::read_ndi_rom(args.in);
    if (tool.trailing_bytes > 0) {
      dropped.push_back("trailing_bytes");
      std::cerr << "vantage: warning: layout convert: " << io::printable(args.in) << ": the "
                << tool.trailing_bytes << " bytes after the tool's " << io::kNdiRomBytes
                << " are not part of it and are not written" << std::endl;
    }
    io::write_text_file(args.out, io::ndi_rom_bytes(tool), args.overwrite);
  } else {
    if (out_format == io::LayoutFormat::kNdiRom) dropped = io::ndi_rom_dropped_fields(layout);
    io::save_layout(args.out, layout, args.overwrite);
  }
  if (args.json) {
    Json out;
    out["input"] = args.in;
    out["input_format"] = io::to_string(in_format);
    out["written"] = args.out;
    out["output_format"] = io::to_string(out_format);
    out["mode"] = to_string(layout.mode);
    out["entries"] = layout.entries.cols();
    if (out_format == io::LayoutFormat::kAtracsys) {
      out["geometry_id"] = io::atracsys_geometry_id_of(args.out);
    }
    out["dropped"] = dropped;
    print_json(out);
    return kExitOk;
  }
  std::cout << "vantage layout convert: " << args.in << " (" << io::to_string(in_format) << ") -> "
            << args.out << " (" << io::to_string(out_format) << ")\n"
            << "  " << layout.entries.cols() << " " << layout.entries_field() << "\n";
  if (out_format == io::LayoutFormat::kAtracsys) {
    std::cout << "  geometry id " << io::atracsys_geometry_id_of(args.out) << "\n";
  }
  if (!dropped.empty()) {
    std::cout << "  left out (the format cannot hold them):";
    for (const std::string& field : dropped) std::cout << " " << field;
    std::cout << "\n";
  }
  std::cout << "written: " << args.out << "\n";
  return kExitOk;
}

}  // namespace

Command add_layout_convert_subcommand(CLI::App* layout) {
  auto args = std::make_shared<ConvertArgs>();
  CLI::App* sub = layout->add_subcommand(
      "convert",
      "Write a layout in another format: any format read (.json, .csv, .yaml, .ini, .rom) to "
      ".json, .csv, an Atracsys geometry .ini (named for its id, e.g. geometry150.ini) or an "
      "NDI tool definition .rom");
  sub->add_option("IN", args->in, "the layout file to read")->required();
  sub->add_option("--out", args->out, "the file to write; its extension names the format")
      ->required();
  args->input.add_options(sub);
  sub->add_flag("--overwrite", args->overwrite, "replace --out if it exists");
  sub->add_flag("--allow-large", args->allow_large, "read inputs up to 1 GiB");
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  return {sub, [args] { return run_convert(*args); }};
}

}  // namespace vantage::cli
