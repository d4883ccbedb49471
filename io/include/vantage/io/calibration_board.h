#pragma once

/// The marker layout of a printed calibration target: the points a detector measures on it, in
/// the board frame (z = 0 plane, x along the columns, y along the rows, row-major order), as a
/// point-mode layout with weights 1.
///
///  - chessboard (OpenCV findChessboardCorners): rows x cols squares of side `square`; the
///    (rows-1) x (cols-1) inner corners, the first at the origin: (j s, i s, 0).
///  - charuco (OpenCV CharucoBoard): rows x cols squares with ArUco markers of side `marker`
///    inside the white ones; the (rows-1) x (cols-1) chessboard corners, origin at the board's
///    outer corner: ((j+1) s, (i+1) s, 0). The markers themselves are not listed.
///  - aprilgrid (Kalibr): rows x cols tags of side `square` with gaps spacing * square; the four
///    corners of every tag on the 2 rows x 2 cols grid of Kalibr's target, point (r, c) at
///    (floor(c/2) (1 + spacing) s + (c mod 2) s, floor(r/2) (1 + spacing) s + (r mod 2) s, 0).
///
/// A board is planar, so the affine pose from one image of it has the two-fold (Necker)
/// ambiguity of coplanar layouts: `vantage analyze` reports it among the swap pairs.

#include <string>

#include "vantage/analysis/layout.h"

namespace vantage::io {

/// The kind of calibration target.
enum class BoardType { kChessboard, kCharuco, kAprilGrid };

/// "chessboard" | "charuco" | "aprilgrid"; throws InvalidArgument naming `option` otherwise.
BoardType board_type_from_string(const std::string& name, const std::string& option);

/// "chessboard", "charuco" or "aprilgrid".
const char* to_string(BoardType type);

/// A calibration target. Lengths in the user's unit (the layout keeps it).
struct BoardOptions {
  static constexpr int kMaxCount = 1000;  ///< most rows or columns

  BoardType type = BoardType::kChessboard;
  int rows = 0;          ///< squares (chessboard, charuco: >= 3) or tags (aprilgrid: >= 1)
  int cols = 0;          ///< as rows, along x
  double square = 0;     ///< side of a square (chessboard, charuco) or of a tag (aprilgrid), > 0
  double marker = 0;     ///< charuco only: ArUco marker side, 0 < marker < square (0: not given)
  double spacing = 0.3;  ///< aprilgrid only: gap between tags over the tag side (Kalibr), > 0

  /// False with `why` naming the field ("rows", "square", ...) and the broken constraint.
  bool is_valid(std::string* why) const;
};

/// The board's layout (see the file comment), named e.g. "chessboard 7x10, square 0.025".
/// Throws InvalidArgument with the message of is_valid() for invalid options.
Layout calibration_board(const BoardOptions& options);

}  // namespace vantage::io
