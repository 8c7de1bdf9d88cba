#include "cyclopt/plot/rich_text.hpp"

namespace cyclopt::plot {

std::vector<TextRun> rich_text_runs(std::string_view s) {
  std::vector<TextRun> runs;
  auto add = [&runs](std::string_view text, int shift) {
    if (text.empty()) return;
    if (!runs.empty() && runs.back().shift == shift) runs.back().text += text;
    else runs.push_back({std::string(text), shift});
  };
  std::size_t plain = 0;  // start of the pending baseline text
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    if ((s[i] != '_' && s[i] != '^') || s[i + 1] != '{') continue;
    const std::size_t close = s.find('}', i + 2);
    if (close == std::string_view::npos) break;
    add(s.substr(plain, i - plain), 0);
    add(s.substr(i + 2, close - i - 2), s[i] == '_' ? -1 : 1);
    plain = close + 1;
    i = close;
  }
  add(s.substr(plain), 0);
  return runs;
}

std::string rich_text_plain(std::string_view markup) {
  std::string out;
  for (const TextRun& r : rich_text_runs(markup)) out += (r.shift < 0 ? "_" : r.shift > 0 ? "^" : "") + r.text;
  return out;
}

}  // namespace cyclopt::plot
