#include "cyclopt/plot/html_report.hpp"

#include "cyclopt/plot/rich_text.hpp"
#include "cyclopt/plot/svg_ids.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace cyclopt::plot {
namespace {

template <class Drawing>
std::string svg_via_file(const Drawing& d, const RenderOptions& options) {
  static std::atomic<int> counter{0};
  const std::filesystem::path tmp = std::filesystem::temp_directory_path() /
                                    ("cyclopt_fig_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".svg");
  render(d, tmp.string(), options);
  std::ifstream in(tmp);
  std::stringstream ss;
  ss << in.rdbuf();
  std::filesystem::remove(tmp);
  std::string svg = ss.str();
  // Drop the XML declaration so the document can be inlined in HTML.
  if (svg.rfind("<?xml", 0) == 0) svg.erase(0, svg.find("?>") + 2);
  return svg;
}

constexpr const char* kStyle = R"(body{font-family:DejaVu Sans,Helvetica,Arial,sans-serif;margin:2em auto;max-width:980px;color:#1a1a1a}
h1{font-size:1.6em;margin-bottom:0}.sub{color:#666;margin-top:.2em}h2{font-size:1.25em;border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:1.6em}
.wide{overflow-x:auto}table{border-collapse:collapse;margin:.8em 0;font-size:.9em}th,td{border:1px solid #ccc;padding:.25em .6em;text-align:right}
th{background:#f2f2f2}td:first-child,th:first-child{text-align:left}pre{background:#f7f7f7;padding:.8em;overflow-x:auto;font-size:.85em}
figure{margin:1em 0}figcaption{color:#444;font-size:.9em}svg{max-width:100%;height:auto}
tr.failed td{background:#fde2e2;color:#8b0000;font-weight:bold}
.grid{display:flex;flex-wrap:wrap;gap:1em;align-items:flex-start}.grid figure{margin:0;max-width:316px}
.box{border:2px solid #5b7fa6;background:#f4f8fc;padding:.2em 1em 1em;margin-top:1.2em}.box h2{border:none;margin-top:.6em}
details summary{cursor:pointer;color:#333;margin-top:.6em}.box table{font-size:.85em}.box td{text-align:left}
.listings{display:flex;gap:1em;align-items:flex-start}.listings details{flex:1;min-width:0}.listings pre{max-height:30em}
.scroll{max-height:36em;overflow:auto;border:1px solid #ddd}.scroll table{margin:0}.scroll td{white-space:nowrap}
.scroll thead th{position:sticky;top:0})";

}  // namespace

std::string svg_of(const LineChart& chart, const RenderOptions& options) { return svg_via_file(chart, options); }
std::string svg_of(const Scene& scene, const RenderOptions& options) { return svg_via_file(scene, options); }

std::string html_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string rich_text_html(const std::string& markup) {
  std::string out;
  for (const TextRun& r : rich_text_runs(markup)) {
    const std::string text = html_escape(r.text);
    out += r.shift < 0 ? "<sub>" + text + "</sub>" : r.shift > 0 ? "<sup>" + text + "</sup>" : text;
  }
  return out;
}

std::string report_number(double v, const char* format) {
  if (!std::isfinite(v)) return "-";
  char b[48];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

std::string report_number(const nlohmann::json& v, const char* format) {
  return report_number(v.is_number() ? v.get<double>() : std::nan(""), format);
}

const std::string& report_script() {
  static const std::string script =
      "(function(){var svgs=[].filter.call(document.querySelectorAll(\"figure>svg\"),function(s){"
      "return s.querySelector(\"animate\")});if(!svgs.length||!(\"IntersectionObserver\" in window))return;"
      "var seen=new IntersectionObserver(function(entries){entries.forEach(function(e){"
      "if(e.isIntersecting)e.target.unpauseAnimations();else e.target.pauseAnimations();});});"
      "svgs.forEach(function(s){s.pauseAnimations();seen.observe(s);});})();";
  return script;
}

std::string to_html(const Report& report) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << html_escape(report.title)
    << "</title><style>" << kStyle << "</style></head><body>\n";
  h << "<h1>" << html_escape(report.title) << "</h1>\n";
  int figure_count = 0;  // the page-wide figure number prefixes each inline SVG's ids (svg_ids.hpp)
  if (!report.subtitle.empty()) h << "<p class=\"sub\">" << rich_text_html(report.subtitle) << "</p>\n";
  for (const ReportSection& s : report.sections) {
    h << (s.boxed ? "<section class=\"box\">" : "<section>") << "<h2>" << rich_text_html(s.heading) << "</h2>\n";
    if (!s.text.empty()) h << "<p>" << rich_text_html(s.text) << "</p>\n";
    for (const ReportTable& t : s.tables) {
      h << (t.scroll ? "<div class=\"scroll\"><table><thead><tr>" : "<div class=\"wide\"><table><thead><tr>");
      for (const std::string& c : t.header) h << "<th>" << rich_text_html(c) << "</th>";
      h << "</tr></thead><tbody>\n";
      for (std::size_t r = 0; r < t.rows.size(); ++r) {
        h << (r < t.failed.size() && t.failed[r] ? "<tr class=\"failed\">" : "<tr>");
        for (const std::string& c : t.rows[r]) h << "<td>" << rich_text_html(c) << "</td>";
        h << "</tr>\n";
      }
      h << "</tbody></table></div>\n";
    }
    if (!s.listings.empty()) h << "<div class=\"listings\">\n";
    for (const ReportListing& l : s.listings)
      h << "<details open><summary>" << rich_text_html(l.caption) << "</summary><pre>" << html_escape(l.text)
        << "</pre></details>\n";
    if (!s.listings.empty()) h << "</div>\n";
    if (s.figure_grid) h << "<div class=\"grid\">\n";
    for (const ReportFigure& f : s.figures)
      h << "<figure>" << svg_with_id_prefix(f.svg, "fig" + std::to_string(++figure_count) + "-") << "<figcaption>"
        << rich_text_html(f.caption) << "</figcaption></figure>\n";
    if (s.figure_grid) h << "</div>\n";
    h << "</section>\n";
  }
  const bool animated = std::any_of(report.sections.begin(), report.sections.end(), [](const ReportSection& s) {
    return std::any_of(s.figures.begin(), s.figures.end(), [](const ReportFigure& f) { return f.svg.find("<animate") != std::string::npos; });
  });
  if (animated) h << "<script>" << report_script() << "</script>\n";
  h << "</body></html>\n";
  return h.str();
}

void write_html(const Report& report, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write report '" + path + "'");
  out << to_html(report);
  if (!out) throw std::runtime_error("cannot write report '" + path + "'");
}

}  // namespace cyclopt::plot
