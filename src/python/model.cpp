#include "model.hpp"

#include <pybind11/stl.h>

#include <optional>
#include <tuple>
#include <vector>

#include "arguments.hpp"
#include "errors.hpp"

namespace frictionref::python {
namespace {

// The keyword if given (and not None), removed from kwargs.
py::object take(py::dict& kwargs, const char* keyword) {
  if (!kwargs.contains(keyword)) return py::none();
  py::object value = kwargs[keyword];
  PyDict_DelItemString(kwargs.ptr(), keyword);
  return value;
}

std::optional<std::string> optional_text(const py::object& value, const std::string& keyword) {
  if (value.is_none()) return std::nullopt;
  return number(value, keyword).text;
}

void set_text(py::dict& kwargs, const char* keyword, std::string& text) {
  const py::object value = take(kwargs, keyword);
  if (!value.is_none()) text = number(value, keyword).text;
}

// "B,W[,PHI]": a string as the command line takes it, or a sequence of numbers.
std::string harmonic_text(py::handle item, std::size_t i) {
  const std::string name = "harmonics[" + std::to_string(i) + "]";
  if (PyUnicode_Check(item.ptr())) return item.cast<std::string>();
  if (!py::isinstance<py::sequence>(item) && !py::hasattr(item, "__len__"))
    type_error(name + " must be a tuple (B, W) or (B, W, PHI) of numbers, or the text \"B,W[,PHI]\"");
  std::string text;
  std::size_t k = 0;
  for (py::handle field : py::iter(item)) {
    text += (k ? "," : "") + number(field, name + "[" + std::to_string(k) + "]").text;
    ++k;
  }
  return text;
}

std::vector<std::string> harmonic_texts(const py::object& value) {
  std::vector<std::string> texts;
  if (value.is_none()) return texts;
  if (PyUnicode_Check(value.ptr()) || !py::hasattr(value, "__iter__"))
    type_error("harmonics must be a list of (B, W) or (B, W, PHI) tuples");
  std::size_t i = 0;
  for (py::handle item : py::iter(value)) texts.push_back(harmonic_text(item, i++));
  return texts;
}

// A path (the file system's bytes) as Python's str, as os.fsdecode gives it.
py::str path_text(const std::string& path) {
  return py::module_::import("os").attr("fsdecode")(py::bytes(path));
}

std::string repr(const PyModel& self) {
  const ModelInput& in = self.input;
  std::string out;
  const auto add = [&](const char* name, const std::string& text, const char* default_text) {
    if (default_text && text == default_text) return;
    out += (out.empty() ? "" : ", ") + std::string(name) + "=" + text;
  };
  const auto quoted = [](const py::str& text) { return py::repr(text).cast<std::string>(); };
  add("mass", in.mass, "1");
  // With a record, B defaults to 0.
  add("amplitude", in.amplitude, in.ground_accel ? "0" : "1");
  add("omega", in.omega, "1");
  if (in.friction) add("friction", *in.friction, nullptr);
  if (in.lambda) add("lambda_", *in.lambda, nullptr);
  if (in.yield_accel) add("yield_accel", *in.yield_accel, nullptr);
  if (in.static_friction) add("static_friction", *in.static_friction, nullptr);
  if (in.static_lambda) add("static_lambda", *in.static_lambda, nullptr);
  add("stiffness", in.stiffness, "0");
  add("damping", in.damping, "0");
  add("force_offset", in.force_offset, "0");
  if (!in.harmonics.empty()) {
    std::string list;
    for (const std::string& h : in.harmonics) list += (list.empty() ? "'" : ", '") + h + "'";
    add("harmonics", "[" + list + "]", nullptr);
  }
  add("x0", in.x0, "0");
  add("v0", in.v0, "0");
  add("t0", in.t0, "0");
  if (in.ground_accel) add("ground_accel", quoted(path_text(*in.ground_accel)), nullptr);
  if (in.record_dt) add("record_dt", *in.record_dt, nullptr);
  if (in.accel_units) add("accel_units", quoted(py::str(*in.accel_units)), nullptr);
  add("gravity", in.gravity, "9.80665");
  if (in.scale) add("scale", *in.scale, nullptr);
  if (in.target_pga) add("target_pga", *in.target_pga, nullptr);
  if (in.inverse) add("inverse", "True", nullptr);
  if (in.one_way) add("one_way", "True", nullptr);
  return "frictionref.Model(" + out + ")";
}

// The ground-motion keywords as given, and the SHA-256 of the record read
// (empty without one).
using RecordState =
    std::tuple<std::optional<py::bytes>, std::optional<std::string>, std::optional<std::string>,
               std::string, std::optional<std::string>, std::optional<std::string>, bool, bool,
               std::optional<std::string>, std::string>;

using State =
    std::tuple<std::string, std::string, std::string, std::optional<std::string>,
               std::optional<std::string>, std::optional<std::string>, std::optional<std::string>,
               std::string, std::string, std::string, std::vector<std::string>, std::string,
               std::string, std::string, RecordState>;

State state_of(const PyModel& model) {
  const ModelInput& in = model.input;
  std::optional<py::bytes> file;
  if (in.ground_accel) file = py::bytes(*in.ground_accel);
  const std::string sha256 = model.model.ground_motion ? model.model.ground_motion->sha256 : "";
  return std::make_tuple(
      in.mass, in.amplitude, in.omega, in.friction, in.lambda, in.static_friction, in.static_lambda,
      in.stiffness, in.damping, in.force_offset, in.harmonics, in.x0, in.v0, in.t0,
      std::make_tuple(file, in.record_dt, in.accel_units, in.gravity, in.scale, in.target_pga,
                      in.inverse, in.one_way, in.yield_accel, sha256));
}

// The model again from its keywords: a record's file is read again, and must
// still be the file that was read (its SHA-256).
PyModel model_of(const State& s) {
  ModelInput in;
  RecordState record;
  std::tie(in.mass, in.amplitude, in.omega, in.friction, in.lambda, in.static_friction,
           in.static_lambda, in.stiffness, in.damping, in.force_offset, in.harmonics, in.x0, in.v0,
           in.t0, record) = s;
  std::optional<py::bytes> file;
  std::string sha256;
  std::tie(file, in.record_dt, in.accel_units, in.gravity, in.scale, in.target_pga, in.inverse,
           in.one_way, in.yield_accel, sha256) = record;
  if (file) in.ground_accel = std::string(*file);
  PyModel model{build_model(in), in};
  if (model.model.ground_motion && model.model.ground_motion->sha256 != sha256)
    value_error("--ground-accel = " + model.model.ground_motion->file +
                ": is not the file the model was pickled with (SHA-256 " + sha256 + ", now " +
                model.model.ground_motion->sha256 + ")");
  return model;
}

// Equal records: the same samples (the motion; not the file's name).
bool same_record(const Model& a, const Model& b) {
  if (a.one_way != b.one_way) return false;
  if (!a.ground_motion || !b.ground_motion) return !a.ground_motion && !b.ground_motion;
  return a.ground_motion->t == b.ground_motion->t && a.ground_motion->a == b.ground_motion->a;
}

// The record as read: its samples and provenance (GroundMotion's fields).
py::object record_dict(const Model& model) {
  if (!model.ground_motion) return py::none();
  const GroundMotion& r = *model.ground_motion;
  py::dict d;
  d["file"] = path_text(r.file);
  d["sha256"] = r.sha256;
  d["format"] = r.format;
  py::list header;  // the file's own lines: not necessarily UTF-8
  for (const std::string& line : r.header)
    header.append(py::reinterpret_steal<py::str>(
        PyUnicode_DecodeUTF8(line.data(), static_cast<py::ssize_t>(line.size()), "replace")));
  d["header"] = header;
  d["npts"] = r.npts;
  d["dt"] = r.dt ? py::cast(*r.dt) : py::none();
  d["units"] = std::string(to_string(r.units));
  d["pga_as_read"] = r.pga_as_read;
  d["gravity"] = r.gravity;
  d["factor"] = r.factor;
  d["scaling"] = r.scaling;
  d["notes"] = r.notes;
  d["t"] = py::array_t<double>(static_cast<py::ssize_t>(r.t.size()), r.t.data());
  d["a"] = py::array_t<double>(static_cast<py::ssize_t>(r.a.size()), r.a.data());
  return d;
}

const char* model_doc = R"doc(The physical model (docs/theory.md 1 and 7), built from keyword arguments:

    m x'' + c x' + k x = F(t) - R sign(v),
    F(t) = F0 + B sin(w t) + sum_i B_i sin(w_i t + phi_i),

from (x0, v0) at t0; at rest while |F(t) - k x| <= Rs.

Keywords (the command line's model options, docs/cli.md):
    mass (m, > 0, default 1), amplitude (B, >= 0, default 1), omega (w, > 0,
    default 1), friction (R, >= 0) or lambda_ (R / B; also lam, or
    **{"lambda": L}), exactly one; static_friction (Rs >= R) or static_lambda
    (Rs / B), at most one; stiffness (k, >= 0), damping (c, >= 0),
    force_offset (F0), harmonics (a list of (B_i, w_i) or (B_i, w_i, phi_i),
    or "B,W[,PHI]" strings), x0, v0, t0 (default 0).

A recorded ground motion (docs/theory.md 9; the CLI's "Ground-motion
records"), entering as the force -m a_g(t), x and v then relative to the
ground: ground_accel (the file: PEER .AT2, a time-acceleration table, or
one column with record_dt), record_dt, accel_units ('g', 'm/s2', 'cm/s2',
'ft/s2', 'in/s2'), gravity (standard gravity in the length unit wanted,
default 9.80665: metres), scale or target_pga (in g), inverse (the record
negated), one_way (the downslope block); yield_accel (KY in g, R = m KY g)
instead of friction or lambda_. With a record amplitude defaults to 0.

Invalid values raise ValueError with the command line's message, e.g.
Model(mass=-1, lambda_=0.7) -> ValueError("--mass = -1: must be > 0").
A Model is immutable, comparable and picklable (a record is pickled as its
keywords and SHA-256: unpickling reads the file again, which must be
unchanged).

Example:
    >>> model = frictionref.Model(lambda_=0.7)
    >>> model.friction, model.is_seed
    (0.7, True)
)doc";

}  // namespace

ModelInput take_model_input(py::dict& kwargs, const ModelKeywords& keywords) {
  ModelInput input;
  input.friction_required = keywords.friction_required;
  set_text(kwargs, "mass", input.mass);
  const bool amplitude_given = kwargs.contains("amplitude") && !kwargs["amplitude"].is_none();
  set_text(kwargs, "amplitude", input.amplitude);
  set_text(kwargs, "omega", input.omega);
  input.friction = optional_text(take(kwargs, "friction"), "friction");
  // `lambda` is a Python keyword: lambda_, lam, or **{"lambda": ...}.
  std::optional<std::string> lambda;
  const char* lambda_keyword = nullptr;
  for (const char* keyword : {"lambda_", "lam", "lambda"}) {
    const py::object value = take(kwargs, keyword);
    if (value.is_none()) continue;
    if (lambda_keyword)
      type_error(std::string("give one of ") + lambda_keyword + " and " + keyword + ", not both");
    lambda_keyword = keyword;
    lambda = number(value, keyword).text;
  }
  input.lambda = lambda;
  input.static_friction = optional_text(take(kwargs, "static_friction"), "static_friction");
  input.static_lambda = optional_text(take(kwargs, "static_lambda"), "static_lambda");
  set_text(kwargs, "stiffness", input.stiffness);
  set_text(kwargs, "damping", input.damping);
  set_text(kwargs, "force_offset", input.force_offset);
  input.harmonics = harmonic_texts(take(kwargs, "harmonics"));
  set_text(kwargs, "x0", input.x0);
  set_text(kwargs, "v0", input.v0);
  set_text(kwargs, "t0", input.t0);
  // A ground motion (docs/cli.md "Ground-motion records"): the record's file
  // and how to read it, as the command line's options.
  const py::object ground_accel = take(kwargs, "ground_accel");
  if (!ground_accel.is_none()) {
    input.ground_accel = path(ground_accel, "ground_accel", "--ground-accel");
    // The record drives the block by itself unless a harmonic is asked for.
    if (!amplitude_given) input.amplitude = "0";
  }
  input.record_dt = optional_text(take(kwargs, "record_dt"), "record_dt");
  const py::object units = take(kwargs, "accel_units");
  if (!units.is_none()) {
    if (!PyUnicode_Check(units.ptr()))
      type_error("accel_units must be a str (g, m/s2, cm/s2, ft/s2 or in/s2), not " +
                 py::str(py::type::handle_of(units).attr("__name__")).cast<std::string>());
    input.accel_units = units.cast<std::string>();
  }
  set_text(kwargs, "gravity", input.gravity);
  input.scale = optional_text(take(kwargs, "scale"), "scale");
  input.target_pga = optional_text(take(kwargs, "target_pga"), "target_pga");
  const py::object inverse = take(kwargs, "inverse");
  input.inverse = !inverse.is_none() && flag(inverse, "inverse");
  const py::object one_way = take(kwargs, "one_way");
  input.one_way = !one_way.is_none() && flag(one_way, "one_way");
  input.yield_accel = optional_text(take(kwargs, "yield_accel"), "yield_accel");
  // The command line refuses these pairs while parsing (CLI11's wording).
  if (input.friction && input.lambda) value_error("--friction excludes --lambda");
  if (input.static_friction && input.static_lambda)
    value_error("--static-friction excludes --static-lambda");
  if (input.yield_accel && input.friction) value_error("--friction excludes --yield-accel");
  if (input.yield_accel && input.lambda) value_error("--lambda excludes --yield-accel");
  if (input.scale && input.target_pga) value_error("--scale excludes --target-pga");
  return input;
}

Model build_model(const ModelInput& input) {
  try {
    if (!input.ground_accel) return input.model();
    // Reading the record's file may take a while: without the GIL.
    py::gil_scoped_release release;
    return input.model();
  } catch (const InvalidInput& error) {
    value_error(input_message(error));
  }
}

void refuse_record(const Model& model, const std::string& command, const std::string& why) {
  if (model.ground_motion)
    value_error("--ground-accel = " + model.ground_motion->file + ": is not taken by " + command +
                ": " + why);
}

void refuse_unknown(const py::dict& kwargs, const std::string& function) {
  for (const auto& item : kwargs)
    type_error(function + "() got an unexpected keyword argument '" +
               py::str(item.first).cast<std::string>() + "'");
}

py::dict model_dict(const Model& model) {
  py::dict d;
  d["mass"] = model.mass;
  d["amplitude"] = model.amplitude;
  d["omega"] = model.omega;
  d["friction"] = model.friction;
  d["lambda"] = model.lambda();
  d["static_friction"] = model.static_friction ? py::cast(*model.static_friction) : py::none();
  d["stiffness"] = model.stiffness;
  d["damping"] = model.damping;
  d["force_offset"] = model.force_offset;
  py::list harmonics;
  for (const Harmonic& h : model.harmonics)
    harmonics.append(py::make_tuple(h.amplitude, h.omega, h.phase));
  d["harmonics"] = harmonics;
  d["x0"] = model.x0;
  d["v0"] = model.v0;
  d["t0"] = model.t0;
  return d;
}

void bind_model(py::module_& m) {
  py::class_<PyModel>(m, "Model", model_doc)
      .def(py::init([](py::kwargs kwargs) {
             py::dict rest(kwargs);
             ModelInput input = take_model_input(rest, {});
             refuse_unknown(rest, "Model");
             return PyModel{build_model(input), input};
           }),
           "Model(**keywords): see the class documentation.")
      .def_property_readonly("mass", [](const PyModel& s) { return s.model.mass; }, "m")
      .def_property_readonly("amplitude", [](const PyModel& s) { return s.model.amplitude; },
                             "B, the amplitude of B sin(w t)")
      .def_property_readonly("omega", [](const PyModel& s) { return s.model.omega; },
                             "w, the angular frequency of B sin(w t)")
      .def_property_readonly("friction", [](const PyModel& s) { return s.model.friction; },
                             "R, the sliding friction force")
      .def_property_readonly("lambda_", [](const PyModel& s) { return s.model.lambda(); },
                             "R / B (inf when B = 0 < R, nan when B = R = 0)")
      .def_property_readonly(
          "static_friction",
          [](const PyModel& s) -> py::object {
            return s.model.static_friction ? py::cast(*s.model.static_friction) : py::none();
          },
          "Rs, the static friction force; None when not set (then Rs = R)")
      .def_property_readonly("stiffness", [](const PyModel& s) { return s.model.stiffness; }, "k")
      .def_property_readonly("damping", [](const PyModel& s) { return s.model.damping; }, "c")
      .def_property_readonly("force_offset",
                             [](const PyModel& s) { return s.model.force_offset; }, "F0")
      .def_property_readonly(
          "harmonics",
          [](const PyModel& s) {
            py::list out;
            for (const Harmonic& h : s.model.harmonics)
              out.append(py::make_tuple(h.amplitude, h.omega, h.phase));
            return out;
          },
          "the extra terms of F(t) as (B_i, w_i, phi_i) tuples")
      .def_property_readonly("x0", [](const PyModel& s) { return s.model.x0; }, "initial position")
      .def_property_readonly("v0", [](const PyModel& s) { return s.model.v0; }, "initial velocity")
      .def_property_readonly("t0", [](const PyModel& s) { return s.model.t0; }, "initial time")
      .def_property_readonly(
          "is_seed", [](const PyModel& s) { return s.model.is_harmonic_coulomb(); },
          "True for the seed's model m x'' = B sin(w t) - R sign(v) (no spring, damper, "
          "offset, extra harmonics; Rs = R)")
      .def_property_readonly(
          "ground_accel",
          [](const PyModel& s) -> py::object {
            return s.input.ground_accel ? py::object(path_text(*s.input.ground_accel)) : py::none();
          },
          "the record's file as given (None without a record)")
      .def_property_readonly("one_way", [](const PyModel& s) { return s.model.one_way; },
                             "True for the one-way (downslope) block")
      .def_property_readonly(
          "record", [](const PyModel& s) { return record_dict(s.model); },
          "The record as read (None without one), a dict: t and a (numpy arrays, a in the "
          "length unit of gravity per s^2, scaled and signed), file, sha256, format, header, "
          "npts, dt (None for a table of times), units, pga_as_read (in units), gravity, "
          "factor (a = factor * the file's value), scaling, notes.")
      .def(
          "to_dict",
          [](const PyModel& s) {
            py::dict d = model_dict(s.model);
            if (s.model.ground_motion) {
              d["ground_accel"] = path_text(s.model.ground_motion->file);
              d["record_sha256"] = s.model.ground_motion->sha256;
              d["one_way"] = s.model.one_way;
            }
            return d;
          },
          "The model as a dict: the `model` object of the command line's JSON outputs (with a "
          "record also ground_accel, record_sha256 and one_way).")
      .def("__repr__", &repr)
      .def("__eq__",
           [](const PyModel& a, py::object other) -> py::object {
             if (!py::isinstance<PyModel>(other))
               return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             const Model& b = other.cast<const PyModel&>().model;
             return py::bool_(model_dict(a.model).equal(model_dict(b)) && same_record(a.model, b));
           })
      .def("__hash__",
           [](const PyModel& s) {
             const std::size_t samples =
                 s.model.ground_motion ? s.model.ground_motion->samples() : 0;
             return py::hash(py::make_tuple(s.model.mass, s.model.amplitude, s.model.omega,
                                            s.model.friction, s.model.x0, s.model.v0, s.model.t0,
                                            s.model.one_way, samples));
           })
      .def(py::pickle(&state_of, &model_of));
}

}  // namespace frictionref::python
