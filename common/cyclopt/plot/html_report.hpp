#pragma once
// One self-contained HTML page (no external files: figures are inline SVG) holding a job's
// specification, result tables and figures: what `cyclopt report JOB` writes.

#include "cyclopt/plot/line_chart.hpp"
#include "cyclopt/plot/scene.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cyclopt::plot {

struct ReportTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

struct ReportFigure {
  std::string caption;
  std::string svg;  // a complete <svg> document, e.g. from svg_of()
};

struct ReportSection {
  std::string heading;
  std::string text;       // plain text paragraphs (escaped)
  std::string code;       // preformatted block, e.g. the job spec as JSON (escaped)
  std::vector<ReportTable> tables;
  std::vector<ReportFigure> figures;
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
// A table cell: `v` in the printf `format`, "-" when v is not finite (or, for JSON, not a number).
std::string report_number(double v, const char* format);
std::string report_number(const nlohmann::json& v, const char* format);
std::string to_html(const Report& report);
// Writes to_html(report) to `path`; throws std::runtime_error if it cannot.
void write_html(const Report& report, const std::string& path);

}  // namespace cyclopt::plot
