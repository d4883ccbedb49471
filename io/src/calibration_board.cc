#include "vantage/io/calibration_board.h"

#include <cmath>
#include <sstream>

#include "vantage/analysis/common.h"
#include "vantage/io/printable.h"

namespace vantage::io {

BoardType board_type_from_string(const std::string& name, const std::string& option) {
  if (name == "chessboard") return BoardType::kChessboard;
  if (name == "charuco") return BoardType::kCharuco;
  if (name == "aprilgrid") return BoardType::kAprilGrid;
  throw InvalidArgument(option + ": expected chessboard, charuco or aprilgrid, got \"" +
                        printable(name) + "\"");
}

const char* to_string(BoardType type) {
  switch (type) {
    case BoardType::kChessboard:
      return "chessboard";
    case BoardType::kCharuco:
      return "charuco";
    case BoardType::kAprilGrid:
      return "aprilgrid";
  }
  return "unknown";
}

bool BoardOptions::is_valid(std::string* why) const {
  auto invalid = [why](const std::string& message) {
    if (why) *why = message;
    return false;
  };
  const bool grid = type == BoardType::kAprilGrid;
  const int min_count = grid ? 1 : 3;  // squares: two rows of inner corners, or they are collinear
  const std::string unit = grid ? " tags" : " squares";
  if (rows < min_count || rows > kMaxCount) {
    return invalid("rows: must be in [" + std::to_string(min_count) + ", " +
                   std::to_string(kMaxCount) + "]" + unit);
  }
  if (cols < min_count || cols > kMaxCount) {
    return invalid("cols: must be in [" + std::to_string(min_count) + ", " +
                   std::to_string(kMaxCount) + "]" + unit);
  }
  if (!(std::isfinite(square) && square > 0 && square <= Layout::kMaxLength / (4.0 * kMaxCount))) {
    return invalid("square: must be a positive finite length");
  }
  if (type == BoardType::kCharuco) {
    if (marker != 0 && !(marker > 0 && marker < square)) {
      return invalid("marker: must be in (0, square)");
    }
  } else if (marker != 0) {
    return invalid("marker: only for charuco boards");
  }
  if (grid && !(std::isfinite(spacing) && spacing > 0 && spacing <= 10)) {
    return invalid("spacing: must be in (0, 10] (gap over tag side)");
  }
  return true;
}

namespace {

std::string board_name(const BoardOptions& o) {
  std::ostringstream name;
  name << to_string(o.type) << " " << o.rows << "x" << o.cols << ", "
       << (o.type == BoardType::kAprilGrid ? "tag " : "square ") << o.square;
  if (o.type == BoardType::kCharuco && o.marker > 0) name << ", marker " << o.marker;
  if (o.type == BoardType::kAprilGrid) name << ", spacing " << o.spacing;
  return name.str();
}

}  // namespace

Layout calibration_board(const BoardOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument(why);
  Layout layout;
  layout.name = board_name(options);
  layout.mode = LayoutMode::kPoints;
  layout.candidates.resize(3, 0);
  const double s = options.square;
  if (options.type == BoardType::kAprilGrid) {
    const int rows = 2 * options.rows;
    const int cols = 2 * options.cols;
    const double pitch = (1 + options.spacing) * s;
    layout.description = "tag corners of a Kalibr aprilgrid, row-major from the lower left";
    layout.entries.resize(3, static_cast<Eigen::Index>(rows) * cols);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) {
        layout.entries.col(static_cast<Eigen::Index>(r) * cols + c)
            << (c / 2) * pitch + (c % 2) * s,
            (r / 2) * pitch + (r % 2) * s, 0.0;
      }
    }
  } else {
    const int rows = options.rows - 1;
    const int cols = options.cols - 1;
    const double offset = options.type == BoardType::kCharuco ? s : 0.0;
    layout.description = options.type == BoardType::kCharuco
                             ? "chessboard corners of an OpenCV ChArUco board, row-major"
                             : "inner corners of an OpenCV chessboard, row-major";
    layout.entries.resize(3, static_cast<Eigen::Index>(rows) * cols);
    for (int i = 0; i < rows; ++i) {
      for (int j = 0; j < cols; ++j) {
        layout.entries.col(static_cast<Eigen::Index>(i) * cols + j) << offset + j * s,
            offset + i * s, 0.0;
      }
    }
  }
  layout.weights = Eigen::VectorXd::Ones(layout.entries.cols());
  layout.validate();
  return layout;
}

}  // namespace vantage::io
