#include "row_table.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace cyclopt::client {

namespace {

// Identifying columns first, then the rest in the (alphabetical) order of the JSON objects.
const std::vector<std::string> kLeadingColumns = {"id", "curve", "point", "parameter", "objective",
                                                  "constraint_violation", "state", "task", "at", "kind"};

// Columns in order of first appearance, with "values" members spliced in.
nlohmann::json flatten(const nlohmann::json& row) {
  nlohmann::json flat = nlohmann::json::object();
  for (const auto& [key, value] : row.items()) {
    if (key == "values" && value.is_object()) {
      for (const auto& [k, v] : value.items()) flat[k] = v;
    } else if (!value.is_structured()) {
      flat[key] = value;
    }
  }
  return flat;
}

std::string cell(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v.get<double>());
    return buf;
  }
  return v.dump();
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

void print_rows(std::ostream& out, const nlohmann::json& rows, RowFormat format) {
  if (format == RowFormat::json) {
    out << rows.dump(2) << "\n";
    return;
  }
  std::vector<std::string> columns;
  std::vector<nlohmann::json> flat;
  for (const auto& c : kLeadingColumns)
    for (const auto& row : rows)
      if (row.contains(c)) {
        columns.push_back(c);
        break;
      }
  for (const auto& row : rows) {
    flat.push_back(flatten(row));
    for (const auto& [key, value] : flat.back().items())
      if (std::find(columns.begin(), columns.end(), key) == columns.end()) columns.push_back(key);
  }
  std::vector<std::vector<std::string>> cells;
  for (const auto& f : flat) {
    std::vector<std::string> line;
    for (const auto& c : columns) line.push_back(f.contains(c) ? cell(f[c]) : "");
    cells.push_back(std::move(line));
  }
  if (format == RowFormat::csv) {
    for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << csv_cell(columns[i]);
    out << "\n";
    for (const auto& line : cells) {
      for (std::size_t i = 0; i < line.size(); ++i) out << (i ? "," : "") << csv_cell(line[i]);
      out << "\n";
    }
    return;
  }
  std::vector<std::size_t> width;
  for (const auto& c : columns) width.push_back(c.size());
  for (const auto& line : cells)
    for (std::size_t i = 0; i < line.size(); ++i) width[i] = std::max(width[i], std::min<std::size_t>(line[i].size(), 40));
  auto print_line = [&](const std::vector<std::string>& line) {
    for (std::size_t i = 0; i < line.size(); ++i) {
      std::string s = line[i].substr(0, 40);
      out << (i ? "  " : "") << s << std::string(width[i] - s.size(), ' ');
    }
    out << "\n";
  };
  print_line(columns);
  for (const auto& line : cells) print_line(line);
}

}  // namespace cyclopt::client
