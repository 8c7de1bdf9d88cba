#pragma once
// The figures of walker jobs by name, as `cyclopt plot KIND` and `cyclopt report` draw them:
//   cost-of-transport  f_mech over speed, one curve per job (seed 001 Fig. 9.19a)
//   torques            max |u| per joint over speed (Fig. 9.4)
//   step-length        step length over speed (Fig. 9.6a)
//   floquet            Floquet multiplier over speed (Fig. 9.6b)
//   impact-loss        kinetic energy the impact dissipates, relative to E_kin after it (Fig. 9.5b)
//   stroboscope        two steps of the gait nearest a speed, first job (Fig. 9.2)
//   foot               the first foot (not point feet) of the jobs with its generating polygon (Fig. 3.5a)

#include "cyclopt/plot/html_report.hpp"
#include "cyclopt/plot/line_chart.hpp"
#include "cyclopt/plot/scene.hpp"
#include "cyclopt/plot/walker_job_results.hpp"

#include <limits>
#include <string>
#include <variant>
#include <vector>

namespace cyclopt::plot {

struct Figure {
  std::string name;     // file stem, e.g. "cost_of_transport"
  std::string caption;  // one line for reports and terminal output
  std::variant<LineChart, Scene> drawing;
  RenderOptions options;
};

const std::vector<std::string>& walker_figure_kinds();

// The converged gait with a trajectory nearest `speed` (NaN: the middle of the converged speeds) of
// the job: the stroboscope's and the report's within-step figures' gait; nullptr when there is none.
const GaitPoint* chosen_point(const WalkerJobResults& job, double speed);

// Throws std::invalid_argument for an unknown kind (naming the known ones) or when the jobs hold
// nothing to draw for it (no converged gait, no trajectory, point feet for "foot").
// `speed` (m/s) selects the stroboscope's gait; NaN: the middle of the converged points.
Figure walker_figure(const std::string& kind, const std::vector<WalkerJobResults>& jobs,
                     double speed = std::numeric_limits<double>::quiet_NaN());

// Every kind that can be drawn from these jobs; the others are skipped and, with `not_drawn`,
// listed there as "KIND: why" (e.g. "stroboscope: job 3 has no converged gait ...").
std::vector<Figure> walker_figures(const std::vector<WalkerJobResults>& jobs,
                                   double speed = std::numeric_limits<double>::quiet_NaN(),
                                   std::vector<std::string>* not_drawn = nullptr);

// Writes DIR/NAME.png and DIR/NAME.svg (creating DIR); returns both paths.
std::vector<std::string> write_figure(const Figure& figure, const std::string& dir);
std::string svg_of(const Figure& figure);
// The figure for a report: its SVG for the HTML page and its drawing for the PDF.
ReportFigure report_figure(const Figure& figure);

}  // namespace cyclopt::plot
