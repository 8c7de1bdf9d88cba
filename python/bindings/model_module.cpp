// cyclopt._model: feet and the walker's gait (python/cyclopt/model.py wraps it). A walker problem
// arrives as the walker fields of a job spec (jobs/walker/walker_job_spec.hpp), so Python checks
// the same fields with the same messages as the server; every long call releases the GIL.

#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot/mass_properties.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/jobs/walker/walker_records.hpp"
#include "cyclopt/service/common_job_fields.hpp"
#include "cyclopt/walker/distant_start_solver.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"
#include "gait_arrays.hpp"
#include "spec_error.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include <memory>

namespace py = pybind11;
using namespace cyclopt;

namespace {

foot::FootSpec foot_from_json(const std::string& text) { return io::foot_spec_from_json(nlohmann::json::parse(text)); }

// A walker problem: the walker fields of a one-speed job spec, parsed as the server parses them,
// and the evaluator of its model, built once (Python keeps recent scenes, model.py).
struct GaitScene {
  explicit GaitScene(jobs::WalkerJob j) : job(std::move(j)), evaluator(job.model()) {}
  jobs::WalkerJob job;
  walker::GaitEvaluator evaluator;
};

std::unique_ptr<GaitScene> gait_scene(const std::string& spec_text) {
  const nlohmann::json spec = nlohmann::json::parse(spec_text);
  return std::make_unique<GaitScene>(jobs::parse_walker_job(spec, service::parse_common_job_fields(spec), false));
}

// Appendix E at the foot's density (or `density`, kg/m^2, when given).
py::dict mass_properties(const foot::FootSpec& spec, std::optional<double> density) {
  if (!density) density = spec.density;
  if (!density) throw SpecError("density", "the foot has no density (kg/m^2) to derive its mass properties from");
  if (!(*density >= foot::kMinDensity && *density <= foot::kMaxDensity))
    throw SpecError("density", "must be in " + range_text(foot::kMinDensity, foot::kMaxDensity, "kg/m^2"));
  const foot::FootMassProperties<double> m =
      foot::mass_properties(foot::make_profile(spec.model, spec.parameters, spec.periodic_terms), *density);
  py::dict d;
  d["area [m^2]"] = m.area;
  d["mass [kg]"] = m.mass;
  d["com_x [m]"] = m.com_x;
  d["com_z [m]"] = m.com_z;
  d["inertia_ankle [kg m^2]"] = m.inertia_ankle;
  d["inertia_com [kg m^2]"] = m.inertia_com;
  d["com_distance [m]"] = m.com_distance;
  d["theta_F0 [rad]"] = m.theta_F0;
  return d;
}

// F and its derivatives (eq. 3.19 / 3.22) and the curvature radius (eq. 3.14) at foot angles theta.
py::dict rolling(const foot::FootSpec& spec, const py::array_t<double, py::array::c_style | py::array::forcecast>& theta) {
  const auto profile = foot::make_profile(spec.model, spec.parameters, spec.periodic_terms);
  const auto in = theta.unchecked<1>();
  const py::ssize_t n = in.shape(0);
  py::array_t<double> F(n), dF(n), ddF(n), dddF(n), R(n);
  auto f = F.mutable_unchecked<1>(), f1 = dF.mutable_unchecked<1>(), f2 = ddF.mutable_unchecked<1>(),
       f3 = dddF.mutable_unchecked<1>(), r = R.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const foot::RollingContact<double> c = foot::rolling_contact(profile, in(i));
    f(i) = c.F, f1(i) = c.dF, f2(i) = c.ddF, f3(i) = c.dddF;
    r(i) = foot::curvature_radius(profile, in(i));
  }
  py::dict d;
  d["theta [rad]"] = theta;
  d["F [m]"] = F;             // horizontal ankle position minus x_0 (eq. 3.9)
  d["dF [m]"] = dF;           // ankle height z_A (eq. 3.10a)
  d["ddF [m]"] = ddF;         // ankle -> contact point, horizontal (eq. 5.5)
  d["dddF [m]"] = dddF;
  d["curvature_radius [m]"] = R;  // eq. 3.14
  return d;
}

// The automatic starting gait at the job's speed (or its "start").
Eigen::VectorXd starting_gait(const GaitScene& scene) {
  py::gil_scoped_release release;
  return walker::gait_start(scene.evaluator, scene.job.speeds.at(0), scene.job.start).x;
}

// The evaluator's vectors and column-major matrices copied straight into C-ordered NumPy arrays.
struct EigenArrays {
  py::array_t<double> operator()(const Eigen::VectorXd& v) const { return py::array_t<double>(v.size(), v.data()); }
  py::array_t<double> operator()(const Eigen::MatrixXd& m) const {
    py::array_t<double> a({m.rows(), m.cols()});
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(a.mutable_data(), m.rows(), m.cols()) = m;
    return a;
  }
};

py::tuple evaluate_gait(const GaitScene& scene, const Eigen::VectorXd& x) {
  walker::PeriodicGait<double> g;
  records::GaitRecord gait;
  {
    py::gil_scoped_release release;
    g = scene.evaluator.evaluate(x, scene.job.gait_options(scene.job.speeds.at(0)));
    gait = jobs::gait_record(g);
  }
  if (g.trajectory.time.size() == 0) return py::make_tuple(python::gait_scalars(gait), py::none());
  return py::make_tuple(python::gait_scalars(gait), python::trajectory_arrays(g.trajectory, EigenArrays{}));
}

// The optimum as a job would store it: (values as JSON text, scalars, trajectories).
py::tuple optimise_gait(const GaitScene& scene) {
  const jobs::WalkerJob& job = scene.job;
  jobs::WalkerPoint point;
  {
    py::gil_scoped_release release;
    const double v = job.speeds.at(0);
    point = jobs::walker_point(walker::optimise_gait(job.model(), job.problem_at(v), walker::distant_start_solver(job.solver), job.start), {0, 0}, v);
  }
  return py::make_tuple(nlohmann::json(point.values).dump(), point.values.gait ? py::object(python::gait_scalars(*point.values.gait)) : py::none(),
                        point.trajectory ? py::object(python::gait_trajectories(*point.trajectory)) : py::none());
}

}  // namespace

PYBIND11_MODULE(_model, m) {
  m.doc() = "cyclopt's feet and walker gait (private; use cyclopt.Foot, cyclopt.evaluate_gait)";
  python::translate_spec_errors();
  py::class_<foot::FootSpec>(m, "FootSpec")
      .def("to_json", [](const foot::FootSpec& s) { return io::to_json(s).dump(); })
      .def_property_readonly("model", [](const foot::FootSpec& s) { return std::string(foot::to_string(s.model)); })
      .def_readonly("name", &foot::FootSpec::name);
  m.def("foot_from_json", &foot_from_json, py::arg("text"));
  m.def("foot_preset", [](const std::string& name) { return foot::foot_preset(name).spec; }, py::arg("name"));
  m.def("foot_preset_names", [] {
    std::vector<std::string> names;
    for (const foot::FootPreset& p : foot::foot_presets()) names.push_back(p.name);
    return names;
  });
  m.def("mass_properties", &mass_properties, py::arg("foot"), py::arg("density") = py::none());
  m.def("rolling", &rolling, py::arg("foot"), py::arg("theta"));
  py::class_<GaitScene>(m, "GaitScene");
  m.def("gait_scene", &gait_scene, py::arg("spec_json"));
  m.def("starting_gait", &starting_gait, py::arg("scene"));
  m.def("evaluate_gait", &evaluate_gait, py::arg("scene"), py::arg("x"));
  m.def("optimise_gait", &optimise_gait, py::arg("scene"));
}
