#pragma once
// The seed's catalogue of fitted feet (seed 001, Table 4.2 and Tables B.1-B.11): 216 HM and HMT
// feet of subjects P1-P9, barefoot and with shoes, left and right, each fitted to one of three
// ankle trajectories (SG, AK, IK). The data ship with the product as fitted_feet.tsv (embedded at
// build time); this file parses it into foot specifications with their provenance.

#include "cyclopt/foot/foot_spec.hpp"

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cyclopt::foot {

struct FittedFoot {
  std::string table;       // "4.2" or "B.1" ... "B.11"
  std::string subject;     // "P1" ... "P9"
  std::string footwear;    // "barefoot" | "shoes"
  std::string side;        // "left" | "right"
  std::string trajectory;  // "SG" | "AK" | "IK"
  bool section_9_2 = false;  // one of the 16 feet compared in section 9.2
  // The values as the seed prints them, by parameter name (k_H, k_HM, h_F, ...): k in rad^-1,
  // lengths in mm, gamma_F in degrees. Only the model's own parameters.
  std::map<std::string, double, std::less<>> table_values;
  FootSpec spec;           // SI units; model HM or HMT
  std::string flag;        // empty when the foot is admissible and convex, else the reason

  // Systematic name SUBJECT-FOOTWEAR-SIDE-MODEL-TRAJECTORY, e.g. "P3-shoes-left-HM-SG".
  std::string name() const;
  // "seed 001 Table B.9 (P2, left, with shoes; HMT fitted to the SG trajectory)".
  std::string source() const;
};

// Parses a catalogue in the format of fitted_feet.tsv ('#' comment lines, one header line, one
// foot per line). Throws std::invalid_argument naming the line and column of the first error.
std::vector<FittedFoot> parse_fitted_feet(std::string_view tsv);

// The shipped catalogue (fitted_feet.tsv as embedded at build time), parsed once.
std::span<const FittedFoot> fitted_feet();
std::string_view fitted_feet_tsv();

// Selects catalogue entries; an unset field matches everything.
struct FittedFootFilter {
  std::optional<std::string> subject = {}, footwear = {}, side = {}, model = {}, trajectory = {}, table = {};
  bool section_9_2_only = false;
};
// Throws SpecError naming the filter field and its admissible values if one is not a known value.
void validate(const FittedFootFilter& filter);
bool matches(const FittedFoot& foot, const FittedFootFilter& filter);
std::vector<const FittedFoot*> select_fitted_feet(const FittedFootFilter& filter);

// The reasons a foot violates the convexity conditions (3.21/3.24 and, for HMT, the toe condition
// toe_convexity_margin >= 0) or the parameter ranges of parameter_layout(); empty when it is fine.
std::vector<std::string> admissibility_violations(const FootSpec& spec);

}  // namespace cyclopt::foot
