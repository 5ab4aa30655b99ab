// frictionref.newmark(): Newmark's sliding block on ground-motion records,
// the permanent displacement for every record x yield acceleration x
// polarity (the CLI's `newmark`, frictionref/newmark.hpp), with the CLI's
// checks, in its order, and its messages.
#include "frictionref/newmark.hpp"

#include <pybind11/numpy.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "arguments.hpp"
#include "errors.hpp"
#include "frictionref/model_input.hpp"
#include "module.hpp"
#include "studies.hpp"

namespace frictionref::python {
namespace {

std::string type_name(py::handle object) {
  return py::str(py::type::handle_of(object).attr("__name__")).cast<std::string>();
}

bool is_path(py::handle object) {
  return PyUnicode_Check(object.ptr()) || PyBytes_Check(object.ptr()) ||
         py::isinstance(object, py::module_::import("os").attr("PathLike"));
}

// One path or a sequence of them (--record, repeated).
std::vector<std::string> record_paths(py::handle object) {
  std::vector<std::string> paths;
  if (is_path(object)) {
    paths.push_back(path(object, "records", "--record"));
    return paths;
  }
  if (!py::hasattr(object, "__iter__"))
    type_error("records must be a path or a list of paths, not " + type_name(object));
  std::size_t i = 0;
  for (py::handle item : py::iter(object)) {
    paths.push_back(path(item, "records[" + std::to_string(i) + "]", "--record"));
    ++i;
  }
  return paths;
}

// One number or a sequence of them (--yield-accel KY[,KY...]), as typed.
std::vector<Number> yield_numbers(py::handle object) {
  std::vector<Number> numbers;
  if (PyUnicode_Check(object.ptr()) || PyBytes_Check(object.ptr()) ||
      !py::hasattr(object, "__iter__")) {
    numbers.push_back(number(object, "yield_accel"));
    return numbers;
  }
  std::size_t i = 0;
  for (py::handle item : py::iter(object)) {
    numbers.push_back(number(item, "yield_accel[" + std::to_string(i) + "]"));
    ++i;
  }
  return numbers;
}

// The CLI's yield_values(): the count, then each value.
std::vector<double> yield_values(const std::vector<Number>& numbers, NewmarkMethod method) {
  // None given: CLI11's word for a required option left out.
  if (numbers.empty()) value_error("--yield-accel is required");
  if (numbers.size() > NewmarkLimits::yield_values)
    value_error("--yield-accel: " + std::to_string(numbers.size()) + " values given, at most " +
                std::to_string(NewmarkLimits::yield_values));
  std::vector<double> values;
  for (const Number& ky : numbers) {
    if (const std::string rule = yield_accel_rule(ky.value, method); !rule.empty())
      value_error("--yield-accel = " + ky.text + ": " + rule);
    values.push_back(ky.value);
  }
  return values;
}

std::string text_keyword(py::handle object, const char* keyword, const char* choices) {
  if (!PyUnicode_Check(object.ptr()))
    type_error(std::string(keyword) + " must be a str (" + choices + "), not " + type_name(object));
  return object.cast<std::string>();
}

// A numpy array of str from `texts` (the dtype as long as the longest).
py::array text_column(const py::list& texts) {
  return py::module_::import("numpy").attr("array")(texts, "str");
}

py::dict newmark(py::handle records_object, py::handle yield_object, py::handle scale_object,
                 py::handle target_pga_object, py::handle record_dt_object,
                 py::handle accel_units_object, py::handle gravity_object,
                 py::handle one_way_object, py::handle polarity_object, py::handle method_object,
                 py::handle threads_object, py::handle progress_object) {
  // The arguments' types first (the command line's parser), then the CLI's
  // checks in its order.
  const std::vector<std::string> paths = record_paths(records_object);
  const std::vector<Number> yield_typed = yield_numbers(yield_object);
  ModelInput input;
  input.record_option = "--record";
  if (!scale_object.is_none()) input.scale = number(scale_object, "scale").text;
  if (!target_pga_object.is_none()) input.target_pga = number(target_pga_object, "target_pga").text;
  if (!record_dt_object.is_none()) input.record_dt = number(record_dt_object, "record_dt").text;
  if (!accel_units_object.is_none())
    input.accel_units =
        text_keyword(accel_units_object, "accel_units", "g, m/s2, cm/s2, ft/s2 or in/s2");
  input.gravity = number(gravity_object, "gravity").text;
  NewmarkOptions options;
  options.one_way = flag(one_way_object, "one_way");
  const std::string polarity =
      text_keyword(polarity_object, "polarity", "'normal', 'inverse' or 'both'");
  const std::string method = text_keyword(method_object, "method", "'exact' or 'slammer'");
  // The command line refuses these while parsing (CLI11's wording).
  if (paths.empty()) value_error("--record is required");
  if (input.scale && input.target_pga) value_error("--scale excludes --target-pga");
  if (polarity == "inverse") {
    options.polarities = {Polarity::inverse};
  } else if (polarity == "both") {
    options.polarities = {Polarity::normal, Polarity::inverse};
  } else if (polarity != "normal") {
    value_error("polarity = " + polarity +
                ": must be normal, inverse (--inverse) or both (--both-polarities)");
  }

  const std::optional<NewmarkMethod> chosen = newmark_method_from_string(method);
  if (!chosen) value_error("--method = " + method + ": must be exact or slammer");
  options.method = *chosen;
  options.yield_accels_g = yield_values(yield_typed, options.method);
  options.threads = threads(threads_object);
  const double runs = static_cast<double>(paths.size()) *
                      static_cast<double>(options.yield_accels_g.size()) *
                      static_cast<double>(options.polarities.size());
  if (runs > NewmarkLimits::runs) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", runs);
    value_error("--yield-accel: " + std::to_string(paths.size()) + " records x " +
                std::to_string(options.yield_accels_g.size()) + " yield values x " +
                std::to_string(options.polarities.size()) + " polarities = " + text +
                " runs, more than 10^7");
  }
  if (paths.size() > NewmarkLimits::records)
    value_error("--record: " + std::to_string(paths.size()) + " files given, at most " +
                std::to_string(NewmarkLimits::records));

  // Set with the GIL: the callback holds a Python object.
  options.progress = progress(progress_object);
  std::vector<std::shared_ptr<const GroundMotion>> records;
  std::vector<NewmarkResult> results;
  double gravity = 0;
  try {
    py::gil_scoped_release release;
    for (const std::string& file : paths) {
      input.ground_accel = file;
      records.push_back(input.record());
    }
    gravity = input.gravity_value();
    if (options.method == NewmarkMethod::slammer) {
      for (const auto& record : records) {
        if (!record->dt)
          throw InvalidInput("--record", record->file,
                             "has no uniform step (a table of times); --method slammer "
                             "integrates at the record's step: give an .AT2 file, or one column "
                             "with --record-dt");
      }
    }
    results = newmark_batch(records, options);
  } catch (const InvalidInput& error) {
    value_error(input_message(error));
  } catch (const py::error_already_set&) {
    throw;
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(std::string("internal error: ") + error.what());
  }

  py::list record, sha256, polarities, methods;
  const auto n = static_cast<py::ssize_t>(results.size());
  py::array_t<double> yield_accel_g(n), pga_g(n), at_end(n), permanent(n), max_velocity(n);
  py::array_t<std::int64_t> slip_episodes(n);
  const std::size_t per_record = results.size() / records.size();
  const py::module_ os = py::module_::import("os");
  for (std::size_t i = 0; i < results.size(); ++i) {
    const NewmarkResult& r = results[i];
    const GroundMotion& read = *records[i / per_record];
    const auto k = static_cast<py::ssize_t>(i);
    record.append(os.attr("fsdecode")(py::bytes(r.record)));
    sha256.append(read.sha256);
    yield_accel_g.mutable_at(k) = r.yield_accel_g;
    pga_g.mutable_at(k) = read.pga() / read.gravity;
    polarities.append(std::string(to_string(r.polarity)));
    methods.append(std::string(to_string(r.method)));
    at_end.mutable_at(k) = r.displacement_at_record_end;
    permanent.mutable_at(k) = r.permanent_displacement ? *r.permanent_displacement : std::nan("");
    slip_episodes.mutable_at(k) = static_cast<std::int64_t>(r.slip_episodes);
    max_velocity.mutable_at(k) = r.max_relative_velocity;
  }
  py::list units;
  for (std::size_t i = 0; i < results.size(); ++i) units.append(length_unit_of_gravity(gravity));
  py::dict out;
  out["record"] = text_column(record);
  out["record_sha256"] = text_column(sha256);
  out["yield_accel_g"] = yield_accel_g;
  out["pga_g"] = pga_g;
  out["polarity"] = text_column(polarities);
  out["method"] = text_column(methods);
  out["displacement_at_record_end"] = at_end;
  out["permanent_displacement"] = permanent;
  out["slip_episodes"] = slip_episodes;
  out["max_relative_velocity"] = max_velocity;
  out["length_unit"] = text_column(units);
  return out;
}

}  // namespace

void bind_newmark(py::module_& m) {
  m.def("newmark", &newmark, py::arg("records"), py::arg("yield_accel"), py::kw_only(),
        py::arg("scale") = py::none(), py::arg("target_pga") = py::none(),
        py::arg("record_dt") = py::none(), py::arg("accel_units") = py::none(),
        py::arg("gravity") = 9.80665, py::arg("one_way") = true, py::arg("polarity") = "normal",
        py::arg("method") = "exact", py::arg("threads") = py::none(),
        py::arg("progress") = py::none(),
        R"doc(Newmark's sliding block (the CLI's `newmark`; docs/theory.md 9): for
every record x yield acceleration x polarity, the displacement of a rigid
block relative to the ground, exact (the record linear between its
samples) or by SLAMMER's algorithm, on all cores.

records: a file or a list of files (PEER .AT2, a time-acceleration table,
or one column with record_dt), read as Model's ground_accel with
record_dt, accel_units, gravity (the length unit of the results: 9.80665
gives metres) and scale or target_pga [g]. yield_accel: KY [g], a number
or a list (finite, >= 0; > 0 with method='slammer'). one_way=True is the
downslope block (False: the CLI's --two-way); polarity 'normal' (the record
as given), 'inverse' (negated) or 'both'; method 'exact' or 'slammer'
(SLAMMER 1.1's trapezoidal rigid block, a numerical peer; it needs a
uniform step). threads: None for all cores; progress(done, total). The GIL
is released while it runs; Ctrl-C stops it.

Displacements are positive downslope (SLAMMER's convention, Jibson 1993).
Returns a dict of numpy arrays, one entry per run (records, then KY, then
polarity), with the keys of `newmark --json`: record, record_sha256,
yield_accel_g, pga_g, polarity, method, displacement_at_record_end,
permanent_displacement (nan where the JSON has null: the block never comes
to rest, KY = 0), slip_episodes, max_relative_velocity, length_unit.

    >>> r = frictionref.newmark("data/records/synthetic/pulse-train.AT2", [0.05, 0.1])
    >>> r['permanent_displacement']
    array([0.53426789, 0.25102161])
)doc");
}

}  // namespace frictionref::python
