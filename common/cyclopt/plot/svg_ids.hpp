#pragma once
// Element ids of an SVG document made unique for inlining several documents in one HTML page.
// cairo names the glyphs, clip paths and surfaces of every SVG it writes the same way ("glyph0-1",
// "clip1", "surface1"); inline SVGs share the page's one id space, so without a per-figure prefix
// every later figure's <use xlink:href="#glyph0-1"> draws the first figure's letter.

#include <string>
#include <vector>

namespace cyclopt::plot {

// `svg` with every id="X" it defines renamed to id="PREFIX X" and every reference to such an id
// (href="#X", xlink:href="#X", url(#X)) renamed with it; references to ids it does not define are
// left alone. `prefix` must be a valid start of an XML name (e.g. "fig3-").
std::string svg_with_id_prefix(const std::string& svg, const std::string& prefix);

// The values of every id="..." attribute in `markup`, in document order (duplicates kept).
std::vector<std::string> svg_ids(const std::string& markup);

// Every id referenced by href="#X" / xlink:href="#X" / url(#X) in `markup`, in document order.
std::vector<std::string> svg_id_references(const std::string& markup);

}  // namespace cyclopt::plot
