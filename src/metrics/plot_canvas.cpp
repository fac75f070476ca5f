#include "metrics/plot_canvas.hpp"

#include "metrics/output_file.hpp"

namespace imasim::metrics {

namespace {

constexpr const char* kFont = "DejaVu Sans";
constexpr int kCairoMaxSide = 16384;  // pixels: cairo's own limit is 32767

cairo_status_t append_to_string(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

void select_font(cairo_t* cr, const TextStyle& style) {
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL,
                         style.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, style.size);
}

}  // namespace

PlotCanvas::PlotCanvas(int width, int height, std::string png_path)
    : width_(width), height_(height), path_(std::move(png_path)) {
  if (width < 1 || height < 1 || width > kCairoMaxSide || height > kCairoMaxSide)
    throw OutputError("cannot draw " + path_ + ": " + std::to_string(width) + " x " +
                      std::to_string(height) + " pixels is outside 1 to " +
                      std::to_string(kCairoMaxSide));
  surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  cr_ = cairo_create(surface_);
  check("creating the picture");
  cairo_set_source_rgb(cr_, 1, 1, 1);
  cairo_paint(cr_);
}

PlotCanvas::~PlotCanvas() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

cairo_status_t PlotCanvas::status() const {
  const cairo_status_t surface = cairo_surface_status(surface_);
  return surface != CAIRO_STATUS_SUCCESS ? surface : cairo_status(cr_);
}

void PlotCanvas::require(cairo_status_t status, const char* doing) const {
  if (status != CAIRO_STATUS_SUCCESS)
    throw OutputError("cannot draw " + path_ + ": cairo failed " + doing + ": " +
                      cairo_status_to_string(status));
}

void PlotCanvas::set_colour(const Rgb& rgb, double alpha) {
  cairo_set_source_rgba(cr_, rgb[0], rgb[1], rgb[2], alpha);
}

double PlotCanvas::text_width(const std::string& utf8, const TextStyle& style) {
  select_font(cr_, style);
  cairo_text_extents_t e;
  cairo_text_extents(cr_, utf8.c_str(), &e);
  return e.x_advance;
}

void PlotCanvas::text(const std::string& utf8, double x, double y, HAlign h, VAlign v,
                      const TextStyle& style) {
  select_font(cr_, style);
  cairo_text_extents_t e;
  cairo_text_extents(cr_, utf8.c_str(), &e);
  cairo_font_extents_t f;
  cairo_font_extents(cr_, &f);
  const double dx = h == HAlign::left ? 0 : h == HAlign::centre ? -e.x_advance / 2 : -e.x_advance;
  // Placed by the font's ascent, not the text's ink, so labels of one row line up.
  const double dy = v == VAlign::baseline ? 0 : v == VAlign::top ? f.ascent : f.ascent / 2 - 1;
  cairo_save(cr_);
  cairo_translate(cr_, x, y);
  cairo_rotate(cr_, -style.angle);
  set_colour(style.rgb);
  cairo_move_to(cr_, dx, dy);
  cairo_show_text(cr_, utf8.c_str());
  cairo_restore(cr_);
}

void PlotCanvas::save(std::span<const std::string> inputs) {
  check("drawing");
  cairo_surface_flush(surface_);
  std::string png;
  const cairo_status_t status = cairo_surface_write_to_png_stream(surface_, append_to_string, &png);
  if (status != CAIRO_STATUS_SUCCESS)
    throw OutputError("cannot encode " + path_ + " as PNG: " + cairo_status_to_string(status));
  OutputFile file(path_, "the picture", inputs);
  file.write(png);
  file.close();
}

}  // namespace imasim::metrics
