// The shipped catalogue of fitted feet (fitted_feet.tsv) against the seed's own text: the rows of
// Table 4.2 and Tables B.1-B.11 are parsed out of ../shared/seeds/001_41d512de8a0c7ee3.txt
// (German; captions "Tabelle B.n: Parameter des Modells HMT, angepasst an die SG-Trajektorie (mit
// Schuhen).", columns named in the header line, numbers with decimal commas and "$a \cdot 10^{b}$").

#include "cyclopt/foot/fitted_feet.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot/generating_polygon.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace cyclopt::foot {
namespace {

constexpr const char* kSeedFile = "001_41d512de8a0c7ee3.txt";

// The seed lies in ../shared/seeds beside the checkout (one level higher for a git worktree);
// CYCLOPT_SEED_DIR overrides.
std::filesystem::path seed_path() {
  std::vector<std::filesystem::path> dirs;
  if (const char* env = std::getenv("CYCLOPT_SEED_DIR")) dirs.emplace_back(env);
  const std::filesystem::path source(CYCLOPT_SOURCE_DIR);
  dirs.push_back(source / ".." / "shared" / "seeds");
  dirs.push_back(source / ".." / ".." / "shared" / "seeds");
  for (const auto& d : dirs)
    if (std::filesystem::exists(d / kSeedFile)) return d / kSeedFile;
  return {};
}

struct SeedRow {
  std::string table, model, trajectory, footwear, subject, side;
  std::map<std::string, double> values;  // seed units
  std::string key() const { return table + " " + subject + " " + side; }
};

// "$5,2 \cdot 10^{-2}$" -> 5.2e-2, "88,5" -> 88.5 (decimal comma).
double seed_number(std::string cell) {
  static const std::regex power(R"(^\s*\$(\d+(?:,\d+)?) \\cdot 10\^\{(-?\d+)\}\$\s*$)");
  static const std::regex plain(R"(^\s*(\d+(?:,\d+)?)\s*$)");
  std::smatch m;
  std::string text;
  if (std::regex_match(cell, m, power))
    text = m[1].str() + "e" + m[2].str();
  else if (std::regex_match(cell, m, plain))
    text = m[1].str();
  else
    throw std::invalid_argument("not a seed number: '" + cell + "'");
  for (char& c : text)
    if (c == ',') c = '.';
  return std::stod(text);
}

// Column header of the seed ("k_{HM} in rad^{-1}", "ℓ_{HA} in mm", "γ_F in $^\circ$") to the
// parameter name of foot_parameters.hpp.
std::string parameter_of(const std::string& header) {
  static const std::vector<std::pair<std::regex, std::string>> names = {
      {std::regex(R"(^k_H in)"), "k_H"},          {std::regex(R"(^k_M in)"), "k_M"},
      {std::regex(R"(^k_T in)"), "k_T"},          {std::regex(R"(^k_\{HM\} in)"), "k_HM"},
      {std::regex(R"(^k_\{MT\} in)"), "k_MT"},    {std::regex(R"(^h_F in mm)"), "h_F"},
      {std::regex(R"(^ℓ_\{HA\} in mm)"), "l_HA"}, {std::regex(R"(^ℓ_\{HM\} in mm)"), "l_HM"},
      {std::regex(R"(^ℓ_\{MT\} in mm)"), "l_MT"}, {std::regex(R"(^γ_F in)"), "gamma_F"},
  };
  for (const auto& [re, name] : names)
    if (std::regex_search(header, re)) return name;
  throw std::invalid_argument("unknown seed column '" + header + "'");
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, '\t')) cells.push_back(cell);
  return cells;
}

struct SeedTables {
  std::vector<SeedRow> rows;
  std::set<std::string> tables;
};

SeedTables parse_seed(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  static const std::regex caption(
      R"(^Tabelle (4\.2|B\.\d+): Parameter des Modells (HMT|HM), angepasst an die (SG|AK|IK)-Trajektorie \((barfuß|mit Schuhen)\)\.$)");
  SeedTables out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (!std::regex_match(lines[i], m, caption)) continue;
    const std::string table = m[1], model = m[2], trajectory = m[3];
    const std::string footwear = m[4] == "barfuß" ? "barefoot" : "shoes";
    out.tables.insert(table);
    // Header: the first line after the caption whose second cell is "Fuß".
    std::size_t j = i + 1;
    while (j < lines.size() && (cells_of(lines[j]).size() < 2 || cells_of(lines[j])[1] != "Fuß")) ++j;
    if (j == lines.size()) throw std::runtime_error("Tabelle " + table + ": no header line");
    const std::vector<std::string> header = cells_of(lines[j]);
    std::string subject;
    for (++j; j < lines.size(); ++j) {
      const std::vector<std::string> c = cells_of(lines[j]);
      if (c.size() < 2) {
        if (lines[j].empty() && !subject.empty()) break;  // the blank line after the table
        continue;
      }
      if (c[1] != "links" && c[1] != "rechts") break;
      if (!c[0].empty()) subject = c[0];
      if (c.size() != header.size())
        throw std::runtime_error("Tabelle " + table + " " + subject + ": " + std::to_string(c.size()) + " cells");
      SeedRow r{table, model, trajectory, footwear, subject, c[1] == "links" ? "left" : "right", {}};
      for (std::size_t k = 2; k < c.size(); ++k) r.values[parameter_of(header[k])] = seed_number(c[k]);
      out.rows.push_back(std::move(r));
    }
  }
  return out;
}

std::string describe(const FittedFoot& f) { return f.table + " " + f.subject + " " + f.side; }

// Every difference between the seed's rows and a catalogue, one line each (empty: identical).
std::vector<std::string> differences(const std::vector<SeedRow>& seed, std::span<const FittedFoot> catalogue) {
  std::vector<std::string> out;
  std::map<std::string, const FittedFoot*> by_key;
  for (const FittedFoot& f : catalogue)
    if (!by_key.emplace(describe(f), &f).second) out.push_back("catalogue has " + describe(f) + " twice");
  std::set<std::string> seen;
  for (const SeedRow& r : seed) {
    seen.insert(r.key());
    const auto it = by_key.find(r.key());
    if (it == by_key.end()) {
      out.push_back("seed row missing from the catalogue: Tabelle " + r.key());
      continue;
    }
    const FittedFoot& f = *it->second;
    if (std::string(to_string(f.spec.model)) != r.model) out.push_back(r.key() + ": model " + r.model);
    if (f.trajectory != r.trajectory) out.push_back(r.key() + ": trajectory " + r.trajectory);
    if (f.footwear != r.footwear) out.push_back(r.key() + ": footwear " + r.footwear);
    for (const auto& [name, value] : r.values) {
      const auto v = f.table_values.find(name);
      if (v == f.table_values.end())
        out.push_back(r.key() + ": no " + name);
      else if (v->second != value)
        out.push_back(r.key() + ": " + name + " = " + std::to_string(v->second) + ", seed " + std::to_string(value));
    }
    if (f.table_values.size() != r.values.size()) out.push_back(r.key() + ": parameter count differs");
  }
  for (const auto& [key, f] : by_key)
    if (!seen.count(key)) out.push_back("catalogue row not in the seed: " + key);
  return out;
}

class SeedTranscription : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::filesystem::path p = seed_path();
    if (p.empty())
      GTEST_SKIP() << "seed 001 (" << kSeedFile << ") not found in ../shared/seeds or ../../shared/seeds of "
                   << CYCLOPT_SOURCE_DIR << " (set CYCLOPT_SEED_DIR): transcription not checked";
    seed_ = parse_seed(p);
  }
  SeedTables seed_;
};

TEST_F(SeedTranscription, EveryTableRowIsInTheCatalogueWithTheSeedsValues) {
  EXPECT_EQ(seed_.tables.size(), 12u) << "Table 4.2 and B.1-B.11";
  EXPECT_EQ(seed_.rows.size(), 216u) << "12 tables of 9 subjects x 2 feet";
  const std::vector<std::string> diff = differences(seed_.rows, fitted_feet());
  for (const std::string& d : diff) ADD_FAILURE() << d;
  EXPECT_EQ(fitted_feet().size(), seed_.rows.size());
  std::printf("seed 001: %zu tables, %zu fitted feet; catalogue %zu rows, %zu differences\n", seed_.tables.size(),
              seed_.rows.size(), fitted_feet().size(), diff.size());
}

// The comparison catches a single changed digit, a missing row and an extra row.
TEST_F(SeedTranscription, ComparisonDetectsChangedMissingAndExtraRows) {
  std::vector<FittedFoot> altered(fitted_feet().begin(), fitted_feet().end());
  altered[100].table_values.begin()->second *= 1.001;
  EXPECT_EQ(differences(seed_.rows, altered).size(), 1u);
  altered = {fitted_feet().begin() + 1, fitted_feet().end()};
  EXPECT_EQ(differences(seed_.rows, altered).size(), 1u);
  altered = {fitted_feet().begin(), fitted_feet().end()};
  altered.back().subject = "P0";
  EXPECT_EQ(differences(seed_.rows, altered).size(), 2u);  // P9 right missing, P0 right extra
}

// An independent convexity check: every turn of the generating polygon A-H-M(-T) has the same
// sense (cross products of consecutive edges >= 0 up to rounding).
bool polygon_is_convex(const FootSpec& s) {
  const std::vector<Eigen::Vector2d> v = generating_polygon(s.model, s.parameters);
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d e1 = v[(i + 1) % n] - v[i], e2 = v[(i + 2) % n] - v[(i + 1) % n];
    if (e1.x() * e2.y() - e1.y() * e2.x() < -1e-15) return false;
  }
  return true;
}

TEST(FittedFeet, EveryFootIsConvexAndAdmissibleOrFlaggedWithTheReason) {
  int flagged = 0;
  for (const FittedFoot& f : fitted_feet()) {
    const std::vector<std::string> reasons = admissibility_violations(f.spec);
    EXPECT_EQ(reasons.empty(), f.flag.empty()) << f.name() << ": flag '" << f.flag << "'"
                                               << (reasons.empty() ? "" : ", violates: " + reasons.front());
    if (reasons.empty()) {
      EXPECT_TRUE(polygon_is_convex(f.spec)) << f.name();
      EXPECT_NO_THROW(validate(f.spec)) << f.name();
    }
    flagged += !f.flag.empty();
  }
  std::printf("%zu fitted feet, %d flagged\n", fitted_feet().size(), flagged);
}

TEST(FittedFeet, AdmissibilityViolationsNameTheCondition) {
  FootSpec s = foot_preset("P2-shoes-left-HMT-SG").spec;
  s.parameters[hmt::gamma_F] = 1.57;
  s.parameters[hmt::l_MT] = 0.5;  // toe tip far above the ankle
  ASSERT_FALSE(polygon_is_convex(s));
  const std::vector<std::string> r = admissibility_violations(s);
  ASSERT_FALSE(r.empty());
  EXPECT_NE(r.front().find("toe"), std::string::npos) << r.front();
  s = foot_preset("P1-barefoot-left-HM-SG").spec;
  s.parameters[hm::l_HA] = 0.3;  // ankle behind the heel-to-ball segment's end
  EXPECT_NE(admissibility_violations(s).front().find("l_HM - l_HA >= 0"), std::string::npos);
}

TEST(FittedFeet, SixteenFeetOfSection92) {
  const std::vector<const FittedFoot*> feet = select_fitted_feet({.section_9_2_only = true});
  ASSERT_EQ(feet.size(), 16u);
  std::set<std::string> names;
  for (const FittedFoot* f : feet) {
    EXPECT_EQ(f->side, "left");
    EXPECT_EQ(f->trajectory, "SG");
    EXPECT_TRUE(f->subject == "P1" || f->subject == "P2" || f->subject == "P3" || f->subject == "P4");
    names.insert(f->name());
  }
  EXPECT_EQ(names.size(), 16u);
  for (const char* n : {"P1-barefoot-left-HM-SG", "P4-shoes-left-HM-SG", "P2-shoes-left-HMT-SG", "P3-barefoot-left-HMT-SG"})
    EXPECT_TRUE(names.count(n)) << n;
}

TEST(FittedFeet, EveryFootIsAPresetAndTheOldNamesAreAliases) {
  for (const FittedFoot& f : fitted_feet()) {
    const FootPreset& p = foot_preset(f.name());
    EXPECT_EQ(p.fitted, &f);
    EXPECT_EQ(p.spec.parameters, f.spec.parameters);
  }
  EXPECT_EQ(foot_presets().size(), fitted_feet().size() + 1);  // and the point foot
  EXPECT_EQ(&foot_preset("P2-shoes-left-HMT"), &foot_preset("P2-shoes-left-HMT-SG"));
  EXPECT_EQ(&foot_preset("P1-barefoot-left-HM"), &foot_preset("P1-barefoot-left-HM-SG"));
  EXPECT_EQ(&foot_preset("P1-shoes-left-HMT"), &foot_preset("P1-shoes-left-HMT-SG"));
  // Table B.9, P2 left: the SI values of the seed's best foot.
  const FootSpec& p2 = foot_preset("P2-shoes-left-HMT").spec;
  EXPECT_DOUBLE_EQ(p2.parameters[hmt::l_MT], 0.1124);
  EXPECT_DOUBLE_EQ(p2.parameters[hmt::gamma_F], 44.0 * std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(p2.parameters[hmt::k_MT], 0.1);
  EXPECT_THROW(foot_preset("P3-shoes-left-HM-XX"), SpecError);
}

TEST(FittedFeet, FiltersSelectAndRejectUnknownValues) {
  EXPECT_EQ(select_fitted_feet({}).size(), 216u);
  EXPECT_EQ(select_fitted_feet({.subject = "P3", .model = "HMT"}).size(), 12u);  // 2 footwear x 2 sides x 3 fits
  EXPECT_EQ(select_fitted_feet({.footwear = "shoes", .side = "left", .model = "HM", .trajectory = "SG"}).size(), 9u);
  EXPECT_EQ(select_fitted_feet({.table = "B.9"}).size(), 18u);
  try {
    select_fitted_feet({.model = "HMX"});
    ADD_FAILURE();
  } catch (const SpecError& e) {
    EXPECT_EQ(e.field(), "model");
    EXPECT_NE(std::string(e.what()).find("HM, HMT"), std::string::npos) << e.what();
  }
}

TEST(FittedFeet, ParserNamesLineAndColumnOfBadData) {
  const std::string header =
      "table\tsubject\tfootwear\tside\tmodel\ttrajectory\tsection_9_2\tk_H\tk_M\tk_T\tk_HM\tk_MT\th_F\tl_HA\tl_HM\tl_MT\t"
      "gamma_F\tflag\n";
  const std::string good = "4.2\tP1\tbarefoot\tleft\tHM\tSG\tyes\t1e-8\t1e-8\t-\t5.2e-2\t-\t88.5\t52.3\t226.6\t-\t-\t-\n";
  EXPECT_EQ(parse_fitted_feet("# c\n" + header + good).size(), 1u);
  const auto message = [&](const std::string& row) {
    try {
      parse_fitted_feet(header + row);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  std::string bad = good;
  bad.replace(bad.find("88.5"), 4, "88,5");
  EXPECT_NE(message(bad).find("line 2, column h_F"), std::string::npos) << message(bad);
  bad = good;
  bad.replace(bad.find("\t-\t88.5"), 2, "\t0.1");
  EXPECT_NE(message(bad).find("column k_MT: a HM foot has no k_MT"), std::string::npos) << message(bad);
  bad = good;
  bad.replace(bad.find("P1"), 2, "P10");
  EXPECT_NE(message(bad).find("column subject"), std::string::npos) << message(bad);
}

}  // namespace
}  // namespace cyclopt::foot
