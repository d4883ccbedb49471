#include "canvas.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "output_file.h"
#include "png_writer.h"
#include "vantage/analysis/common.h"

namespace vantage::plot::internal {
namespace {

std::mutex& plplot_mutex() {
  static std::mutex mutex;
  return mutex;
}

// The extcairo driver draws on a cairo context vantage owns; its absence means the Debian
// package plplot-driver-cairo is missing.
bool has_extcairo_driver() {
  constexpr int kMaxDevices = 128;
  const char* menus[kMaxDevices];
  const char* names[kMaxDevices];
  int count = kMaxDevices;
  const char** menu_list = menus;
  const char** name_list = names;
  plgDevs(&menu_list, &name_list, &count);
  for (int i = 0; i < count; ++i) {
    if (names[i] && std::strcmp(names[i], "extcairo") == 0) return true;
  }
  return false;
}

cairo_status_t write_to_file(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<OutputFile*>(closure)->write(data, length);
  return CAIRO_STATUS_SUCCESS;
}

void set_source(cairo_t* cr, Rgb c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

struct PenColour {
  Pen pen;
  Rgb rgb;
};

constexpr PenColour kPens[] = {
    {kPenBackground, {255, 255, 255}},
    {kPenInk, {25, 25, 25}},
    {kPenWorst, kWorstViewpointColour},
    {kPenPaperLmi, kPaperLmiColour},
    {kPenVector, kDataVectorColour},
    {kPenThreshold, kThresholdColour},
    {kPenGreatCircle, {205, 205, 205}},
    {kPenGrid, {200, 200, 200}},
    {kPenBar, {49, 104, 142}},
    {kPenPlane, {66, 146, 198}},
    {kPenLegendBack, {245, 245, 245}},
    {kPenDirect, {33, 113, 181}},
    {kPenNormal, kNormalColour},
    {kPenBody, {105, 105, 105}},
    {kPenBodyWorst, kBodyWorstViewpointColour},
};

// Entries of PLplot's continuous colour map 1 (the value map of colormap.h).
constexpr int kValueMapEntries = 256;

}  // namespace

Raster value_raster(const Eigen::MatrixXd& values, double lo, double hi) {
  Raster raster;
  raster.height = static_cast<int>(values.rows());
  raster.width = static_cast<int>(values.cols());
  raster.argb.assign(static_cast<std::size_t>(raster.width) * raster.height, 0u);
  for (int r = 0; r < raster.height; ++r) {
    for (int c = 0; c < raster.width; ++c) {
      const double v = values(r, c);
      if (std::isnan(v)) continue;
      const Rgb rgb = value_colour(v, lo, hi);
      raster.argb[static_cast<std::size_t>(r) * raster.width + c] =
          0xff000000u | (std::uint32_t{rgb.r} << 16) | (std::uint32_t{rgb.g} << 8) | rgb.b;
    }
  }
  return raster;
}

Canvas::Canvas(const std::filesystem::path& path, const FigureOptions& options)
    : lock_(plplot_mutex()), path_(path), options_(options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options." + why);
  if (!has_extcairo_driver()) {
    throw RenderError(
        "PLplot's cairo driver (extcairo) is not installed (Debian package "
        "plplot-driver-cairo)");
  }
  width_ = options.width;
  height_ = options.height;
  file_ = std::make_unique<OutputFile>(path);
  switch (options.format) {
    case Format::kPng:
      surface_ = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width_, height_);
      break;
    case Format::kSvg:
      surface_ = cairo_svg_surface_create_for_stream(write_to_file, file_.get(), width_, height_);
      break;
    case Format::kPdf:
      surface_ = cairo_pdf_surface_create_for_stream(write_to_file, file_.get(), width_, height_);
      break;
  }
  surface_owner_.reset(surface_);
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
    throw RenderError(std::string("cairo: ") +
                      cairo_status_to_string(cairo_surface_status(surface_)));
  }
  cairo_ = cairo_create(surface_);
  cairo_owner_.reset(cairo_);
  cairo_set_source_rgb(cairo_, 1.0, 1.0, 1.0);
  cairo_paint(cairo_);

  pls_ = std::make_unique<plstream>();
  pls_->sdev("extcairo");
  pls_->spage(0.0, 0.0, width_, height_, 0, 0);
  pls_->scmap0n(kPenCount);
  for (const PenColour& p : kPens) pls_->scol0(p.pen, p.rgb.r, p.rgb.g, p.rgb.b);
  pls_->init();
  pls_->cmd(PLESC_DEVINIT, cairo_);
  PLINT r[kValueMapEntries], g[kValueMapEntries], b[kValueMapEntries];
  for (int i = 0; i < kValueMapEntries; ++i) {
    const Rgb c = value_colour(i / double(kValueMapEntries - 1));
    r[i] = c.r;
    g[i] = c.g;
    b[i] = c.b;
  }
  pls_->scmap1(r, g, b, kValueMapEntries);
  pls_->scol0a(kPenPlane, 66, 146, 198, 0.22);
  pls_->adv(0);
  pls_->col0(kPenInk);
}

Eigen::Vector2d Canvas::device(double x, double y) {
  PLFLT vx0, vx1, vy0, vy1, wx0, wx1, wy0, wy1;
  pls_->gvpd(vx0, vx1, vy0, vy1);
  pls_->gvpw(wx0, wx1, wy0, wy1);
  const double u = vx0 + (x - wx0) / (wx1 - wx0) * (vx1 - vx0);
  const double v = vy0 + (y - wy0) / (wy1 - wy0) * (vy1 - vy0);
  return {u * width_, (1.0 - v) * height_};
}

void Canvas::clip_to_unit_disc() {
  const Eigen::Vector2d centre = device(0.0, 0.0);
  const Eigen::Vector2d right = device(1.0, 0.0);
  const Eigen::Vector2d top = device(0.0, 1.0);
  cairo_matrix_t plplot_matrix;
  cairo_get_matrix(cairo_, &plplot_matrix);
  cairo_identity_matrix(cairo_);
  cairo_new_path(cairo_);
  cairo_translate(cairo_, centre.x(), centre.y());
  cairo_scale(cairo_, right.x() - centre.x(), centre.y() - top.y());
  cairo_arc(cairo_, 0.0, 0.0, 1.0, 0.0, 2.0 * kPi);
  cairo_clip(cairo_);
  cairo_set_matrix(cairo_, &plplot_matrix);
}

void Canvas::clip_to_polygon(const std::vector<double>& x, const std::vector<double>& y) {
  cairo_matrix_t plplot_matrix;
  cairo_get_matrix(cairo_, &plplot_matrix);
  cairo_identity_matrix(cairo_);
  cairo_new_path(cairo_);
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    const Eigen::Vector2d p = device(x[i], y[i]);
    cairo_line_to(cairo_, p.x(), p.y());
  }
  cairo_close_path(cairo_);
  cairo_clip(cairo_);
  cairo_set_matrix(cairo_, &plplot_matrix);
}

void Canvas::unclip() { cairo_reset_clip(cairo_); }

void Canvas::paint_raster(const Raster& raster, double x0, double x1, double y0, double y1) {
  if (raster.width <= 0 || raster.height <= 0) return;
  cairo_surface_t* image = cairo_image_surface_create_for_data(
      reinterpret_cast<unsigned char*>(const_cast<std::uint32_t*>(raster.argb.data())),
      CAIRO_FORMAT_ARGB32, raster.width, raster.height, raster.width * 4);
  const Eigen::Vector2d top_left = device(x0, y1);
  const Eigen::Vector2d bottom_right = device(x1, y0);
  cairo_save(cairo_);
  cairo_identity_matrix(cairo_);  // PLplot's driver leaves its own (y-up) transform
  cairo_translate(cairo_, top_left.x(), top_left.y());
  cairo_scale(cairo_, (bottom_right.x() - top_left.x()) / raster.width,
              (bottom_right.y() - top_left.y()) / raster.height);
  cairo_set_source_surface(cairo_, image, 0.0, 0.0);
  cairo_pattern_set_filter(cairo_get_source(cairo_), CAIRO_FILTER_BILINEAR);
  cairo_pattern_set_extend(cairo_get_source(cairo_), CAIRO_EXTEND_PAD);
  cairo_rectangle(cairo_, 0.0, 0.0, raster.width, raster.height);
  cairo_fill(cairo_);
  cairo_restore(cairo_);
  cairo_surface_destroy(image);
}

void Canvas::marker(double x, double y, double radius_px, Rgb fill, Shape shape, Rgb outline) {
  marker_at(device(x, y), radius_px, fill, shape, outline);
}

void Canvas::marker_at(const Eigen::Vector2d& p, double radius_px, Rgb fill, Shape shape,
                       Rgb outline) {
  cairo_save(cairo_);
  cairo_identity_matrix(cairo_);  // PLplot's driver leaves its own (y-up) transform
  cairo_new_path(cairo_);
  switch (shape) {
    case Shape::kCircle:
      cairo_arc(cairo_, p.x(), p.y(), radius_px, 0.0, 2.0 * kPi);
      break;
    case Shape::kDiamond:
      cairo_move_to(cairo_, p.x(), p.y() - 1.3 * radius_px);
      cairo_line_to(cairo_, p.x() + 1.3 * radius_px, p.y());
      cairo_line_to(cairo_, p.x(), p.y() + 1.3 * radius_px);
      cairo_line_to(cairo_, p.x() - 1.3 * radius_px, p.y());
      cairo_close_path(cairo_);
      break;
    case Shape::kSquare:
      cairo_rectangle(cairo_, p.x() - radius_px, p.y() - radius_px, 2 * radius_px, 2 * radius_px);
      break;
  }
  set_source(cairo_, fill);
  cairo_fill_preserve(cairo_);
  set_source(cairo_, outline);
  cairo_set_line_width(cairo_, std::max(1.0, 0.18 * radius_px));
  cairo_stroke(cairo_);
  cairo_restore(cairo_);
}

void Canvas::label(double x, double y, const std::string& text, double dx_px, double dy_px,
                   double align, double size_px, Rgb colour, Rgb box, double box_alpha) {
  const Eigen::Vector2d p = device(x, y) + Eigen::Vector2d(dx_px, dy_px);
  cairo_save(cairo_);
  cairo_identity_matrix(cairo_);  // PLplot's driver leaves its own (y-up) transform
  cairo_select_font_face(cairo_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cairo_, size_px);
  cairo_text_extents_t extents;
  cairo_text_extents(cairo_, text.c_str(), &extents);
  cairo_font_extents_t font;
  cairo_font_extents(cairo_, &font);
  const double left = p.x() - align * extents.x_advance;
  const double baseline = p.y() + 0.5 * (font.ascent - font.descent);
  if (box_alpha > 0.0) {
    const double pad = 0.3 * size_px;
    const double x0 = left - pad;
    const double y0 = baseline - font.ascent - 0.5 * pad;
    const double w = extents.x_advance + 2 * pad;
    const double h = font.ascent + font.descent + pad;
    const double r = 0.3 * size_px;
    cairo_new_path(cairo_);
    cairo_arc(cairo_, x0 + w - r, y0 + r, r, -kPi / 2, 0);
    cairo_arc(cairo_, x0 + w - r, y0 + h - r, r, 0, kPi / 2);
    cairo_arc(cairo_, x0 + r, y0 + h - r, r, kPi / 2, kPi);
    cairo_arc(cairo_, x0 + r, y0 + r, r, kPi, 1.5 * kPi);
    cairo_close_path(cairo_);
    set_source(cairo_, box, box_alpha);
    cairo_fill(cairo_);
  }
  cairo_move_to(cairo_, left, baseline);
  set_source(cairo_, colour);
  cairo_show_text(cairo_, text.c_str());
  cairo_restore(cairo_);
}

double Canvas::text_width(const std::string& text, double size_px) {
  cairo_save(cairo_);
  cairo_identity_matrix(cairo_);
  cairo_select_font_face(cairo_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cairo_, size_px);
  cairo_text_extents_t extents;
  cairo_text_extents(cairo_, text.c_str(), &extents);
  cairo_restore(cairo_);
  return extents.x_advance;
}

namespace {

// The legend box's layout (pixels) for rows of text size size_px; the font must be selected.
struct LegendLayout {
  double pad = 0.0, symbol = 0.0, row = 0.0, width = 0.0, height = 0.0;
  cairo_font_extents_t font{};
};

LegendLayout legend_layout(cairo_t* cairo, const std::vector<Canvas::LegendEntry>& entries,
                           double size_px) {
  LegendLayout l;
  cairo_font_extents(cairo, &l.font);
  double text_width = 0.0;
  for (const Canvas::LegendEntry& e : entries) {
    cairo_text_extents_t extents;
    cairo_text_extents(cairo, e.text.c_str(), &extents);
    text_width = std::max(text_width, extents.x_advance);
  }
  l.pad = 0.7 * size_px;
  l.symbol = 2.4 * size_px;
  l.row = 1.6 * size_px;
  l.width = l.pad + l.symbol + 0.5 * l.pad + text_width + l.pad;
  l.height = 2 * l.pad + l.row * static_cast<double>(entries.size()) - (l.row - l.font.height);
  return l;
}

}  // namespace

Eigen::Vector2d Canvas::legend_size(const std::vector<LegendEntry>& entries, double size_px) {
  if (entries.empty()) return Eigen::Vector2d::Zero();
  cairo_save(cairo_);
  cairo_identity_matrix(cairo_);  // PLplot's driver leaves its own (y-up) transform
  cairo_select_font_face(cairo_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cairo_, size_px);
  const LegendLayout l = legend_layout(cairo_, entries, size_px);
  cairo_restore(cairo_);
  return {l.width / width_, l.height / height_};
}

void Canvas::legend(double x, double y, const std::vector<LegendEntry>& entries, double size_px,
                    double anchor) {
  if (entries.empty()) return;
  cairo_save(cairo_);
  cairo_identity_matrix(cairo_);  // PLplot's driver leaves its own (y-up) transform
  cairo_select_font_face(cairo_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cairo_, size_px);
  const LegendLayout l = legend_layout(cairo_, entries, size_px);
  const cairo_font_extents_t& font = l.font;
  const double pad = l.pad, symbol = l.symbol, row = l.row, w = l.width, h = l.height;
  const double x0 = x * width_ - anchor * w;
  const double y0 = (1.0 - y) * height_;
  cairo_rectangle(cairo_, x0, y0, w, h);
  set_source(cairo_, {255, 255, 255}, 0.94);
  cairo_fill_preserve(cairo_);
  set_source(cairo_, {150, 150, 150});
  cairo_set_line_width(cairo_, 1.0);
  cairo_stroke(cairo_);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const LegendEntry& e = entries[k];
    const double centre_y = y0 + pad + row * static_cast<double>(k) + 0.5 * font.height;
    const double centre_x = x0 + pad + 0.5 * symbol;
    if (e.symbol == LegendEntry::Symbol::kLine || e.symbol == LegendEntry::Symbol::kLineMarker) {
      cairo_save(cairo_);
      cairo_identity_matrix(cairo_);  // PLplot's driver leaves its own (y-up) transform
      if (e.dashed) {
        const double dash[] = {6.0, 4.0};
        cairo_set_dash(cairo_, dash, 2, 0.0);
      }
      // A light line on a light box gets a dark underlay so that it stays visible.
      const bool light = e.colour.r + e.colour.g + e.colour.b > 600;
      if (light) {
        set_source(cairo_, {90, 90, 90});
        cairo_set_line_width(cairo_, e.line_width_px + 3.0);
        cairo_move_to(cairo_, x0 + pad, centre_y);
        cairo_line_to(cairo_, x0 + pad + symbol, centre_y);
        cairo_stroke(cairo_);
      }
      set_source(cairo_, e.colour);
      cairo_set_line_width(cairo_, e.line_width_px);
      cairo_move_to(cairo_, x0 + pad, centre_y);
      cairo_line_to(cairo_, x0 + pad + symbol, centre_y);
      cairo_stroke(cairo_);
      cairo_restore(cairo_);
    }
    if (e.symbol == LegendEntry::Symbol::kMarker || e.symbol == LegendEntry::Symbol::kLineMarker) {
      marker_at({centre_x, centre_y}, 0.42 * size_px, e.colour, e.shape);
    }
    cairo_move_to(cairo_, x0 + pad + symbol + 0.5 * pad,
                  centre_y + 0.5 * (font.ascent - font.descent));
    set_source(cairo_, {25, 25, 25});
    cairo_show_text(cairo_, e.text.c_str());
  }
  cairo_restore(cairo_);
}

void Canvas::fill_polygon(const std::vector<double>& x, const std::vector<double>& y, Rgb fill,
                          double alpha) {
  if (x.size() < 3 || x.size() != y.size()) return;
  cairo_save(cairo_);
  cairo_identity_matrix(cairo_);  // PLplot's driver leaves its own (y-up) transform
  cairo_new_path(cairo_);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Eigen::Vector2d p = device(x[i], y[i]);
    if (i == 0) {
      cairo_move_to(cairo_, p.x(), p.y());
    } else {
      cairo_line_to(cairo_, p.x(), p.y());
    }
  }
  cairo_close_path(cairo_);
  set_source(cairo_, fill, alpha);
  cairo_fill(cairo_);
  cairo_restore(cairo_);
}

void Canvas::finish() {
  pls_.reset();
  const std::string aborts = quiet_.aborts();
  if (!aborts.empty()) throw RenderError("PLplot: " + aborts + " (" + path_.string() + ")");
  cairo_owner_.reset();
  cairo_ = nullptr;
  cairo_status_t status = CAIRO_STATUS_SUCCESS;
  if (options_.format == Format::kPng) {
    if (!write_png(surface_, *file_)) status = CAIRO_STATUS_WRITE_ERROR;
  } else {
    cairo_surface_finish(surface_);
    status = cairo_surface_status(surface_);
  }
  surface_owner_.reset();
  surface_ = nullptr;
  if (status != CAIRO_STATUS_SUCCESS) {
    throw RenderError("cairo: " + std::string(cairo_status_to_string(status)) + " (" +
                      path_.string() + ")");
  }
  file_->commit();
}

}  // namespace vantage::plot::internal
