// frictionref.stiff(): the stiff-spring (penalty) model the seed validates,
// by central differences (the CLI's `stiff`, stiff_spring.hpp).
#include <cmath>
#include <vector>

#include "arguments.hpp"
#include "errors.hpp"
#include "frictionref/stiff_spring.hpp"
#include "model.hpp"
#include "module.hpp"
#include "records.hpp"

namespace frictionref::python {
namespace {

py::array stiff(const PyModel& model, py::handle t_end_object, py::handle kf_object,
                py::handle dt_object, py::handle output_dt_object,
                py::handle contact_damping_object, py::handle force_object) {
  const Number t_end = number(t_end_object, "t_end");
  const Number kf = number(kf_object, "kf");
  const Number output_dt = number(output_dt_object, "output_dt");
  const Number contact_damping = number(contact_damping_object, "contact_damping");
  const bool force = flag(force_object, "force");
  TypedInputs inputs = model.input.typed_inputs();
  inputs["t_end"] = {"--t-end", t_end.text};
  inputs["kf"] = {"--kf", kf.text};
  inputs["output_dt"] = {"--output-dt", output_dt.text};
  inputs["contact_damping"] = {"--contact-damping", contact_damping.text};
  StiffSpringOptions options;
  options.contact_damping = contact_damping.value;
  options.kf = kf.value;
  options.output_dt = output_dt.value;
  Number dt;
  if (!dt_object.is_none()) {
    dt = number(dt_object, "dt");
    inputs["dt"] = {"--dt", dt.text};
    options.dt = dt.value;
    // 0 means "automatic" in the library; here that is dt=None (the CLI:
    // leaving --dt out), and the message is the CLI's.
    if (std::isfinite(dt.value) && !(dt.value > 0))
      value_error("--dt = " + dt.text + ": must be > 0 (leave --dt out for the automatic step)");
  }
  StiffSpringSimulator simulator =
      naming(inputs, [&] { return StiffSpringSimulator(model.model, t_end.value, options); });
  const std::uint64_t rows = simulator.total_samples();
  if (!force && rows > 1'000'000'000)
    value_error("--output-dt = " + output_dt.text + ": the output up to --t-end = " + t_end.text +
                " has " + std::to_string(rows) +
                " rows, more than 10^9; pass --force to write them anyway");
  const std::uint64_t steps = simulator.total_steps();
  if (!force && static_cast<double>(steps) > 1e12) {
    const std::string culprit =
        dt_object.is_none() ? "--t-end = " + t_end.text : "--dt = " + dt.text;
    value_error(culprit + ": " + std::to_string(steps) +
                " time steps of dt = " + number_text(simulator.step()) + " (--kf = " + kf.text +
                ") up to t = " + t_end.text + ", more than 10^12; pass --force to run anyway");
  }
  require_memory(static_cast<double>(rows), sizeof(StiffSample), "--output-dt = " + output_dt.text,
                 "pass a larger output_dt or a shorter t_end");
  std::vector<StiffSample> samples;
  {
    py::gil_scoped_release release;
    samples.reserve(rows);
    // A sample may cost up to steps / rows time steps.
    SignalCheck interrupt(std::max<std::uint64_t>(
        1, (1u << 20) / std::max<std::uint64_t>(1, steps / std::max<std::uint64_t>(1, rows))));
    StiffSample sample;
    while (simulator.next(sample)) {
      samples.push_back(sample);
      interrupt();
    }
  }
  static_assert(sizeof(StiffSample) == 5 * sizeof(double), "t, x, v, f, z and nothing else");
  const py::dtype dtype = record_dtype({{"t", "<f8", offsetof(StiffSample, t)},
                                        {"x", "<f8", offsetof(StiffSample, x)},
                                        {"v", "<f8", offsetof(StiffSample, v)},
                                        {"f", "<f8", offsetof(StiffSample, f)},
                                        {"z", "<f8", offsetof(StiffSample, z)}},
                                       sizeof(StiffSample));
  return records(std::move(samples), dtype);
}

}  // namespace

void bind_stiff(py::module_& m) {
  m.def("stiff", &stiff, py::arg("model"), py::arg("t_end"), py::kw_only(), py::arg("kf") = 1e7,
        py::arg("dt") = py::none(), py::arg("output_dt") = 0.01, py::arg("contact_damping") = 0.0,
        py::arg("force") = false,
        R"doc(The stiff-spring (penalty friction) model, by explicit central differences
(the CLI's `stiff`; docs/stiff-spring.md), for every model: friction through
a spring kf in series with a Coulomb slider that breaks loose when the
spring force exceeds the static friction Rs and slides with |f| = R; the
model's spring, damper, offset and harmonics act on the mass.

contact_damping: damping ratio zeta of the contact while stuck (a dashpot
2 zeta sqrt(kf m) beside the spring); with Rs > R use about 1, or the
undamped spring rings past Rs at every stop and the model does not converge.
dt: the time step (default None: 0.1 of the stability limit
2 (sqrt(1+zeta^2)-zeta) sqrt(m/(kf+k))),
reduced to divide output_dt; rows at t0 + k output_dt and at t_end. Returns
a structured array with the fields t, x, v (central difference), f (the
friction force on the mass) and z (the slider). Above 10^9 rows or 10^12
time steps it needs force=True.

    >>> s = frictionref.stiff(frictionref.Model(lambda_=0.7), 30)
    >>> len(s)
    3001
)doc");
}

}  // namespace frictionref::python
