#pragma once
// The report as a PDF for papers (`cyclopt report JOB --out FILE.pdf`), on cairo like every figure:
// title, sections, text, tables (failed rows tinted) and listings flowed over A4 pages; every
// figure that has its drawing (ReportFigure::draw) on a page of its own size as vector graphics,
// its caption below. SVG-only figures (the gait animations) are left out and named on the page.

#include "cyclopt/plot/html_report.hpp"

#include <string>

namespace cyclopt::plot {

// Throws std::runtime_error when the file cannot be written.
void write_pdf(const Report& report, const std::string& path);

}  // namespace cyclopt::plot
