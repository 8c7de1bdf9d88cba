// cyclopt._results: a job's results from a database file or from cycloptd over LCM, through the
// C++ client (client/result_source.hpp, client/service_client.hpp: its receiver, wire checks and
// signatures); python/cyclopt/results.py wraps it. Links no solver, study or job kind.

#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/records/json_fields.hpp"
#include "gait_arrays.hpp"
#include "result_source.hpp"
#include "spec_error.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

namespace py = pybind11;
using namespace cyclopt;

namespace {

constexpr double kAnswerSeconds = 10.0;  // for an ack of a submission or a cancellation

py::dict ack_dict(const cyclopt_lcm::job_ack_t& a) {
  py::dict d;
  d["request_id"] = a.request_id;
  d["accepted"] = a.accepted;
  d["job_id"] = a.job_id;
  d["duplicate"] = a.duplicate;
  d["state"] = a.state;
  d["field"] = a.field;
  d["problem"] = a.problem;
  return d;
}

py::dict progress_dict(const cyclopt_lcm::job_progress_t& p) {
  py::dict d;
  d["job_id"] = p.job_id;
  d["task"] = p.task;
  d["time [s]"] = 1e-6 * static_cast<double>(p.timestamp_us);  // server clock, Unix seconds
  d["iteration"] = p.iteration;
  d["objective"] = p.objective;
  d["constraint_violation"] = p.constraint_violation;
  d["parameter"] = p.parameter;
  d["curve"] = p.curve_id;
  d["points_done"] = p.points_done;
  d["points_total"] = p.points_total;
  d["percent"] = p.percent;
  d["percent_is_lower_bound"] = p.percent_is_lower_bound;
  d["eta [s]"] = p.eta_seconds;
  d["message"] = p.message;
  d["phase"] = p.phase;
  d["phase_done"] = p.phase_done;
  d["phase_total"] = p.phase_total;
  d["best_objective"] = p.best_objective;
  d["elapsed [s]"] = p.elapsed_seconds;
  return d;
}

py::dict done_dict(const cyclopt_lcm::job_done_t& m) {
  py::dict d;
  d["job_id"] = m.job_id;
  d["state"] = m.state;
  d["points_stored"] = m.points_stored;
  d["run [s]"] = m.run_seconds;
  d["error"] = m.error;
  d["points_expected"] = m.points_expected;
  d["points_converged"] = m.points_converged;
  return d;
}

double number_or_nan(const nlohmann::json& v) {
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

template <class T>
py::array_t<T> array_of(const std::vector<T>& v) {
  return py::array_t<T>(v.size(), v.data());
}

// The name of the points' parameter column: the curves' parameter with its unit.
std::string parameter_column(const nlohmann::json& curves) {
  const std::string name = curves.empty() ? "parameter" : curves[0].value("parameter_name", "parameter");
  return name == "speed" ? "speed [m/s]" : name;
}

class Results {
 public:
  explicit Results(client::ResultSourceOptions options) : source_(std::move(options)) {}

  // Rows of `what` for a job as JSON text (small: the job row, curves, events).
  std::string rows(const std::string& what, std::int64_t job_id, const std::string& state) {
    storage::QueryPage page;
    {
      py::gil_scoped_release release;
      std::lock_guard lock(mutex_);
      page = source_.fetch(storage::query_for(what, job_id, state));
    }
    return page.rows.dump();
  }

  // One column per stored quantity of every point: the row's, then the gait's (gait_arrays.hpp);
  // NaN where a point has no gait.
  py::dict point_columns(std::int64_t job_id) {
    storage::QueryPage points, curves;
    std::vector<std::int64_t> curve, point, iterations;
    std::vector<double> parameter, objective, violation, solved_at;
    std::vector<std::string> status;
    std::vector<records::GaitRecord> gaits;
    {
      py::gil_scoped_release release;
      std::lock_guard lock(mutex_);
      curves = source_.fetch(storage::query_for("curves", job_id));
      points = source_.fetch(storage::query_for("solutions", job_id));
      for (const nlohmann::json& row : points.rows) {
        curve.push_back(row.at("curve").get<std::int64_t>());
        point.push_back(row.at("point").get<std::int64_t>());
        parameter.push_back(number_or_nan(row.at("parameter")));
        objective.push_back(number_or_nan(row.at("objective")));
        violation.push_back(number_or_nan(row.at("constraint_violation")));
        iterations.push_back(row.at("iterations").get<std::int64_t>());
        status.push_back(row.at("status").get<std::string>());
        solved_at.push_back(number_or_nan(row.at("solved_at")));
        const nlohmann::json& values = row.at("values");
        records::GaitRecord gait;
        if (values.is_object() && values.contains("gait")) {
          try {
            gait = values["gait"].get<records::GaitRecord>();
          } catch (const records::RecordError&) {
            gait = {};  // not the contract's gait: its columns stay NaN
          }
        }
        gaits.push_back(std::move(gait));
      }
    }
    py::dict d;
    d["curve"] = array_of(curve);
    d["point"] = array_of(point);
    d[py::str(parameter_column(curves.rows))] = array_of(parameter);
    d["objective [-]"] = array_of(objective);
    d["constraint_violation [-]"] = array_of(violation);
    d["iterations"] = array_of(iterations);
    d["status"] = status;
    d["solved_at [s]"] = array_of(solved_at);
    std::vector<double> column(gaits.size());
    std::vector<std::uint8_t> flag(gaits.size());
    for (std::size_t i = 0; i < gaits.size(); ++i) flag[i] = gaits[i].real;
    d["real"] = array_of(flag).attr("astype")("bool");
    for (std::size_t i = 0; i < gaits.size(); ++i) flag[i] = gaits[i].stable;
    d["stable"] = array_of(flag).attr("astype")("bool");
    for (const python::GaitScalarColumn& c : python::gait_scalar_columns()) {
      if (d.contains(c.name)) continue;  // the row's objective is the gait's
      for (std::size_t i = 0; i < gaits.size(); ++i) column[i] = gaits[i].*c.member;
      d[c.name] = array_of(column);
    }
    return d;
  }

  // The stored trajectory of one point; None when it has none.
  py::object trajectory(std::int64_t job_id, std::int64_t curve, std::int64_t point) {
    std::optional<records::GaitTrajectoryRecord> found;
    {
      py::gil_scoped_release release;
      std::lock_guard lock(mutex_);
      const storage::QueryPage page = source_.fetch(storage::query_for("trajectories", job_id));
      for (const nlohmann::json& row : page.rows)
        if (row.at("curve") == curve && row.at("point") == point && row.at("format") == "json")
          found = row.at("data").get<records::GaitTrajectoryRecord>();
    }
    return found ? py::object(python::gait_trajectories(*found)) : py::none();
  }

  py::object submit(const std::string& spec_json, const std::string& request_id) {
    std::optional<cyclopt_lcm::job_ack_t> ack;
    {
      py::gil_scoped_release release;
      std::lock_guard lock(mutex_);
      ack = source_.remote().submit(request_id.empty() ? client::new_request_id() : request_id, spec_json, kAnswerSeconds);
    }
    return ack ? py::object(ack_dict(*ack)) : py::none();
  }

  py::object cancel(std::int64_t job_id) {
    std::optional<cyclopt_lcm::job_ack_t> ack;
    {
      py::gil_scoped_release release;
      std::lock_guard lock(mutex_);
      ack = source_.remote().cancel(job_id, kAnswerSeconds);
    }
    return ack ? py::object(ack_dict(*ack)) : py::none();
  }

  // The job's progress records received within `seconds`, and its done record once it ended.
  py::tuple watch(std::int64_t job_id, double seconds) {
    std::vector<cyclopt_lcm::job_progress_t> progress;
    std::optional<cyclopt_lcm::job_done_t> done;
    {
      py::gil_scoped_release release;
      std::lock_guard lock(mutex_);
      const std::function<void(const cyclopt_lcm::job_progress_t&)> keep = [&](const cyclopt_lcm::job_progress_t& p) {
        progress.push_back(p);
      };
      done = source_.remote().watch(job_id, keep, seconds, std::min(seconds, 0.5));
    }
    py::list records;
    for (const cyclopt_lcm::job_progress_t& p : progress) records.append(progress_dict(p));
    return py::make_tuple(records, done ? py::object(done_dict(*done)) : py::none());
  }

  long malformed_received() {
    std::lock_guard lock(mutex_);
    return source_.remote().malformed_received();
  }
  long unverified_received() {
    std::lock_guard lock(mutex_);
    return source_.remote().unverified_received();
  }
  bool reads_database() const { return source_.reads_database(); }

 private:
  client::ResultSource source_;
  std::mutex mutex_;  // the source is used by one thread at a time (calls release the GIL)
};

}  // namespace

PYBIND11_MODULE(_results, m) {
  m.doc() = "cyclopt's results and job server client (private; use cyclopt.Client, cyclopt.open_database)";
  python::translate_spec_errors();
  py::register_exception<client::NoAnswer>(m, "NoAnswer", PyExc_TimeoutError);
  py::register_exception<client::QueryError>(m, "QueryError", PyExc_LookupError);
  py::register_exception<client::SignatureRejected>(m, "SignatureRejected", PyExc_PermissionError);
  py::class_<Results>(m, "Results")
      .def(py::init([](const std::string& database, const std::string& lcm_url, const std::string& key_file, double timeout) {
             return std::make_unique<Results>(
                 client::ResultSourceOptions{.database = database, .lcm_url = lcm_url, .key_file = key_file, .timeout = timeout});
           }),
           py::arg("database"), py::arg("lcm_url"), py::arg("key_file"), py::arg("timeout"))
      .def("rows", &Results::rows, py::arg("what"), py::arg("job_id") = 0, py::arg("state") = "")
      .def("point_columns", &Results::point_columns, py::arg("job_id"))
      .def("trajectory", &Results::trajectory, py::arg("job_id"), py::arg("curve"), py::arg("point"))
      .def("submit", &Results::submit, py::arg("spec_json"), py::arg("request_id") = "")
      .def("cancel", &Results::cancel, py::arg("job_id"))
      .def("watch", &Results::watch, py::arg("job_id"), py::arg("seconds"))
      .def_property_readonly("malformed_received", &Results::malformed_received)
      .def_property_readonly("unverified_received", &Results::unverified_received)
      .def_property_readonly("reads_database", &Results::reads_database);
}
