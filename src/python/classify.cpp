// frictionref.classify(): the steady state as a dict with the keys of the
// CLI's `classify --json`.
#include <cmath>

#include "arguments.hpp"
#include "errors.hpp"
#include "frictionref/classification.hpp"
#include "frictionref/classification_json.hpp"
#include "frictionref/steady_state.hpp"
#include "model.hpp"
#include "module.hpp"

namespace frictionref::python {
namespace {

// classify --json's document, key for key (the library writes both), with
// the model's harmonics as tuples like Model.to_dict().
py::dict classification_dict(const Model& model, const Classification& c) {
  py::dict out = py::module_::import("json").attr("loads")(classification_json(model, c));
  out["model"] = model_dict(model);
  return out;
}

py::dict classify_model(const PyModel& model, py::handle max_periods_object, py::handle simulate) {
  ClassifyOptions options;
  options.closed_forms = !flag(simulate, "simulate");
  const Number periods = whole(max_periods_object, "max_periods");
  if (!(periods.value >= 2 && periods.value <= 1e6 && periods.value == std::floor(periods.value)))
    value_error("--max-periods = " + periods.text + ": must be a whole number from 2 to 1000000");
  options.max_periods = static_cast<std::uint64_t>(periods.value);
  const TypedInputs inputs = model.input.typed_inputs();
  const Classification c = naming(inputs, [&] {
    py::gil_scoped_release release;
    return classify(model.model, options);
  });
  return classification_dict(model.model, c);
}

}  // namespace

void bind_classify(py::module_& m) {
  m.def("classify", &classify_model, py::arg("model"), py::kw_only(), py::arg("max_periods") = 400,
        py::arg("simulate") = false,
        R"doc(The steady state of the motion, as a dict with the keys of the CLI's
`classify --json`.

The seed's model (method 'closed-form'): regime ('continuous', 'dead-bands',
'stops') by lambda = R / B against lambda* = 2 / sqrt(4 + pi^2), lambda,
threshold, threshold_quoted (0.536), regime_by_quoted_threshold,
reversal_phase, breakaway_phase, stop_phase, stops_per_period,
stuck_fraction, slide_per_half_period, peak_velocity, energy_per_period.
Any other model (or simulate=True): regime (also 'aperiodic'), method,
forcing_period, multiplicity, transient_periods, stops_per_period,
reversals_per_period, stuck_fraction, drift_per_period, peak_velocity,
den_hartog (a dict where Den Hartog's solution applies, else None). Both
end with model (Model.to_dict()) and version. Figures that do not apply are
None. max_periods (2 to 10^6) bounds the simulated forcing periods.

    >>> frictionref.classify(frictionref.Model(lambda_=0.7))['regime']
    'dead-bands'
)doc");
  m.def("regime_threshold", &regime_threshold,
        "lambda* = 2 / sqrt(4 + pi^2) = 0.5370292721463151: the seed's model moves "
        "continuously iff lambda = R / B < lambda*.");
}

}  // namespace frictionref::python
