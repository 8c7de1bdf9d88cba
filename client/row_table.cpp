#include "row_table.hpp"

#include "point_table.hpp"

#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/records/sweep_records.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

namespace cyclopt::client {

namespace {

// Identifying columns first, then the rest in the (alphabetical) order of the JSON objects.
const std::vector<std::string> kLeadingColumns = {"id", "curve", "point", "parameter", "objective",
                                                  "constraint_violation", "state", "task", "at", "kind"};

// Columns in order of first appearance, with "values" members spliced in, and the scalars of
// their objects as "member.key" (gait.step_length, solver.iterations, ...).
nlohmann::ordered_json flatten(const nlohmann::json& row) {
  nlohmann::ordered_json flat = nlohmann::ordered_json::object();
  for (const auto& [key, value] : row.items()) {
    if (key == "values" && value.is_object()) {
      for (const auto& [k, v] : value.items()) {
        if (!v.is_object()) {
          if (!v.is_array()) flat[k] = v;
          continue;
        }
        for (const auto& [sub, x] : v.items())
          if (!x.is_structured()) flat[k + "." + sub] = x;
      }
    } else if (!value.is_structured()) {
      flat[key] = value;
    }
  }
  return flat;
}

// Timestamps (submitted_at, finished_at, at, solved_at, ...: Unix seconds) as ISO 8601 UTC.
bool is_time_column(const std::string& column) {
  return column == "at" || (column.size() > 3 && column.compare(column.size() - 3, 3, "_at") == 0);
}

std::string iso_time(double unix_seconds) {
  const std::time_t t = static_cast<std::time_t>(std::floor(unix_seconds));
  std::tm utc{};
  gmtime_r(&t, &utc);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return b;
}

// Fixed decimals per column of the point tables (point_table.hpp), so a column's numbers line up
// and compare digit by digit; other columns in `fallback`.
const char* summary_format(const std::string& column, const char* fallback) {
  static const std::vector<std::pair<std::string, const char*>> formats = {
      {"speed_m_s", "%.3f"},     {"f_mech", "%.6f"},        {"objective", "%.6f"},    {"step_length_m", "%.4f"},
      {"period_s", "%.4f"},      {"cadence_1_min", "%.1f"}, {"floquet", "%.4f"},      {"impact_loss_J", "%.3f"},
      {"rms_mm", "%.2f"},        {"max_mm", "%.2f"},        {"rho_kg_m2", "%.1f"},    {"m_F_kg", "%.4f"},
      {"mean_f_mech", "%.6f"},   {"low_mean_f_mech", "%.6f"}, {"value", "%.6g"},      {"relative", "%.4f"},
      {"kkt_df_dp", "%.4e"},     {"predicted_minus", "%.4e"}, {"predicted_plus", "%.4e"},
      {"continuation_minus", "%.4e"}, {"continuation_plus", "%.4e"}, {"sweep_s", "%.1f"}};
  for (const auto& [name, format] : formats)
    if (column == name) return format;
  if (column.size() > 2 && column.compare(column.size() - 2, 2, "_%") == 0) return "%.1f";  // savings in percent
  return fallback;
}

// `summary`: a point table's cell (summary_format), else every float in float_format.
std::string cell(const std::string& column, const nlohmann::ordered_json& v, const char* float_format, bool summary) {
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number() && is_time_column(column)) return iso_time(v.get<double>());
  if (v.is_number()) {
    const char* format = summary ? summary_format(column, float_format) : float_format;
    if (v.is_number_integer() && format == float_format) return v.dump();  // counts, ids
    char buf[32];
    std::snprintf(buf, sizeof buf, format, v.get<double>());
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

struct Grid {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> cells;
};

Grid grid_of(const std::vector<nlohmann::ordered_json>& rows, const std::vector<std::string>& leading,
             const char* float_format, bool summary = false) {
  Grid g;
  for (const auto& c : leading)
    for (const auto& row : rows)
      if (row.contains(c)) {
        g.columns.push_back(c);
        break;
      }
  for (const auto& row : rows)
    for (const auto& [key, value] : row.items())
      if (std::find(g.columns.begin(), g.columns.end(), key) == g.columns.end()) g.columns.push_back(key);
  for (const auto& row : rows) {
    std::vector<std::string> line;
    for (const auto& c : g.columns) line.push_back(row.contains(c) ? cell(c, row[c], float_format, summary) : "");
    g.cells.push_back(std::move(line));
  }
  return g;
}

void print_aligned(std::ostream& out, const Grid& g, std::size_t max_width) {
  std::vector<std::size_t> width;
  for (const auto& c : g.columns) width.push_back(std::min(c.size(), max_width));
  for (const auto& line : g.cells)
    for (std::size_t i = 0; i < line.size(); ++i) width[i] = std::max(width[i], std::min(line[i].size(), max_width));
  auto print_line = [&](const std::vector<std::string>& line) {
    std::string text;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const std::string s = line[i].substr(0, max_width);
      text += (i ? "  " : "") + s + std::string(width[i] - s.size(), ' ');
    }
    out << text.substr(0, text.find_last_not_of(' ') + 1) << "\n";
  };
  print_line(g.columns);
  for (const auto& line : g.cells) print_line(line);
}

// A walker gait row (values.gait a records::GaitRecord): its parameter is the speed.
bool is_gait_row(const nlohmann::json& row) {
  const nlohmann::json values = row.value("values", nlohmann::json());
  if (!values.is_object() || !values.contains("gait")) return false;
  try {
    values["gait"].get<records::GaitRecord>();
    return true;
  } catch (const records::RecordError&) {
    return false;
  }
}

// A sweep's curve 0 holds its best point per speed (records::SweepBestRecord beside the gait).
bool is_sweep_best_row(const nlohmann::json& row) {
  if (row.value("curve", -1) != 0) return false;
  try {
    row.at("values").get<records::SweepBestRecord>();
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

void print_rows(std::ostream& out, const nlohmann::json& rows, RowFormat format) {
  if (format == RowFormat::json) {
    out << rows.dump(2) << "\n";
    return;
  }
  if (format == RowFormat::table && !rows.empty()) {
    std::vector<nlohmann::ordered_json> points;
    for (const auto& row : rows)
      if (const auto s = point_summary(row)) points.push_back(*s);
    if (points.size() == rows.size()) {
      print_aligned(out, grid_of(points, {}, "%.5g", true), 40);
      if (std::any_of(rows.begin(), rows.end(), is_sweep_best_row))
        out << "curve 0: the best point per speed; curves 1, 2, ...: the solution curves the sweep followed "
               "(cyclopt report draws them all); --wide: every stored value\n";
      return;
    }
  }
  std::vector<nlohmann::ordered_json> flat;
  for (const auto& row : rows) flat.push_back(flatten(row));
  Grid g = grid_of(flat, kLeadingColumns, "%.10g");
  // A walker gait's parameter is its speed: say so where people read it.
  if (format == RowFormat::wide && std::all_of(rows.begin(), rows.end(), is_gait_row))
    std::replace(g.columns.begin(), g.columns.end(), std::string("parameter"), std::string("speed [m/s]"));
  if (format == RowFormat::csv) {
    for (std::size_t i = 0; i < g.columns.size(); ++i) out << (i ? "," : "") << csv_cell(g.columns[i]);
    out << "\n";
    for (const auto& line : g.cells) {
      for (std::size_t i = 0; i < line.size(); ++i) out << (i ? "," : "") << csv_cell(line[i]);
      out << "\n";
    }
    return;
  }
  print_aligned(out, g, format == RowFormat::wide ? 80 : 40);
}

}  // namespace cyclopt::client
