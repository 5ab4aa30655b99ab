// frictionref.classify(): the steady state as a dict with the keys of the
// CLI's `classify --json`.
#include <cmath>

#include "arguments.hpp"
#include "errors.hpp"
#include "frictionref/classification.hpp"
#include "frictionref/steady_state.hpp"
#include "frictionref/version.hpp"
#include "model.hpp"
#include "module.hpp"

namespace frictionref::python {
namespace {

// NaN marks a figure that does not apply: None (JSON null).
py::object value_or_none(double value) {
  if (std::isnan(value)) return py::none();
  return py::float_(value);
}

py::dict seed_dict(const Model& model, const SteadyState& steady) {
  py::dict d;
  d["regime"] = std::string(to_string(steady.regime));
  d["method"] = std::string(to_string(ClassificationMethod::closed_form));
  d["lambda"] = value_or_none(steady.lambda);
  d["threshold"] = value_or_none(steady.threshold);
  d["threshold_quoted"] = value_or_none(steady.threshold_quoted);
  d["regime_by_quoted_threshold"] = std::string(to_string(steady.regime_by_quoted_threshold));
  d["reversal_phase"] = value_or_none(steady.reversal_phase);
  d["breakaway_phase"] = value_or_none(steady.breakaway_phase);
  d["stop_phase"] = value_or_none(steady.stop_phase);
  d["stops_per_period"] = value_or_none(steady.stops_per_period);
  d["stuck_fraction"] = value_or_none(steady.stuck_fraction);
  d["slide_per_half_period"] = value_or_none(steady.slide_per_half_period);
  d["peak_velocity"] = value_or_none(steady.peak_velocity);
  d["energy_per_period"] = value_or_none(steady.energy_per_period);
  d["model"] = model_dict(model);
  d["version"] = version;
  return d;
}

py::dict classification_dict(const Model& model, const Classification& c) {
  if (c.seed && c.method == ClassificationMethod::closed_form) return seed_dict(model, *c.seed);
  py::dict d;
  d["regime"] = std::string(to_string(c.regime));
  d["method"] = std::string(to_string(c.method));
  d["forcing_period"] = value_or_none(c.forcing_period);
  d["multiplicity"] = c.multiplicity;
  d["transient_periods"] = c.transient_periods;
  d["stops_per_period"] = value_or_none(c.stops_per_period);
  d["reversals_per_period"] = value_or_none(c.reversals_per_period);
  d["stuck_fraction"] = value_or_none(c.stuck_fraction);
  d["drift_per_period"] = value_or_none(c.drift_per_period);
  d["peak_velocity"] = value_or_none(c.peak_velocity);
  if (c.den_hartog) {
    const DenHartogSolution& h = *c.den_hartog;
    py::dict dh;
    dh["non_stop"] = h.non_stop;
    dh["stable"] = h.stable;
    dh["failed"] = h.failed;
    dh["frequency_ratio"] = value_or_none(h.frequency_ratio);
    dh["amplitude"] = value_or_none(h.amplitude);
    dh["reversal_phase"] = value_or_none(h.reversal_phase);
    dh["peak_velocity"] = value_or_none(h.peak_velocity);
    dh["growth"] = value_or_none(h.growth);
    d["den_hartog"] = dh;
  } else {
    d["den_hartog"] = py::none();
  }
  d["model"] = model_dict(model);
  d["version"] = version;
  return d;
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
  m.def("classify", &classify_model, py::arg("model"), py::kw_only(),
        py::arg("max_periods") = 400, py::arg("simulate") = false,
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
