#include "cyclopt/plot/svg_ids.hpp"

#include <set>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

// One occurrence of an id in markup: the id's characters are text[begin, end).
struct IdSpan {
  std::size_t begin, end;
};

// The id values following each of `openers` (e.g. ` id="`) up to `closer`.
std::vector<IdSpan> spans_after(const std::string& text, const std::vector<std::string>& openers, char closer) {
  std::vector<IdSpan> spans;
  for (const std::string& open : openers)
    for (std::size_t at = text.find(open); at != std::string::npos; at = text.find(open, at + 1)) {
      const std::size_t begin = at + open.size();
      const std::size_t end = text.find(closer, begin);
      if (end == std::string::npos) break;
      spans.push_back({begin, end});
    }
  return spans;
}

std::vector<IdSpan> definitions(const std::string& text) { return spans_after(text, {" id=\""}, '"'); }

std::vector<IdSpan> references(const std::string& text) {
  // SVG 2's plain href and SVG 1.1's xlink:href (what cairo writes).
  std::vector<IdSpan> spans = spans_after(text, {" href=\"#", ":href=\"#"}, '"');
  for (const IdSpan& s : spans_after(text, {"url(#"}, ')')) spans.push_back(s);
  return spans;
}

std::vector<std::string> values(const std::string& text, const std::vector<IdSpan>& spans) {
  std::vector<std::string> out;
  out.reserve(spans.size());
  for (const IdSpan& s : spans) out.push_back(text.substr(s.begin, s.end - s.begin));
  return out;
}

}  // namespace

std::vector<std::string> svg_ids(const std::string& markup) { return values(markup, definitions(markup)); }

std::vector<std::string> svg_id_references(const std::string& markup) { return values(markup, references(markup)); }

std::string svg_with_id_prefix(const std::string& svg, const std::string& prefix) {
  if (prefix.empty()) throw std::invalid_argument("svg_with_id_prefix: empty prefix");
  const std::vector<IdSpan> defined = definitions(svg);
  const std::vector<std::string> names = values(svg, defined);
  const std::set<std::string> own(names.begin(), names.end());
  std::vector<std::size_t> insert_at;
  for (const IdSpan& s : defined) insert_at.push_back(s.begin);
  for (const IdSpan& s : references(svg))
    if (own.count(svg.substr(s.begin, s.end - s.begin))) insert_at.push_back(s.begin);
  std::set<std::size_t> sorted(insert_at.begin(), insert_at.end());
  std::string out;
  out.reserve(svg.size() + sorted.size() * prefix.size());
  std::size_t copied = 0;
  for (std::size_t at : sorted) {
    out.append(svg, copied, at - copied);
    out += prefix;
    copied = at;
  }
  out.append(svg, copied, std::string::npos);
  return out;
}

}  // namespace cyclopt::plot
