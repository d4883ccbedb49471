#pragma once

// One figure being drawn: a cairo surface of the requested format with PLplot's extcairo driver
// drawing into it, plus the few things PLplot cannot do fast (a raster painted under the plot,
// filled markers). Private to vantage::plot.

#include <cairo.h>
#include <plstream.h>

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "quiet_stdio.h"
#include "vantage/plot/colormap.h"
#include "vantage/plot/figure.h"

namespace vantage::plot::internal {

/// PLplot colour-map-0 entries every figure uses (set by Canvas).
enum Pen : int {
  kPenBackground = 0,
  kPenInk = 1,          ///< text, axes
  kPenWorst = 2,        ///< kWorstViewpointColour
  kPenPaperLmi = 3,     ///< kPaperLmiColour
  kPenVector = 4,       ///< kDataVectorColour
  kPenThreshold = 5,    ///< kThresholdColour
  kPenGreatCircle = 6,  ///< light grey, thin lines over the value map
  kPenGrid = 7,         ///< pale grey grid and guides
  kPenBar = 8,          ///< a mid value colour for plain bars and curves
  kPenPlane = 9,        ///< translucent blue of a plane
  kPenLegendBack = 10,  ///< dark legend background
  kPenDirect = 11,      ///< a second series colour (blue)
  kPenNormal = 12,      ///< kNormalColour: marker normals
  kPenBody = 13,        ///< grey edges of a body mesh
  kPenBodyWorst = 14,   ///< kBodyWorstViewpointColour
  kPenCount
};

/// An RGBA image, row 0 at the top; alpha 0 marks undefined pixels.
struct Raster {
  int width = 0;
  int height = 0;
  std::vector<std::uint32_t> argb;  ///< premultiplied, cairo's ARGB32 layout
};

/// value -> value_colour((value - lo) / (hi - lo)); NaN -> transparent. values(row, col), row 0
/// at the top of the image.
Raster value_raster(const Eigen::MatrixXd& values, double lo, double hi);

class Canvas {
 public:
  enum class Shape { kCircle, kDiamond, kSquare };

  /// Starts a figure to be written to `path` in options.format at options.width x
  /// options.height. Throws RenderError when PLplot's cairo driver is missing or the file
  /// cannot be created.
  Canvas(const std::filesystem::path& path, const FigureOptions& options);
  ~Canvas() = default;
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  plstream& pls() { return *pls_; }
  int width() const { return width_; }
  int height() const { return height_; }

  /// Device coordinates (pixels, y down) of world point (x, y) in the current viewport/window.
  Eigen::Vector2d device(double x, double y);

  /// Paints the raster over the world rectangle [x0, x1] x [y0, y1] (smoothly interpolated).
  void paint_raster(const Raster& raster, double x0, double x1, double y0, double y1);

  /// Restricts all drawing (PLplot's too) to the unit disc of the current window, or to a
  /// polygon in world coordinates, until unclip().
  void clip_to_unit_disc();
  void clip_to_polygon(const std::vector<double>& x, const std::vector<double>& y);
  void unclip();

  /// A filled marker of radius_px pixels (points) at world (x, y) with a thin outline.
  void marker(double x, double y, double radius_px, Rgb fill, Shape shape = Shape::kCircle,
              Rgb outline = {20, 20, 20});
  /// The same at device position (pixels, y down).
  void marker_at(const Eigen::Vector2d& p, double radius_px, Rgb fill, Shape shape,
                 Rgb outline = {20, 20, 20});

  /// Text at world (x, y) shifted by (dx_px, dy_px) pixels (y down), on a rounded box of colour
  /// `box` (opacity box_alpha; 0 = no box). align: 0 left, 0.5 centre, 1 right. size_px is the
  /// font size. Uses the same sans-serif face as PLplot's cairo driver.
  void label(double x, double y, const std::string& text, double dx_px, double dy_px, double align,
             double size_px, Rgb colour, Rgb box = {255, 255, 255}, double box_alpha = 0.0);

  /// The advance width in pixels of `text` at font size size_px (the face of label()).
  double text_width(const std::string& text, double size_px);

  /// One row of a legend: a marker (shape, fill), a line (colour, width, dashed), a line with a
  /// marker on it, or nothing, and its text.
  struct LegendEntry {
    enum class Symbol { kNone, kMarker, kLine, kLineMarker };
    std::string text;
    Symbol symbol = Symbol::kNone;
    Rgb colour;
    Shape shape = Shape::kCircle;
    double line_width_px = 2.0;
    bool dashed = false;

    static LegendEntry text_only(std::string text) { return {std::move(text), Symbol::kNone, {}}; }
    static LegendEntry marker(std::string text, Rgb colour, Shape shape = Shape::kCircle) {
      return {std::move(text), Symbol::kMarker, colour, shape};
    }
    static LegendEntry line(std::string text, Rgb colour, double width_px, bool dashed = false) {
      return {std::move(text), Symbol::kLine, colour, Shape::kCircle, width_px, dashed};
    }
    static LegendEntry line_marker(std::string text, Rgb colour, double width_px, Shape shape,
                                   bool dashed = false) {
      return {std::move(text), Symbol::kLineMarker, colour, shape, width_px, dashed};
    }
  };
  /// A legend box whose top edge is at page fraction y (0..1, y up) and whose left edge
  /// (anchor 0) or right edge (anchor 1) is at page fraction x; rows of text size size_px on a
  /// white box with a grey border.
  void legend(double x, double y, const std::vector<LegendEntry>& entries, double size_px,
              double anchor = 0.0);
  /// The width and height (page fractions) of that legend box.
  Eigen::Vector2d legend_size(const std::vector<LegendEntry>& entries, double size_px);

  /// A filled polygon in world coordinates with opacity alpha in [0, 1].
  void fill_polygon(const std::vector<double>& x, const std::vector<double>& y, Rgb fill,
                    double alpha);

  /// Ends PLplot, encodes the surface and moves the file into place. Throws RenderError.
  void finish();

 private:
  std::unique_lock<std::mutex> lock_;  // PLplot and the stdio redirection are process-global
  QuietStdio quiet_;
  std::filesystem::path path_;
  FigureOptions options_;
  int width_ = 0;
  int height_ = 0;
  struct SurfaceDeleter {
    void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
  };
  struct ContextDeleter {
    void operator()(cairo_t* c) const { cairo_destroy(c); }
  };
  // Declared in this order so that PLplot ends before the context and the surface go.
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface_owner_;
  std::unique_ptr<cairo_t, ContextDeleter> cairo_owner_;
  cairo_surface_t* surface_ = nullptr;  // surface_owner_.get()
  cairo_t* cairo_ = nullptr;            // cairo_owner_.get()
  std::unique_ptr<plstream> pls_;
  std::unique_ptr<class OutputFile> file_;
};

}  // namespace vantage::plot::internal
