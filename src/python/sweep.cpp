// frictionref.sweep(): for a grid of lambdas, the regime the simulation
// reaches against the closed form's, the stuck fraction, slide, stops and
// reversals per period (the CLI's `sweep`, frictionref/sweep.hpp), with the
// CLI's checks and messages.
#include "frictionref/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "arguments.hpp"
#include "errors.hpp"
#include "model.hpp"
#include "module.hpp"
#include "records.hpp"
#include "studies.hpp"

namespace frictionref::python {
namespace {

struct SweepRow {
  double lambda, stuck_fraction, slide_per_period;
  std::uint32_t stops_per_period, reversals_per_period;
  char32_t regime_simulated[10];
  char32_t regime_threshold[10];  // "n/a" where no closed form gives it
};

py::dtype sweep_dtype() {
  return record_dtype({{"lambda", "<f8", offsetof(SweepRow, lambda)},
                       {"regime_simulated", "<U10", offsetof(SweepRow, regime_simulated)},
                       {"regime_threshold", "<U10", offsetof(SweepRow, regime_threshold)},
                       {"stuck_fraction", "<f8", offsetof(SweepRow, stuck_fraction)},
                       {"slide_per_period", "<f8", offsetof(SweepRow, slide_per_period)},
                       {"stops_per_period", "<u4", offsetof(SweepRow, stops_per_period)},
                       {"reversals_per_period", "<u4", offsetof(SweepRow, reversals_per_period)}},
                      sizeof(SweepRow));
}

// lambda_from / lambda_to: finite, >= 0, <= 1e6.
double finite_lambda(const Number& n, const std::string& option) {
  if (!std::isfinite(n.value)) value_error(option + " = " + n.text + ": must be a finite number");
  if (!(n.value >= 0)) value_error(option + " = " + n.text + ": must be >= 0");
  if (!(n.value <= 1e6))
    value_error(option + " = " + n.text + ": must be <= 1e6 (every lambda >= 1 stops)");
  return n.value;
}

// The decimal in long double for the grid's interior points, as the CLI
// reads --lambda-from: the double itself where the long double would round
// to another double.
long double precise(const Number& n) {
  const long double wide = std::strtold(n.text.c_str(), nullptr);
  return static_cast<double>(wide) == n.value ? wide : static_cast<long double>(n.value);
}

// The model options the sweep sets itself, refused as the CLI refuses them.
void refuse_fixed(const py::dict& kwargs) {
  const struct {
    const char* keyword;
    const char* option;
  } fixed[] = {{"friction", "--friction"},
               {"lambda_", "--lambda"},
               {"lam", "--lambda"},
               {"lambda", "--lambda"},
               {"static_friction", "--static-friction"},
               {"static_lambda", "--static-lambda"},
               {"yield_accel", "--yield-accel"},
               {"t0", "--t0"}};
  for (const auto& f : fixed) {
    if (!kwargs.contains(f.keyword)) continue;
    const py::object value = kwargs[f.keyword];
    const std::string option = f.option;
    const std::string given =
        value.is_none() ? option : option + " = " + number(value, f.keyword).text;
    if (option == "--t0") value_error(given + ": not a sweep option; every run starts at t = 0");
    if (option == "--friction" || option == "--lambda" || option == "--yield-accel")
      value_error(given +
                  ": not a sweep option; the sweep sets R = lambda B for lambda from "
                  "--lambda-from to --lambda-to");
    value_error(given +
                ": not a sweep option; the sweep sets Rs = S R at every lambda, S from "
                "--static-ratio");
  }
}

py::array sweep_lambdas(py::handle lambdas_object, py::handle lambda_from, py::handle lambda_to,
                        py::handle points_object, py::handle static_ratio_object,
                        py::handle periods_object, py::handle threads_object,
                        py::handle shard_object, py::handle progress_object, py::kwargs kwargs) {
  py::dict rest(kwargs);
  refuse_fixed(rest);
  const ModelInput input = take_model_input(rest, {/*friction_required=*/false});
  refuse_unknown(rest, "sweep");
  const Model model = build_model(input);
  TypedInputs inputs = input.typed_inputs();

  const bool range = !lambda_from.is_none() || !lambda_to.is_none() || !points_object.is_none();
  if (range == !lambdas_object.is_none())
    type_error("sweep() takes either lambdas, or lambda_from, lambda_to and points");
  std::vector<double> grid;
  std::uint64_t points = 0;
  Number from, to, points_text;
  if (range) {
    if (lambda_from.is_none() || lambda_to.is_none() || points_object.is_none())
      type_error("sweep() needs lambda_from, lambda_to and points together");
    from = number(lambda_from, "lambda_from");
    to = number(lambda_to, "lambda_to");
    finite_lambda(from, "--lambda-from");
    finite_lambda(to, "--lambda-to");
    if (!(to.value >= from.value))
      value_error("--lambda-to = " + to.text + ": must be >= --lambda-from = " + from.text);
    points_text = whole(points_object, "points");
    points = whole_number(points_text, "--points", 1e7, "10^7");
    if (points == 1 && to.value != from.value)
      value_error("--points = " + points_text.text +
                  ": a single lambda needs --lambda-to = --lambda-from");
    if (points > 1 && to.value == from.value)
      value_error("--points = " + points_text.text +
                  ": must be 1 when --lambda-from = --lambda-to");
  } else {
    const py::array_t<double> array = float_array(lambdas_object, "lambdas");
    grid.assign(array.data(), array.data() + array.size());
    if (grid.empty()) value_error("lambdas: must hold at least one lambda");
    if (grid.size() > 10'000'000)
      value_error("lambdas: " + std::to_string(grid.size()) + " lambdas, more than 10^7");
    for (std::size_t i = 0; i < grid.size(); ++i)
      finite_lambda({grid[i], number_text(grid[i])}, "lambdas[" + std::to_string(i) + "]");
    points = grid.size();
    const double largest = *std::max_element(grid.begin(), grid.end());
    to = {largest, number_text(largest)};
    points_text = {static_cast<double>(points), std::to_string(points)};
  }
  const std::string to_option = range ? "--lambda-to" : "max(lambdas)";
  SweepOptions options;
  const Number periods = whole(periods_object, "periods");
  options.periods = whole_number(periods, "--periods",
                                 static_cast<double>(SweepOptions::max_periods), "10^6");
  const double total = static_cast<double>(points) * static_cast<double>(options.periods);
  if (total > 1e9) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", total);
    value_error("--periods = " + periods.text + ": with --points = " + points_text.text +
                " the sweep would simulate " + text + " forcing periods, more than 10^9");
  }
  options.threads = threads(threads_object);
  options.v0 = model.v0;
  options.base = model;
  options.base.v0 = 0;
  const Number static_ratio = number(static_ratio_object, "static_ratio");
  options.static_ratio = static_ratio.value;
  if (std::isfinite(options.static_ratio) && !(options.static_ratio <= 1e6))
    value_error("--static-ratio = " + static_ratio.text + ": must be <= 1e6");

  if (range) {
    inputs["lambda_from"] = {"--lambda-from", from.text};
    inputs["lambda_to"] = {"--lambda-to", to.text};
  }
  inputs["lambda"] = {to_option, to.text};
  inputs["friction"] = {to_option, to.text};  // R = lambda B beyond double
  inputs["static_ratio"] = {"--static-ratio", static_ratio.text};
  inputs["static_friction"] = {"--static-ratio", static_ratio.text};
  inputs["points"] = {"--points", points_text.text};
  inputs["periods"] = {"--periods", periods.text};
  naming(inputs, [&] { options.validate(); });
  const double speed_unit = model.amplitude / (model.mass * model.omega);
  if (!(std::fabs(options.v0) <= 1e6 * speed_unit))
    value_error("--v0 = " + inputs.at("v0").text + ": must satisfy |v0| <= 1e6 (in B/(m w))");
  const Shard part = shard(shard_object);
  if (range)
    grid = naming(inputs, [&] { return sweep_grid(precise(from), precise(to), points); });
  const Shard::Range block = part.range(grid.size());
  const std::vector<double> lambdas(grid.begin() + static_cast<std::ptrdiff_t>(block.begin),
                                    grid.begin() + static_cast<std::ptrdiff_t>(block.end));

  const auto report = progress(progress_object);
  std::vector<SweepPoint> results = naming(inputs, [&] {
    py::gil_scoped_release release;
    return sweep(lambdas, options, report);
  });
  std::vector<SweepRow> rows(results.size());
  for (std::size_t i = 0; i < results.size(); ++i) {
    const SweepPoint& p = results[i];
    if (p.termination != Termination::reached_end)
      throw std::runtime_error("internal error: the engine stopped early (" +
                               std::string(to_string(p.termination)) +
                               ") at lambda = " + number_text(p.lambda));
    SweepRow& row = rows[i];
    row = SweepRow{p.lambda, p.stuck_fraction, p.slide_per_period, p.stops_per_period,
                   p.reversals_per_period, {}, {}};
    put_text(row.regime_simulated, to_string(p.regime_simulated));
    put_text(row.regime_threshold, p.regime_threshold ? to_string(*p.regime_threshold) : "n/a");
  }
  return records(std::move(rows), sweep_dtype());
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def("sweep", &sweep_lambdas, py::arg("lambdas") = py::none(), py::kw_only(),
        py::arg("lambda_from") = py::none(), py::arg("lambda_to") = py::none(),
        py::arg("points") = py::none(), py::arg("static_ratio") = 1, py::arg("periods") = 100,
        py::arg("threads") = py::none(), py::arg("shard") = py::none(),
        py::arg("progress") = py::none(),
        R"doc(For each lambda = R / B: the regime the exact motion reaches in its last
forcing period against the regime a closed form gives, with the stuck
fraction, slide, stops and reversals per period (the CLI's `sweep`).

The lambdas: sweep(lambdas) with an array, or lambda_from=A, lambda_to=B,
points=N for A + (B - A) i / (N - 1) (in long double from the numbers as
given, rounded once: 0, 1.2, 13 points give exactly 0.1, 0.2, ...). Each
lambda runs the model of the keyword arguments (mass, amplitude, omega,
stiffness, damping, force_offset, harmonics, x0, v0; not friction, lambda,
static friction or t0, which the sweep sets) with R = lambda B,
Rs = static_ratio R, from t = 0 for `periods` forcing periods.
threads: worker threads (None: all cores); shard=(I, N): only the I-th of N
contiguous blocks of the lambdas; progress(done, total): called about ten
times a second. The GIL is released while it runs; Ctrl-C stops it.

Returns a structured array with the CLI's columns: lambda,
regime_simulated, regime_threshold ('n/a' where no closed form applies),
stuck_fraction, slide_per_period, stops_per_period, reversals_per_period.

    >>> s = frictionref.sweep(lambda_from=0, lambda_to=1.2, points=7)
    >>> list(s['regime_simulated'])
    ['continuous', 'continuous', 'continuous', 'dead-bands', 'dead-bands', 'stops', 'stops']
)doc");
}

}  // namespace frictionref::python
