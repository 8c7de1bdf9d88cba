// cyclopt-foot: describe a foot geometry (seed 001, ch. 3 and appendix E) from a preset or a
// JSON spec: parameters, admissible angles, mass properties and the rolling kinematics.
#include "cyclopt/cli/closest_name.hpp"
#include "cyclopt/cli/exit_codes.hpp"
#include "cyclopt/cli/usage_text.hpp"
#include "cyclopt/cli/version.hpp"
#include "cyclopt/foot/fitted_feet.hpp"
#include "cyclopt/foot/foot_parameters.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/io/foot_report.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/plot/foot_figures.hpp"
#include "foot_fit_commands.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <utility>

namespace {

constexpr const char* kUsage = R"(usage: cyclopt-foot [--preset NAME | --foot FILE.json] [--density RHO]
                    [--samples N] [--json]
       cyclopt-foot --list-presets [--subject P1..P9]
                    [--footwear barefoot|shoes] [--side left|right]
                    [--model HM|HMT] [--trajectory SG|AK|IK]
                    [--table 4.2|B.1..B.11] [--section-9-2]
       cyclopt-foot fit [options] TRIAL...
       (fit HM / HMT to marker files; fit --help)
       cyclopt-foot synth [options] --out DIR
       (synthetic marker trials; synth --help)

Describes a foot geometry of the walker: polygon transitions, admissible foot
angles, mass properties from an area density (appendix E of the seed) and the
ankle / contact-point kinematics while the foot rolls. Units are SI (m, rad, kg,
kg/m^2).

  --preset NAME   point or one of the seed's 216 fitted feet,
                  SUBJECT-FOOTWEAR-SIDE-MODEL-TRAJECTORY (e.g.
                  P3-shoes-left-HM-SG; Table 4.2, B.1-B.11); default
                  P2-shoes-left-HMT
  --list-presets  name, alias and source of every preset; the filters keep the
                  fitted feet that match all of them (--section-9-2: the 16 feet
                  compared in section 9.2)
  --foot FILE     a JSON foot spec (schema: proto/schemas/foot.schema.json)
  --density RHO   area density in kg/m^2 for mass properties (default for
                  presets: 36.9)
  --samples N     rolling-kinematics samples over the admissible range
                  (2..100000, default 13)
  --json          print the full report as JSON instead of a table
  --plot-dir DIR  also write foot_shape.{png,svg} (Fig. 3.5a) and
                  ankle_trajectory.{png,svg} (Fig. 3.5b) into DIR
  --version       print the version and git revision
)";

int usage_error(const std::string& message) {
  std::fputs(cyclopt::cli::short_usage("cyclopt-foot", message, kUsage).c_str(), stderr);
  return cyclopt::cli::kExitUsage;
}

// The preset of that name; an unknown one is rejected with the known names and the nearest.
const cyclopt::foot::FootPreset& preset_named(const std::string& name) {
  std::vector<std::string> names;
  for (const cyclopt::foot::FootPreset& p : cyclopt::foot::foot_presets()) {
    names.push_back(p.name);
    if (!p.alias.empty()) names.push_back(p.alias);
  }
  if (std::find(names.begin(), names.end(), name) == names.end() && cyclopt::cli::closest_name(name, names))
    throw std::invalid_argument("--preset: unknown foot '" + name + "'" + cyclopt::cli::did_you_mean(name, names) +
                                "; cyclopt-foot --list-presets lists them");
  return cyclopt::foot::foot_preset(name);
}

// v in %.*f, a value that rounds to zero shown as 0 ("0.00000", never "-0.00000").
std::string fixed(double v, int decimals) {
  if (std::abs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0.0;
  char b[48];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

// The unit and meaning of a foot spec's number `key`: a shape parameter of the model's layout
// (foot_parameters.hpp), the density or theta_F0; empty when unknown.
std::pair<std::string, std::string> unit_of(const std::string& model, const std::string& key) {
  if (key == "density") return {"kg/m^2", "area density rho (appendix E)"};
  if (key == "theta_F0") return {"rad", "foot angle at rest theta_F0"};
  for (const cyclopt::foot::FootModel m : {cyclopt::foot::FootModel::hm, cyclopt::foot::FootModel::hmt})
    if (cyclopt::foot::to_string(m) == model)
      for (const cyclopt::foot::ParameterInfo& p : cyclopt::foot::parameter_layout(m))
        if (p.name == key) return {std::string(p.unit), std::string(p.meaning)};
  return {"", ""};
}

void print_table(const nlohmann::json& r) {
  const auto& spec = r["spec"];
  const std::string model = spec["model"].get<std::string>();
  std::printf("foot %s (model %s)\n", spec.value("name", std::string("-")).c_str(), model.c_str());
  std::printf("  %-12s %12s  %-7s %s\n", "parameter", "value", "unit", "meaning");
  for (const auto& [key, value] : spec.items())
    if (value.is_number()) {
      const auto [unit, meaning] = unit_of(model, key);
      std::printf("  %-12s %12.6g  %-7s %s\n", key.c_str(), value.get<double>() == 0.0 ? 0.0 : value.get<double>(),
                  unit.empty() ? "-" : unit.c_str(), meaning.c_str());
    }
  std::printf("admissible foot angle: [%s, %s] rad\n", fixed(r["admissible_theta"][0].get<double>(), 4).c_str(),
              fixed(r["admissible_theta"][1].get<double>(), 4).c_str());
  if (r.contains("mass_properties")) {
    const auto& m = r["mass_properties"];
    std::printf("mass properties (appendix E):\n  area %s m^2, mass %s kg, CoM (%s, %s) m from the ankle,\n"
                "  J_ankle %s kg m^2, J_CoM %s kg m^2, theta_F0 %s rad\n",
                fixed(m["area"].get<double>(), 6).c_str(), fixed(m["mass"].get<double>(), 4).c_str(),
                fixed(m["com_x"].get<double>(), 4).c_str(), fixed(m["com_z"].get<double>(), 4).c_str(),
                fixed(m["inertia_ankle"].get<double>(), 6).c_str(), fixed(m["inertia_com"].get<double>(), 6).c_str(),
                fixed(m["theta_F0"].get<double>(), 4).c_str());
  }
  std::printf("rolling (ankle A and contact point C while the foot turns through its admissible angles):\n");
  std::printf("%10s %10s %10s %12s %12s %14s\n", "theta/rad", "x_A/m", "z_A/m", "x_AC/m", "z_AC/m", "R/m");
  for (const auto& s : r["rolling"])
    std::printf("%10s %10s %10s %12s %12s %14.6g\n", fixed(s["theta"].get<double>(), 4).c_str(),
                fixed(s["ankle_x"].get<double>(), 5).c_str(), fixed(s["ankle_z"].get<double>(), 5).c_str(),
                fixed(s["contact_x_from_ankle"].get<double>(), 5).c_str(),
                fixed(s["contact_z_from_ankle"].get<double>(), 5).c_str(), s["curvature_radius"].get<double>());
}

// One line per preset: name, alias, source; a fitted foot flagged in the catalogue shows its reason.
int list_presets(const cyclopt::foot::FittedFootFilter& filter, bool filtered) {
  using namespace cyclopt::foot;
  int shown = 0;
  for (const FootPreset& p : foot_presets()) {
    if (filtered && (!p.fitted || !matches(*p.fitted, filter))) continue;
    std::printf("%-24s %-20s %s%s\n", p.name.c_str(), p.alias.empty() ? "-" : p.alias.c_str(), p.source.c_str(),
                p.fitted && !p.fitted->flag.empty() ? ("; FLAGGED: " + p.fitted->flag).c_str() : "");
    ++shown;
  }
  std::fprintf(stderr, "cyclopt-foot: %d of %zu presets\n", shown, foot_presets().size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cyclopt::foot;
  using namespace cyclopt::io;
  if (argc > 1 && std::string(argv[1]) == "fit") return cyclopt::client::run_fit_command(argc, argv);
  if (argc > 1 && std::string(argv[1]) == "synth") return cyclopt::client::run_synth_command(argc, argv);
  std::string preset = "P2-shoes-left-HMT", file;
  std::optional<double> density;
  FootReportOptions options;
  options.samples = 13;
  bool json = false, list = false;
  std::string plot_dir;
  FittedFootFilter filter;
  bool filtered = false;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto next = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
        return argv[++i];
      };
      if (a == "--help" || a == "-h") {
        std::fputs(kUsage, stdout);
        std::fputs(cyclopt::cli::kExitCodeTable, stdout);
        return 0;
      } else if (a == "--version") {
        std::printf("%s\n", cyclopt::cli::version_text("cyclopt-foot").c_str());
        return 0;
      } else if (a == "--list-presets") {
        list = true;
      } else if (std::optional<std::string>* field = a == "--subject"      ? &filter.subject
                                                     : a == "--footwear"   ? &filter.footwear
                                                     : a == "--side"       ? &filter.side
                                                     : a == "--model"      ? &filter.model
                                                     : a == "--trajectory" ? &filter.trajectory
                                                     : a == "--table"      ? &filter.table
                                                                           : nullptr) {
        *field = next();
        filtered = true;
      } else if (a == "--section-9-2") {
        filter.section_9_2_only = filtered = true;
      } else if (a == "--preset") {
        preset = next();
      } else if (a == "--foot") {
        file = next();
      } else if (a == "--density") {
        density = std::stod(next());
      } else if (a == "--samples") {
        options.samples = std::stoi(next());
        if (options.samples < 2 || options.samples > 100000) throw std::invalid_argument("--samples must be in [2, 100000]");
      } else if (a == "--plot-dir") {
        plot_dir = next();
      } else if (a == "--json") {
        json = true;
      } else {
        return usage_error("unknown argument '" + a + "'");
      }
    }
    if (filtered && !list) throw std::invalid_argument("the filters --subject ... --section-9-2 need --list-presets");
    if (list) {
      validate(filter);
      return list_presets(filter, filtered);
    }
  } catch (const cyclopt::SpecError& e) {
    return usage_error("--" + std::string(e.what()));
  } catch (const std::exception& e) {
    return usage_error(e.what());
  }
  try {
    FootSpec spec;
    if (!file.empty()) {
      std::ifstream in(file);
      if (!in) {
        std::fprintf(stderr, "cyclopt-foot: cannot read %s\n", file.c_str());
        return cyclopt::cli::kExitResource;
      }
      spec = foot_spec_from_json(nlohmann::json::parse(in));
    } else {
      spec = preset_named(preset).spec;
      spec.density = 36.9;  // section 10.2's density of the P2 foot
    }
    if (density) spec.density = *density;
    const nlohmann::json report = foot_report(spec, options);
    if (json)
      std::cout << report.dump(2) << "\n";
    else
      print_table(report);
    if (!plot_dir.empty()) {
      std::filesystem::create_directories(plot_dir);
      for (const char* ext : {".png", ".svg"}) {
        cyclopt::plot::render(cyclopt::plot::foot_shape_scene(spec), plot_dir + "/foot_shape" + ext);
        cyclopt::plot::render(cyclopt::plot::ankle_trajectory_chart(spec), plot_dir + "/ankle_trajectory" + ext);
      }
      std::fprintf(stderr, "cyclopt-foot: wrote %s/foot_shape.{png,svg} and %s/ankle_trajectory.{png,svg}\n",
                   plot_dir.c_str(), plot_dir.c_str());
    }
  } catch (const nlohmann::json::parse_error& e) {
    std::fprintf(stderr, "cyclopt-foot: %s is not valid JSON: %s\n", file.c_str(), e.what());
    return cyclopt::cli::kExitRejected;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclopt-foot: %s\n", e.what());
    return cyclopt::cli::kExitRejected;
  }
  return 0;
}
