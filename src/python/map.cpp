// frictionref.map(): the steady state by simulation over a grid of two model
// parameters (the CLI's `map`, frictionref/parameter_map.hpp), with the
// CLI's checks and messages, and shards of the grid.
#include "frictionref/parameter_map.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include "arguments.hpp"
#include "errors.hpp"
#include "model.hpp"
#include "module.hpp"
#include "records.hpp"
#include "studies.hpp"

namespace frictionref::python {
namespace {

struct MapRow {
  double x, y, stops_per_period, reversals_per_period, stuck_fraction;
  std::uint64_t transient_periods;
  std::uint32_t multiplicity;
  char32_t regime[10];
};

py::dtype map_dtype(const MapAxis& x, const MapAxis& y) {
  return record_dtype({{column_name(x.parameter), "<f8", offsetof(MapRow, x)},
                       {column_name(y.parameter), "<f8", offsetof(MapRow, y)},
                       {"regime", "<U10", offsetof(MapRow, regime)},
                       {"stops_per_period", "<f8", offsetof(MapRow, stops_per_period)},
                       {"reversals_per_period", "<f8", offsetof(MapRow, reversals_per_period)},
                       {"multiplicity", "<u4", offsetof(MapRow, multiplicity)},
                       {"stuck_fraction", "<f8", offsetof(MapRow, stuck_fraction)},
                       {"transient_periods", "<u8", offsetof(MapRow, transient_periods)}},
                      sizeof(MapRow));
}

// "NAME:FROM:TO:POINTS" as the CLI takes it, or (NAME, FROM, TO, POINTS).
std::string axis_spec(py::handle object, const char* keyword) {
  if (PyUnicode_Check(object.ptr())) return object.cast<std::string>();
  if (!py::isinstance<py::tuple>(object) && !py::isinstance<py::list>(object))
    type_error(std::string(keyword) +
               " must be \"NAME:FROM:TO:POINTS\" or a tuple (NAME, FROM, TO, POINTS)");
  const py::sequence parts = py::reinterpret_borrow<py::sequence>(object);
  if (parts.size() != 4)
    type_error(std::string(keyword) + " must be a tuple (NAME, FROM, TO, POINTS), not one of " +
               std::to_string(parts.size()) + " items");
  if (!PyUnicode_Check(parts[0].ptr()))
    type_error(std::string(keyword) + "[0] must be the parameter's name, a str");
  const std::string name = keyword;
  return parts[0].cast<std::string>() + ":" + number(parts[1], name + "[1]").text + ":" +
         number(parts[2], name + "[2]").text + ":" + whole(parts[3], name + "[3]").text;
}

MapAxis axis(const std::string& spec, const std::string& option) {
  try {
    return MapAxis::parse(spec, option);
  } catch (const InvalidInput& error) {
    value_error(option + " = " + spec + ": " + error.rule());
  }
}

py::array parameter_map_of(py::handle x_object, py::handle y_object, py::handle periods_object,
                           py::handle threads_object, py::handle shard_object,
                           py::handle progress_object, py::kwargs kwargs) {
  py::dict rest(kwargs);
  const ModelInput input = take_model_input(rest, {/*friction_required=*/false});
  refuse_unknown(rest, "map");
  const Model base = build_model(input);
  // The CLI refuses a record here, before the axes (src/cli/map.cpp).
  refuse_record(base, "map",
                "it maps steady states, which a record (a transient) does not have "
                "(newmark runs records x yield accelerations)");
  const std::string x_spec = axis_spec(x_object, "x");
  const std::string y_spec = axis_spec(y_object, "y");
  const MapAxis x = axis(x_spec, "--x");
  const MapAxis y = axis(y_spec, "--y");
  if (x.parameter == y.parameter)
    value_error("--y = " + y_spec + ": must vary another parameter than --x");
  const double total_points = static_cast<double>(x.points) * static_cast<double>(y.points);
  char text[32];
  if (total_points > 1e7) {
    std::snprintf(text, sizeof text, "%.3g", total_points);
    value_error("--y = " + y_spec + ": with --x the map has " + text + " points, more than 10^7");
  }
  MapOptions options;
  const Number periods = whole(periods_object, "periods");
  options.classify.max_periods = whole_number(periods, "--periods", 1e6, "10^6");
  if (options.classify.max_periods < 2) value_error("--periods = " + periods.text + ": must be >= 2");
  const double total = total_points * static_cast<double>(options.classify.max_periods);
  if (total > 1e10) {
    std::snprintf(text, sizeof text, "%.3g", total);
    value_error("--periods = " + periods.text + ": the map could simulate " + text +
                " forcing periods, more than 10^10");
  }
  options.threads = threads(threads_object);
  options.shard = shard(shard_object);

  const auto report = progress(progress_object);
  std::vector<MapPoint> points;
  try {
    py::gil_scoped_release release;
    points = parameter_map(base, x, y, options, report);
  } catch (const InvalidInput& error) {
    // An axis that cannot apply to this model, or a corner of the grid that
    // makes an invalid model, named against its axis (as the CLI).
    const std::string p = error.parameter();
    const bool on_y = p == "y" || p == std::string(to_string(y.parameter));
    const bool on_x = p == "x" || p == std::string(to_string(x.parameter));
    if (on_x || on_y)
      value_error(std::string(on_x ? "--x" : "--y") + " = " + (on_x ? x_spec : y_spec) + ": " +
                  error.rule());
    if (p == "shard") value_error(input_message(error));
    value_error("the map's grid reaches an invalid model at a corner: " + p + " = " +
                error.value() + ": " + error.rule() +
                " (check --x and --y against the model options)");
  }
  std::vector<MapRow> rows(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const MapPoint& p = points[i];
    rows[i] = MapRow{p.x, p.y, p.stops_per_period, p.reversals_per_period, p.stuck_fraction,
                     p.transient_periods, p.multiplicity, {}};
    put_text(rows[i].regime, to_string(p.regime));
  }
  return records(std::move(rows), map_dtype(x, y));
}

}  // namespace

void bind_map(py::module_& m) {
  m.def("map", &parameter_map_of, py::arg("x"), py::arg("y"), py::kw_only(),
        py::arg("periods") = 200, py::arg("threads") = py::none(), py::arg("shard") = py::none(),
        py::arg("progress") = py::none(),
        R"doc(The steady state, by simulation, at every point of a grid of two model
parameters (the CLI's `map`): x and y as "NAME:FROM:TO:POINTS" or
(NAME, FROM, TO, POINTS), NAME one of lambda, static-ratio,
frequency-ratio, damping-ratio, mass, amplitude, omega, friction,
static-friction, stiffness, damping, force-offset, x0, v0. The other
parameters come from the model keywords (as Model(); friction is optional
here, default 0). periods (2 to 10^6) bounds the forcing periods simulated
per point; threads: None for all cores; shard=(I, N): only the I-th of N
contiguous blocks of the grid's points, x outer (the rows of the whole map
are the shards' rows in order, bit for bit); progress(done, total). The GIL
is released while it runs; Ctrl-C stops it.

Returns a structured array, x outer, with the CLI's columns: the two axes
(named as the parameters with '_' for '-', e.g. frequency_ratio), regime,
stops_per_period, reversals_per_period, multiplicity (0: no repetition
found), stuck_fraction, transient_periods.

    >>> m = frictionref.map("lambda:0.1:0.9:5", "frequency-ratio:0.5:2:4", stiffness=1)
    >>> m.dtype.names[:3]
    ('lambda', 'frequency_ratio', 'regime')
)doc");
}

}  // namespace frictionref::python
