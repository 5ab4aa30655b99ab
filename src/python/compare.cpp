// frictionref.compare(): another code's time history against the exact
// solution, as a dict with the keys of the CLI's `compare --json`.
#include <pybind11/stl.h>

#include <cmath>
#include <vector>

#include "arguments.hpp"
#include "errors.hpp"
#include "frictionref/comparison.hpp"
#include "frictionref/motion_scales.hpp"
#include "frictionref/comparison_json.hpp"
#include "model.hpp"
#include "module.hpp"

namespace frictionref::python {
namespace {

// compare --json's document, key for key (the library writes both), with
// the model's harmonics as tuples like Model.to_dict(), plus the text report.
py::dict report_dict(const ComparisonReport& r) {
  py::dict out = py::module_::import("json").attr("loads")(comparison_json(r));
  out["model"] = model_dict(r.model);
  out["report"] = r.full_report();
  return out;
}

std::uint64_t stop_count(py::handle object, const char* keyword, const char* option) {
  const Number n = whole(object, keyword);
  if (!(n.value >= 0) || n.value != std::floor(n.value) || !(n.value < 1e18))
    value_error(std::string(option) + " = " + n.text + ": must be a whole number >= 0");
  return static_cast<std::uint64_t>(n.value);
}

std::vector<double> column(py::handle object, const char* keyword) {
  const py::array_t<double> array = float_array(object, keyword);
  return std::vector<double>(array.data(), array.data() + array.size());
}

py::dict compare_history(const PyModel& model, py::handle t_object, py::handle v_object,
                         py::handle x_object, py::handle stick_threshold,
                         py::handle min_stick_duration, py::handle velocity_tolerance,
                         py::handle velocity_rms_tolerance, py::handle stop_time_tolerance,
                         py::handle max_missed_stops, py::handle max_extra_stops,
                         py::handle displacement_tolerance, py::handle regime_window) {
  TypedInputs inputs = model.input.typed_inputs();
  CompareOptions options;
  // (library field, keyword, CLI option, value)
  const auto set = [&](const char* field, const char* keyword, const char* option,
                       py::handle object, double& value) {
    const Number n = number(object, keyword);
    inputs[field] = {option, n.text};
    value = n.value;
  };
  set("stick_threshold", "stick_threshold", "--stick-threshold", stick_threshold,
      options.stick_threshold);
  set("min_stick_duration", "min_stick_duration", "--min-stick-duration", min_stick_duration,
      options.min_stick_duration);
  set("velocity_max_tolerance", "velocity_tolerance", "--velocity-tolerance", velocity_tolerance,
      options.velocity_max_tolerance);
  set("velocity_rms_tolerance", "velocity_rms_tolerance", "--velocity-rms-tolerance",
      velocity_rms_tolerance, options.velocity_rms_tolerance);
  set("stop_time_tolerance", "stop_time_tolerance", "--stop-time-tolerance", stop_time_tolerance,
      options.stop_time_tolerance);
  set("displacement_max_tolerance", "displacement_tolerance", "--displacement-tolerance",
      displacement_tolerance, options.displacement_max_tolerance);
  set("regime_window", "regime_window", "--regime-window", regime_window, options.regime_window);
  options.max_missed_stops = stop_count(max_missed_stops, "max_missed_stops", "--max-missed-stops");
  options.max_extra_stops = stop_count(max_extra_stops, "max_extra_stops", "--max-extra-stops");
  naming(inputs, [&] { options.validate(); });
  // The scales every tolerance is relative to exist (B > 0, or a record that
  // is not zero throughout), checked as the CLI does before the candidate.
  naming(inputs, [&] { (void)motion_scales(model.model, "to compare"); });

  TimeHistory history;
  history.t = column(t_object, "t");
  history.v = column(v_object, "v");
  if (!x_object.is_none()) history.x = column(x_object, "x");
  history.source = "arrays t, v" + std::string(history.x ? ", x" : "") + " (" +
                   std::to_string(history.t.size()) + " rows)";
  naming(inputs, [&] { history.validate(); });
  if (history.t.front() < model.model.t0)
    value_error("t[0] = " + number_text(history.t.front()) +
                ": is before --t0 = " + inputs.at("t0").text +
                "; the exact motion starts at t0 (pass the candidate's start time as t0)");
  const ComparisonReport report = naming(inputs, [&] {
    py::gil_scoped_release release;
    return compare(model.model, history, options);
  });
  return report_dict(report);
}

}  // namespace

void bind_compare(py::module_& m) {
  const CompareOptions defaults;
  m.def("compare", &compare_history, py::arg("model"), py::arg("t"), py::arg("v"),
        py::arg("x") = py::none(), py::kw_only(),
        py::arg("stick_threshold") = defaults.stick_threshold,
        py::arg("min_stick_duration") = defaults.min_stick_duration,
        py::arg("velocity_tolerance") = defaults.velocity_max_tolerance,
        py::arg("velocity_rms_tolerance") = defaults.velocity_rms_tolerance,
        py::arg("stop_time_tolerance") = defaults.stop_time_tolerance,
        py::arg("max_missed_stops") = defaults.max_missed_stops,
        py::arg("max_extra_stops") = defaults.max_extra_stops,
        py::arg("displacement_tolerance") = defaults.displacement_max_tolerance,
        py::arg("regime_window") = defaults.regime_window,
        R"doc(Checks another code's time history (times t, velocities v, optionally
positions x; 1-D arrays of equal length, t non-decreasing, from model.t0 on)
against the exact solution at those very times (the CLI's `compare`;
docs/cross-checking.md). Needs amplitude B > 0, or a record (ground_accel).

Returns the report as a dict with the keys of `compare --json`: verdict
('PASS', 'FAIL' or 'INCONCLUSIVE': every check passed but the samples do not
resolve the exact motion, see resolution), failed_checks, diagnosis (defect:
the most likely defect class, value, evidence, text), checks (name, passed, value, tolerance,
message), candidate, model, options, scales, velocity_error,
displacement_error (None without x), sticks, creep, regime, notes, version,
and report (the CLI's text report). Tolerances as the CLI's options, in
B/(m w) for velocities, B/(m w^2) for positions and forcing periods for
times (with a record: its PGV, PGV^2/PGA and T* = 2 pi PGV/PGA; scales
names them): stick_threshold, min_stick_duration, velocity_tolerance,
velocity_rms_tolerance, stop_time_tolerance, max_missed_stops,
max_extra_stops, displacement_tolerance, regime_window.

    >>> model = frictionref.Model(lambda_=0.7)
    >>> s = frictionref.stiff(model, 30)
    >>> frictionref.compare(model, s['t'], s['v'])['verdict']
    'PASS'
)doc");
}

}  // namespace frictionref::python
