// `vantage layout board --type chessboard|charuco|aprilgrid --rows R --cols C --square S
// [--marker M] [--spacing G] --out FILE.json [--overwrite] [--json]`: writes the layout of the
// points a detector measures on a standard calibration target, so the printed target can be
// analysed like any other layout. `vantage layout convert` (layout_convert.cc) converts formats,
// `vantage layout snap` (layout_snap.cc) moves markers onto their body.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>

#include "command.h"
#include "layout_convert.h"
#include "vantage/analysis/common.h"
#include "vantage/io/calibration_board.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/text_file.h"

namespace vantage::cli {

namespace {

struct BoardArgs {
  std::string type;
  io::BoardOptions board;
  std::string out;
  bool overwrite = false;
  bool json = false;
};

std::string lowercase_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

int run_board(BoardArgs args) {
  args.board.type = io::board_type_from_string(args.type, "--type");
  std::string why;
  if (!args.board.is_valid(&why)) throw InvalidArgument("--" + why);
  if (lowercase_extension(args.out) != ".json") {
    throw InvalidArgument("--out: " + args.out + ": layouts are written as JSON; use a .json name");
  }
  try {
    io::check_write_target(args.out, args.overwrite);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("--out: ") + e.what());
  }
  const Layout layout = io::calibration_board(args.board);
  io::write_layout(args.out, layout, args.overwrite);
  if (args.json) {
    Json out;
    out["type"] = args.type;
    out["rows"] = args.board.rows;
    out["cols"] = args.board.cols;
    out["square"] = args.board.square;
    if (args.board.type == io::BoardType::kCharuco && args.board.marker > 0) {
      out["marker"] = args.board.marker;
    }
    if (args.board.type == io::BoardType::kAprilGrid) out["spacing"] = args.board.spacing;
    out["name"] = layout.name;
    out["n_points"] = layout.entries.cols();
    out["written"] = args.out;
    print_json(out);
  } else {
    std::cout << "vantage layout board: " << layout.name << "\n"
              << "  " << layout.entries.cols() << " points (" << layout.description << ")\n"
              << "written: " << args.out << "\n";
  }
  return kExitOk;
}

}  // namespace

Command add_layout_command(CLI::App& root) {
  CLI::App* layout = root.add_subcommand("layout", "Make layouts of standard objects");
  layout->require_subcommand(1, 1);
  auto args = std::make_shared<BoardArgs>();
  CLI::App* sub = layout->add_subcommand(
      "board",
      "Write the layout of a calibration target: chessboard or ChArUco inner corners (OpenCV), "
      "or the tag corners of a Kalibr aprilgrid, in the board's z = 0 plane");
  sub->add_option("--type", args->type, "chessboard, charuco or aprilgrid")
      ->required()
      ->check(CLI::IsMember({"chessboard", "charuco", "aprilgrid"}));
  sub->add_option("--rows", args->board.rows,
                  "squares (chessboard, charuco) or tags (aprilgrid) along y")
      ->required();
  sub->add_option("--cols", args->board.cols,
                  "squares (chessboard, charuco) or tags (aprilgrid) along x")
      ->required();
  sub->add_option("--square", args->board.square,
                  "side of a square (chessboard, charuco) or of a tag (aprilgrid), in your unit")
      ->required();
  sub->add_option("--marker", args->board.marker,
                  "charuco: side of the ArUco markers (< square; recorded in the name)");
  sub->add_option("--spacing", args->board.spacing,
                  "aprilgrid: gap between tags over the tag side (Kalibr tagSpacing)")
      ->capture_default_str();
  sub->add_option("--out", args->out, "the layout JSON file to write")->required();
  sub->add_flag("--overwrite", args->overwrite, "replace --out if it exists");
  sub->add_flag("--json", args->json, "print one JSON object instead of the report");
  const Command convert = add_layout_convert_subcommand(layout);
  const Command snap = add_layout_snap_subcommand(layout);
  return {layout, [args, convert, snap] {
            if (convert.app->parsed()) return convert.run();
            return snap.app->parsed() ? snap.run() : run_board(*args);
          }};
}

}  // namespace vantage::cli
