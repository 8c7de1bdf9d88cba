#include "cyclopt/plot/walker_figures.hpp"

#include "cyclopt/plot/foot_figures.hpp"
#include "cyclopt/plot/gait_stroboscope.hpp"
#include "cyclopt/plot/html_report.hpp"
#include "cyclopt/plot/speed_charts.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

// The converged speed in the middle of the first job's curve.
double middle_speed(const WalkerJobResults& job) {
  std::vector<double> v;
  for (const GaitPoint& p : job.points)
    if (p.converged && p.trajectory) v.push_back(p.speed);
  return v.empty() ? std::nan("") : v[v.size() / 2];
}

void render_to(const Figure& f, const std::string& path) {
  std::visit([&](const auto& d) { render(d, path, f.options); }, f.drawing);
}

}  // namespace

const GaitPoint* chosen_point(const WalkerJobResults& job, double speed) {
  return point_near(job, std::isfinite(speed) ? speed : middle_speed(job));
}

const std::vector<std::string>& walker_figure_kinds() {
  static const std::vector<std::string> kinds = {"cost-of-transport", "torques", "step-length", "floquet",
                                                 "impact-loss", "stroboscope", "foot"};
  return kinds;
}

Figure walker_figure(const std::string& kind, const std::vector<WalkerJobResults>& jobs, double speed) {
  if (jobs.empty()) throw std::invalid_argument("plot " + kind + ": no job given");
  if (kind == "cost-of-transport")
    return {"cost_of_transport", "Mechanical cost of transport f_{mech} over speed (seed 001 Fig. 9.19a)",
            cost_of_transport_chart(jobs), {}};
  if (kind == "torques")
    return {"max_torques", "Maximal joint torques over speed (seed 001 Fig. 9.4)", max_torque_chart(jobs), {}};
  if (kind == "step-length")
    return {"step_length", "Step length over speed (seed 001 Fig. 9.6a)", step_length_chart(jobs), {}};
  if (kind == "floquet")
    return {"floquet_multiplier", "Floquet multiplier over speed (seed 001 Fig. 9.6b)", floquet_chart(jobs), {}};
  if (kind == "impact-loss")
    return {"impact_loss", "Kinetic energy dissipated in the impact over speed (seed 001 Fig. 9.5b)",
            impact_loss_chart(jobs), {}};
  if (kind == "stroboscope") {
    const GaitPoint* p = chosen_point(jobs.front(), speed);
    if (!p) throw std::invalid_argument("job " + std::to_string(jobs.front().id) +
                                        " has no converged gait with a stored trajectory");
    char caption[160];
    std::snprintf(caption, sizeof caption, "Two steps of the gait at %.2f m/s (seed 001 Fig. 9.2), %s", p->speed,
                  jobs.front().label.c_str());
    Scene scene = gait_stroboscope(jobs.front(), *p);
    const RenderOptions size = fitted_options(scene, 760, 600, kPageWidth);
    return {"stroboscope", caption, std::move(scene), size};
  }
  if (kind == "foot") {
    for (const WalkerJobResults& job : jobs)
      if (job.walker.foot.model != foot::FootModel::point)
        return {"foot_shape", "Foot shape of job " + std::to_string(job.id) +
                                  " with its generating polygon (seed 001 Fig. 3.5a)",
                foot_shape_scene(job.walker.foot), {}};
    throw std::invalid_argument("the given jobs all walk on point feet, which have no foot shape");
  }
  std::string known;
  for (const std::string& k : walker_figure_kinds()) known += (known.empty() ? "" : ", ") + k;
  throw std::invalid_argument("plot: unknown KIND '" + kind + "' (known: " + known + ", giant-swing, all)");
}

std::vector<Figure> walker_figures(const std::vector<WalkerJobResults>& jobs, double speed,
                                   std::vector<std::string>* not_drawn) {
  std::vector<Figure> out;
  for (const std::string& kind : walker_figure_kinds()) {
    try {
      out.push_back(walker_figure(kind, jobs, speed));
    } catch (const std::invalid_argument& e) {  // nothing to draw for this kind
      if (not_drawn) not_drawn->push_back(kind + ": " + e.what());
    }
  }
  return out;
}

std::vector<std::string> write_figure(const Figure& f, const std::string& dir) {
  std::filesystem::create_directories(dir);
  std::vector<std::string> paths;
  for (const char* ext : {".png", ".svg"}) {
    paths.push_back((std::filesystem::path(dir) / (f.name + ext)).string());
    render_to(f, paths.back());
  }
  return paths;
}

ReportFigure report_figure(const Figure& f) {
  return {f.caption, svg_of(f), [drawing = f.drawing](Canvas& c) { std::visit([&c](const auto& d) { draw(d, c); }, drawing); },
          f.options};
}

std::string svg_of(const Figure& f) {
  return std::visit([&](const auto& d) { return plot::svg_of(d, f.options); }, f.drawing);
}

}  // namespace cyclopt::plot
