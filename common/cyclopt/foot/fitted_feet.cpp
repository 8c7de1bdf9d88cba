#include "cyclopt/foot/fitted_feet.hpp"

#include "cyclopt/foot/convexity_constraints.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace cyclopt::foot {
namespace {

constexpr std::array<std::string_view, 18> kColumns{
    "table", "subject", "footwear", "side", "model", "trajectory", "section_9_2", "k_H", "k_M",
    "k_T",   "k_HM",    "k_MT",     "h_F",  "l_HA",  "l_HM",       "l_MT",        "gamma_F", "flag"};
constexpr std::size_t kFirstValueColumn = 7;  // k_H
constexpr std::size_t kFlagColumn = 17;

constexpr std::array<std::string_view, 12> kTables{"4.2", "B.1", "B.2", "B.3", "B.4", "B.5",
                                                   "B.6", "B.7", "B.8", "B.9", "B.10", "B.11"};
constexpr std::array<std::string_view, 9> kSubjects{"P1", "P2", "P3", "P4", "P5", "P6", "P7", "P8", "P9"};
constexpr std::array<std::string_view, 2> kFootwear{"barefoot", "shoes"};
constexpr std::array<std::string_view, 2> kSides{"left", "right"};
constexpr std::array<std::string_view, 2> kModels{"HM", "HMT"};
constexpr std::array<std::string_view, 3> kTrajectories{"SG", "AK", "IK"};

template <std::size_t N>
bool one_of(std::string_view v, const std::array<std::string_view, N>& set) {
  return std::find(set.begin(), set.end(), v) != set.end();
}

template <std::size_t N>
std::string joined(const std::array<std::string_view, N>& set) {
  std::string out;
  for (std::string_view s : set) out += (out.empty() ? "" : ", ") + std::string(s);
  return out;
}

std::vector<std::string_view> split(std::string_view line, char sep) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = line.find(sep, start);
    cells.push_back(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return cells;
    start = end + 1;
  }
}

// Seed units to SI: lengths printed in mm, gamma_F in degrees, k in rad^-1 as they are.
double to_si(ParameterKind kind, double table_value) {
  switch (kind) {
    case ParameterKind::angle: return table_value * std::numbers::pi / 180.0;
    case ParameterKind::regularisation: return table_value;
    case ParameterKind::length: break;
  }
  return table_value * 1e-3;
}

}  // namespace

std::string FittedFoot::name() const {
  return subject + "-" + footwear + "-" + side + "-" + std::string(to_string(spec.model)) + "-" + trajectory;
}

std::string FittedFoot::source() const {
  return "seed 001 Table " + table + " (" + subject + ", " + side + ", " +
         (footwear == "shoes" ? "with shoes" : "barefoot") + "; " + std::string(to_string(spec.model)) +
         " fitted to the " + trajectory + " trajectory)" + (section_9_2 ? "; compared in section 9.2" : "");
}

std::vector<std::string> admissibility_violations(const FootSpec& spec) {
  std::vector<std::string> reasons;
  const LinearInequalities li = convexity_constraints(spec.model);
  if (li.A.cols() == spec.parameters.size()) {
    const Eigen::VectorXd margin = li.A * spec.parameters.cast<double>() + li.b;
    for (Eigen::Index r = 0; r < margin.size(); ++r)
      if (margin[r] < 0.0) reasons.push_back("violates " + li.names[static_cast<std::size_t>(r)] + " (eq. 3.21/3.24)");
    if (spec.model == FootModel::hmt && toe_convexity_margin(spec.parameters) < 0.0)
      reasons.push_back("toe tip above the ankle line: polygon A-H-M-T not convex at A (toe_convexity_margin < 0)");
  }
  try {
    validate(spec);
  } catch (const SpecError& e) {
    reasons.push_back(e.what());
  }
  return reasons;
}

std::vector<FittedFoot> parse_fitted_feet(std::string_view tsv) {
  std::vector<FittedFoot> feet;
  bool header_seen = false;
  int line_number = 0;
  for (std::string_view line : split(tsv, '\n')) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line.front() == '#') continue;
    const auto where = [&](std::size_t column) {
      return "fitted feet line " + std::to_string(line_number) + ", column " +
             std::string(column < kColumns.size() ? kColumns[column] : "?") + ": ";
    };
    const std::vector<std::string_view> cells = split(line, '\t');
    if (cells.size() != kColumns.size())
      throw std::invalid_argument("fitted feet line " + std::to_string(line_number) + ": expected " +
                                  std::to_string(kColumns.size()) + " tab-separated columns, got " +
                                  std::to_string(cells.size()));
    if (!header_seen) {
      for (std::size_t c = 0; c < kColumns.size(); ++c)
        if (cells[c] != kColumns[c])
          throw std::invalid_argument(where(c) + "header must be '" + std::string(kColumns[c]) + "', got '" +
                                      std::string(cells[c]) + "'");
      header_seen = true;
      continue;
    }
    const auto require = [&](std::size_t column, const auto& set) {
      if (!one_of(cells[column], set))
        throw std::invalid_argument(where(column) + "'" + std::string(cells[column]) + "' is not one of " + joined(set));
      return std::string(cells[column]);
    };
    FittedFoot f;
    f.table = require(0, kTables);
    f.subject = require(1, kSubjects);
    f.footwear = require(2, kFootwear);
    f.side = require(3, kSides);
    const std::string model = require(4, kModels);
    f.trajectory = require(5, kTrajectories);
    if (cells[6] != "yes" && cells[6] != "no") throw std::invalid_argument(where(6) + "must be yes or no");
    f.section_9_2 = cells[6] == "yes";
    f.spec.model = foot_model_from_string(model);
    const auto layout = parameter_layout(f.spec.model);
    f.spec.parameters.resize(static_cast<Eigen::Index>(layout.size()));
    for (std::size_t c = kFirstValueColumn; c < kFlagColumn; ++c) {
      const std::string_view parameter = kColumns[c];
      const auto info = std::find_if(layout.begin(), layout.end(),
                                     [&](const ParameterInfo& p) { return p.name == parameter; });
      const std::string_view cell = cells[c];
      if (info == layout.end()) {
        if (cell != "-") throw std::invalid_argument(where(c) + "a " + model + " foot has no " + std::string(parameter) + "; write -");
        continue;
      }
      double value = 0.0;
      const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
      if (ec != std::errc() || end != cell.data() + cell.size() || !std::isfinite(value))
        throw std::invalid_argument(where(c) + "'" + std::string(cell) + "' is not a number");
      f.table_values.emplace(std::string(parameter), value);
      f.spec.parameters[info - layout.begin()] = to_si(info->kind, value);
    }
    if (cells[kFlagColumn] != "-") f.flag = std::string(cells[kFlagColumn]);
    f.spec.name = f.subject + " " + f.footwear + " " + f.side + " (" + model + ", " + f.trajectory + ")";
    feet.push_back(std::move(f));
  }
  if (!header_seen) throw std::invalid_argument("fitted feet: no header line");
  return feet;
}

std::span<const FittedFoot> fitted_feet() {
  static const std::vector<FittedFoot> catalogue = parse_fitted_feet(fitted_feet_tsv());
  return catalogue;
}

void validate(const FittedFootFilter& filter) {
  const auto check = [](const std::optional<std::string>& v, std::string_view field, const auto& set) {
    if (v && !one_of(*v, set))
      throw SpecError(std::string(field), "'" + *v + "' is not one of " + joined(set));
  };
  check(filter.subject, "subject", kSubjects);
  check(filter.footwear, "footwear", kFootwear);
  check(filter.side, "side", kSides);
  check(filter.model, "model", kModels);
  check(filter.trajectory, "trajectory", kTrajectories);
  check(filter.table, "table", kTables);
}

bool matches(const FittedFoot& foot, const FittedFootFilter& filter) {
  const auto same = [](const std::optional<std::string>& want, std::string_view have) { return !want || *want == have; };
  return same(filter.subject, foot.subject) && same(filter.footwear, foot.footwear) && same(filter.side, foot.side) &&
         same(filter.model, to_string(foot.spec.model)) && same(filter.trajectory, foot.trajectory) &&
         same(filter.table, foot.table) && (!filter.section_9_2_only || foot.section_9_2);
}

std::vector<const FittedFoot*> select_fitted_feet(const FittedFootFilter& filter) {
  validate(filter);
  std::vector<const FittedFoot*> out;
  for (const FittedFoot& f : fitted_feet())
    if (matches(f, filter)) out.push_back(&f);
  return out;
}

}  // namespace cyclopt::foot
