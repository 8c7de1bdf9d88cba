#include "cyclopt/plot/foot_fit_figures.hpp"

#include "cyclopt/foot/foot_profile.hpp"
#include "cyclopt/foot/mass_properties.hpp"
#include "cyclopt/io/foot_fit_json.hpp"
#include "cyclopt/plot/foot_figures.hpp"
#include "cyclopt/records/foot_fit_record.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

std::string model_name(const foot_fit::FootFitResult& fit) { return std::string(foot::to_string(fit.model)); }

std::pair<double, double> fitted_angle_range(const foot_fit::FootFitResult& fit) {
  double lo = 1e300, hi = -1e300;
  for (const Eigen::VectorXd& th : fit.theta) {
    if (th.size() == 0) continue;
    lo = std::min(lo, th.minCoeff());
    hi = std::max(hi, th.maxCoeff());
  }
  return {lo, hi};
}

}  // namespace

LineChart stance_chart(const foot_fit::GaitTrial& trial, int first_track) {
  const foot_fit::AnkleSeries& a = trial.ankle;
  LineChart chart;
  chart.axes = {a.source + ": ankle height and stances (" + std::to_string(trial.complete_stances()) + " of " +
                    std::to_string(trial.stances.size()) + " fitted)",
                "time t (s)", "ankle height z (m)", true};
  chart.x_range = Range{a.time.front(), a.time.back()};
  Series all{"ankle", a.time, {}, false, false, Color{0.6, 0.6, 0.6, 1}};
  for (int i = 0; i < a.samples(); ++i) all.y.push_back(a.present(i) ? a.height(i) : std::nan(""));
  chart.series.push_back(all);
  int track = first_track;
  for (std::size_t k = 0; k < trial.stances.size(); ++k) {
    const foot_fit::Stance& s = trial.stances[k];
    Series window;
    char label[200];
    if (s.complete()) {
      std::snprintf(label, sizeof label, "stance %zu, %s: fitted", k + 1, s.rule.c_str());
      window = {label, {}, {}, true, false, palette(track++)};
    } else {
      std::string why = s.refusal.substr(0, s.refusal.find('('));
      while (!why.empty() && why.back() == ' ') why.pop_back();
      std::snprintf(label, sizeof label, "stance %zu, %s: refused, %s", k + 1, s.rule.c_str(), why.c_str());
      window = {label, {}, {}, false, true, Color{0.84, 0.15, 0.16, 1}};
    }
    for (int i = s.first; i <= s.last; ++i) {
      window.x.push_back(a.time[i]);
      window.y.push_back(a.present(i) ? a.height(i) : std::nan(""));
    }
    chart.series.push_back(window);
  }
  return chart;
}

std::vector<Figure> stance_figures(const std::vector<foot_fit::GaitTrial>& trials) {
  std::vector<Figure> out;
  int track = 0;
  for (std::size_t k = 0; k < trials.size(); ++k) {
    LineChart chart = stance_chart(trials[k], track);
    track += trials[k].complete_stances();
    out.push_back({"fit_stances_" + std::to_string(k + 1), chart.axes.title, std::move(chart), RenderOptions{1000, 500}});
  }
  return out;
}

Scene fitted_ankle_scene(const std::vector<foot_fit::AnkleTrack>& tracks, const foot_fit::FootFitResult& fit) {
  Scene scene;
  char title[160];
  std::snprintf(title, sizeof title, "%s fit: ankle of %zu trial(s), RMS %.3f mm (Fig. 4.%da)", model_name(fit).c_str(),
                tracks.size(), 1e3 * fit.rms, fit.model == foot::FootModel::hm ? 3 : 4);
  scene.axes = {title, "x - x_off (m)", "ankle height z (m)", true};
  const Color model{0.1, 0.1, 0.1, 1};
  for (std::size_t k = 0; k < tracks.size(); ++k)
    for (int j = 0; j < tracks[k].samples(); ++j) {
      scene.markers.push_back({tracks[k].x[j] - fit.x_off[k], tracks[k].z[j], palette(static_cast<int>(k)), 2.5,
                               "measured: " + tracks[k].source});
      const Eigen::Vector2d m = fit.model_ankle(static_cast<int>(k), j);
      scene.markers.push_back({m.x() - fit.x_off[k], m.y(), model, 1.2, "model at fitted theta_F"});
    }
  // The model's ankle trajectory over the fitted angles, eq. (4.15) / (4.20).
  const foot::FootProfile<double> prof = foot::make_profile(fit.model, fit.parameters);
  const double f0 = foot::rolling_contact(prof, 0.0).F;
  const auto [lo, hi] = fitted_angle_range(fit);
  Shape curve{{}, Color{0.17, 0.63, 0.17, 1}, 1.2, false, false, std::nullopt, "model trajectory"};
  for (int i = 0; i <= 400; ++i) {
    const foot::RollingContact<double> c = foot::rolling_contact(prof, lo + (hi - lo) * i / 400.0);
    curve.points.push_back({c.F - f0, c.dF});
  }
  scene.shapes.push_back(curve);
  scene.ground_z = 0.0;
  return scene;
}

Scene fitted_outline_scene(const foot_fit::FootFitResult& fit) {
  Scene scene = foot_shape_scene(fit.spec("fitted " + model_name(fit)));
  scene.axes.title = "fitted " + model_name(fit) + ": outline and generating polygon (Fig. 4." +
                     (fit.model == foot::FootModel::hm ? "3b)" : "4b)");
  // The part of the outline that touched the ground during the fit (Fig. 4.9).
  const foot::FootProfile<double> prof = foot::make_profile(fit.model, fit.parameters);
  const auto [lo, hi] = fitted_angle_range(fit);
  Shape rolled{{}, Color{0.17, 0.63, 0.17, 1}, 3.5, false, false, std::nullopt, "rolled in the fit"};
  for (int i = 0; i <= 300; ++i) {
    const double a = lo + (hi - lo) * i / 300.0;
    const foot::Vector2<double> c = foot::outline_point(foot::rolling_contact(prof, a), a);
    rolled.points.push_back({c.x(), c.y()});
  }
  scene.shapes.push_back(rolled);
  return scene;
}

std::vector<Figure> fit_figures(const std::vector<foot_fit::AnkleTrack>& tracks, const foot_fit::FootFitResult& fit) {
  const std::string stem = fit.model == foot::FootModel::hm ? "fit_hm" : "fit_hmt";
  Scene ankle = fitted_ankle_scene(tracks, fit), outline = fitted_outline_scene(fit);
  const RenderOptions ankle_size = fitted_options(ankle, 600), outline_size = fitted_options(outline, 600);
  std::vector<Figure> out;
  out.push_back({stem + "_ankle", ankle.axes.title, std::move(ankle), ankle_size});
  out.push_back({stem + "_outline", outline.axes.title, std::move(outline), outline_size});
  return out;
}

std::vector<Figure> foot_fit_job_figures(const nlohmann::json& doc, std::vector<std::string>* not_drawn) {
  const std::int64_t id = doc.value("id", std::int64_t{0});
  if (doc.value("task", "") != "foot_fit" || !doc.contains("spec"))
    throw std::invalid_argument("job " + std::to_string(id) + " is a " + doc.value("task", std::string("?")) +
                                " job; the foot fit figures need a foot_fit job");
  const std::vector<foot_fit::AnkleTrack> tracks = io::ankle_tracks_from_json(doc["spec"].at("trials"), "spec.trials");
  std::map<int, const nlohmann::json*> angles;  // by point index, into doc
  const nlohmann::json none = nlohmann::json::array();
  for (const nlohmann::json& t : doc.contains("trajectories") ? doc["trajectories"] : none)
    if (t.value("format", "") == "json" && t.value("curve", 0) == 0) angles[t.value("point", 0)] = &t.at("data");
  std::vector<Figure> out;
  int fits = 0;
  for (const nlohmann::json& s : doc.value("solutions", nlohmann::json::array())) {
    if (s.value("curve", 0) != 0 || !records::is_foot_fit(s.at("values"))) continue;
    ++fits;
    const auto record = s["values"].get<records::FootFitRecord>();
    const auto a = angles.find(s.value("point", 0));
    std::string why;
    if (!record.converged) why = "did not converge (" + record.message + ")";
    else if (a == angles.end()) why = "has no stored foot angles (stored before they were kept)";
    if (!why.empty()) {
      if (not_drawn) not_drawn->push_back(record.model + " fit: " + why);
      continue;
    }
    const foot_fit::FootFitResult fit = io::foot_fit_result(record, a->second->get<records::FootFitAnglesRecord>());
    for (Figure& f : fit_figures(tracks, fit)) out.push_back(std::move(f));
  }
  if (fits == 0) throw std::invalid_argument("job " + std::to_string(id) + " has no stored fit yet (is it finished?)");
  return out;
}

}  // namespace cyclopt::plot
