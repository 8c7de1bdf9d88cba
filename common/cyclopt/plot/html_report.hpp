#pragma once
// One self-contained HTML page (no external files: figures are inline SVG) holding a job's
// provenance, specification, result tables and figures: what `cyclopt report JOB` writes.
//
// Text of headings, paragraphs, table cells and captions may carry the light markup of
// rich_text.hpp (x_{H}^{-}: sub- and superscripts), written as <sub>/<sup>.

#include "cyclopt/plot/line_chart.hpp"
#include "cyclopt/plot/scene.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace cyclopt::plot {

struct ReportTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  // Rows shown as failed (tinted red), e.g. a point whose solve did not converge; empty or one
  // flag per row.
  std::vector<bool> failed;
  bool scroll = false;  // a long table: in a box of its own height that scrolls, cells unwrapped
};

// A preformatted block under its own caption, e.g. the resolved spec as JSON (escaped).
struct ReportListing {
  std::string caption;
  std::string text;
};

struct ReportFigure {
  std::string caption;
  std::string svg;  // a complete <svg> document, e.g. from svg_of()
  // The drawing itself for the PDF (pdf_report.hpp) on a canvas of `size`; empty for a figure
  // that is SVG only (the animations), which the PDF leaves out.
  std::function<void(Canvas&)> draw;
  RenderOptions size;
};

struct ReportSection {
  std::string heading;
  std::string text;       // plain text paragraphs (escaped)
  std::vector<ReportTable> tables;
  std::vector<ReportListing> listings;
  std::vector<ReportFigure> figures;
  bool figure_grid = false;  // figures side by side in a grid (each at its own size), not one per row
  bool boxed = false;        // the section drawn as a framed box (the provenance)
};

struct Report {
  std::string title;
  std::string subtitle;  // e.g. job id, machine, date
  std::vector<ReportSection> sections;
};

// The chart or scene as SVG text (rendered through a temporary file).
std::string svg_of(const LineChart& chart, const RenderOptions& options = {});
std::string svg_of(const Scene& scene, const RenderOptions& options = {});

std::string html_escape(const std::string& s);
// `markup` (rich_text.hpp) escaped, its sub- and superscripts as <sub>/<sup>.
std::string rich_text_html(const std::string& markup);
// A table cell: `v` in the printf `format`, "-" when v is not finite (or, for JSON, not a number).
std::string report_number(double v, const char* format);
std::string report_number(const nlohmann::json& v, const char* format);
std::string to_html(const Report& report);
// The one script a report holds, when a figure is animated: animations run only while their
// figure is on screen (a sweep's report loops a gait per converged speed; a browser drawing all of
// them each frame kept a core busy). A server that forbids scripts allows this one by its hash.
const std::string& report_script();
// Writes to_html(report) to `path`; throws std::runtime_error if it cannot.
void write_html(const Report& report, const std::string& path);

}  // namespace cyclopt::plot
