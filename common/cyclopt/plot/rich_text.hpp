#pragma once
// A light markup for sub- and superscripts in figure and report text: "x_{H}^{-} - x_{H}^{+}",
// "kg/m^{2}", "f_{mech}". `_{...}` lowers its text, `^{...}` raises it (no nesting); everything else,
// Greek letters and other Unicode included, is plain text. Canvas::text draws the runs in PNG, SVG
// and PDF alike; rich_text_html (html_report.hpp) writes them as <sub>/<sup> for the HTML report.

#include <string>
#include <string_view>
#include <vector>

namespace cyclopt::plot {

struct TextRun {
  std::string text;
  int shift = 0;  // -1 subscript, 0 baseline, +1 superscript
};

// The runs of `markup` in order; an unclosed "_{" or "^{" reads as plain text.
std::vector<TextRun> rich_text_runs(std::string_view markup);

// The text as a terminal shows it, braces dropped ("x_{H}^{-}" -> "x_H^-", "f_{mech}" -> "f_mech").
std::string rich_text_plain(std::string_view markup);

}  // namespace cyclopt::plot
