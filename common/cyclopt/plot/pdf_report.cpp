#include "cyclopt/plot/pdf_report.hpp"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

constexpr double kPageW = 595.28, kPageH = 841.89, kMargin = 48;  // A4 in points
constexpr Color kInk{0.1, 0.1, 0.1, 1}, kGrey{0.4, 0.4, 0.4, 1}, kFailed{0.99, 0.89, 0.89, 1};

// Flows text down A4 pages; figures get pages of their own size.
class PdfWriter {
 public:
  explicit PdfWriter(const std::string& path)
      : surface_(cairo_pdf_surface_create(path.c_str(), kPageW, kPageH)), cr_(cairo_create(surface_)) {
    if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error("cannot write report '" + path + "': " + cairo_status_to_string(cairo_surface_status(surface_)));
  }
  ~PdfWriter() {
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
  }
  PdfWriter(const PdfWriter&) = delete;
  PdfWriter& operator=(const PdfWriter&) = delete;

  // `text` wrapped at spaces to the page width.
  void paragraph(const std::string& text, double size, Color c = kInk, bool bold = false) {
    std::istringstream words(text);
    std::string line, word;
    while (words >> word) {
      const std::string longer = line.empty() ? word : line + " " + word;
      if (!line.empty() && canvas().text_width(longer, size, bold) > kPageW - 2 * kMargin) {
        put_line(line, size, c, bold);
        line = word;
      } else {
        line = longer;
      }
    }
    if (!line.empty()) put_line(line, size, c, bold);
    y_ += 0.4 * size;
  }

  // Columns as wide as their widest cell, the font shrunk (to 4.5 pt at least) until they fit.
  void table(const ReportTable& t) {
    double size = 7.5;
    std::vector<double> width;
    for (;; size -= 0.5) {
      width.assign(t.header.size(), 0.0);
      auto widen = [&](const std::vector<std::string>& row, bool bold) {
        for (std::size_t i = 0; i < row.size() && i < width.size(); ++i)
          width[i] = std::max(width[i], canvas().text_width(row[i], size, bold) + 6);
      };
      widen(t.header, true);
      for (const auto& row : t.rows) widen(row, false);
      double total = 0;
      for (double w : width) total += w;
      if (total <= kPageW - 2 * kMargin || size <= 4.5) break;
    }
    auto put_row = [&](const std::vector<std::string>& row, bool bold, bool failed) {
      need(1.5 * size);
      if (failed) canvas().rectangle({kMargin, y_ - size}, kPageW - 2 * kMargin, 1.4 * size, kFailed, kFailed, 0);
      double x = kMargin;
      for (std::size_t i = 0; i < row.size() && i < width.size(); ++i) {
        canvas().text({x, y_}, row[i], size, kInk, Align::left, 0, bold);
        x += width[i];
      }
      y_ += 1.4 * size;
    };
    put_row(t.header, true, false);
    for (std::size_t r = 0; r < t.rows.size(); ++r) put_row(t.rows[r], false, r < t.failed.size() && t.failed[r]);
    y_ += 6;
  }

  void listing(const ReportListing& l) {
    paragraph(l.caption, 9, kInk, true);
    std::istringstream lines(l.text);
    for (std::string line; std::getline(lines, line);) put_line(line, 6, kGrey, false);
    y_ += 6;
  }

  // A page of the figure's own size with the caption below the drawing.
  void figure(const ReportFigure& f) {
    end_page();
    const double caption = 34;
    cairo_pdf_surface_set_size(surface_, f.size.width, f.size.height + caption);
    Canvas drawing(cr_, f.size.width, f.size.height);
    f.draw(drawing);
    Canvas page(cr_, f.size.width, f.size.height + caption);
    page.text({20, f.size.height + 20}, f.caption, 10, kGrey);
    cairo_show_page(cr_);
    cairo_pdf_surface_set_size(surface_, kPageW, kPageH);
    y_ = kMargin;
    page_has_text_ = false;
  }

  void end_page() {
    if (page_has_text_) cairo_show_page(cr_);
    page_has_text_ = false;
    y_ = kMargin;
  }

  void finish() {
    end_page();
    cairo_surface_finish(surface_);
    if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error(std::string("cannot write the PDF report: ") + cairo_status_to_string(cairo_surface_status(surface_)));
  }

 private:
  Canvas& canvas() {
    if (!canvas_) canvas_.emplace(cr_, kPageW, kPageH);
    return *canvas_;
  }
  void need(double height) {
    if (y_ + height > kPageH - kMargin) end_page();
  }
  void put_line(const std::string& line, double size, Color c, bool bold) {
    need(1.3 * size);
    y_ += size;
    canvas().text({kMargin, y_}, line, size, c, Align::left, 0, bold);
    y_ += 0.3 * size;
    page_has_text_ = true;
  }

  cairo_surface_t* surface_;
  cairo_t* cr_;
  std::optional<Canvas> canvas_;
  double y_ = kMargin;
  bool page_has_text_ = false;
};

}  // namespace

void write_pdf(const Report& report, const std::string& path) {
  PdfWriter pdf(path);
  pdf.paragraph(report.title, 16, kInk, true);
  if (!report.subtitle.empty()) pdf.paragraph(report.subtitle, 9, kGrey);
  for (const ReportSection& s : report.sections) {
    pdf.paragraph(s.heading, 12, kInk, true);
    if (!s.text.empty()) pdf.paragraph(s.text, 8.5);
    for (const ReportTable& t : s.tables) pdf.table(t);
    for (const ReportListing& l : s.listings) pdf.listing(l);
    int svg_only = 0;
    for (const ReportFigure& f : s.figures) svg_only += !f.draw;
    if (svg_only) pdf.paragraph(std::to_string(svg_only) + " animated figure(s): in the HTML report only.", 8.5, kGrey);
  }
  for (const ReportSection& s : report.sections)
    for (const ReportFigure& f : s.figures)
      if (f.draw) pdf.figure(f);
  pdf.finish();
}

}  // namespace cyclopt::plot
