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

std::string repr(const PyModel& self) {
  const ModelInput& in = self.input;
  std::string out;
  const auto add = [&](const char* name, const std::string& text, const char* default_text) {
    if (default_text && text == default_text) return;
    out += (out.empty() ? "" : ", ") + std::string(name) + "=" + text;
  };
  add("mass", in.mass, "1");
  add("amplitude", in.amplitude, "1");
  add("omega", in.omega, "1");
  if (in.friction) add("friction", *in.friction, nullptr);
  if (in.lambda) add("lambda_", *in.lambda, nullptr);
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
  return "frictionref.Model(" + out + ")";
}

using State = std::tuple<std::string, std::string, std::string, std::optional<std::string>,
                         std::optional<std::string>, std::optional<std::string>,
                         std::optional<std::string>, std::string, std::string, std::string,
                         std::vector<std::string>, std::string, std::string, std::string>;

State state_of(const ModelInput& in) {
  return {in.mass,      in.amplitude, in.omega,        in.friction,  in.lambda,
          in.static_friction, in.static_lambda, in.stiffness, in.damping, in.force_offset,
          in.harmonics, in.x0,        in.v0,           in.t0};
}

ModelInput input_of(const State& s) {
  ModelInput in;
  std::tie(in.mass, in.amplitude, in.omega, in.friction, in.lambda, in.static_friction,
           in.static_lambda, in.stiffness, in.damping, in.force_offset, in.harmonics, in.x0,
           in.v0, in.t0) = s;
  return in;
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

Invalid values raise ValueError with the command line's message, e.g.
Model(mass=-1, lambda_=0.7) -> ValueError("--mass = -1: must be > 0").
A Model is immutable, comparable and picklable.

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
  // The command line refuses these pairs while parsing (CLI11's wording).
  if (input.friction && input.lambda) value_error("--friction excludes --lambda");
  if (input.static_friction && input.static_lambda)
    value_error("--static-friction excludes --static-lambda");
  return input;
}

Model build_model(const ModelInput& input) {
  try {
    return input.model();
  } catch (const InvalidInput& error) {
    value_error(input_message(error));
  }
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
      .def("to_dict", [](const PyModel& s) { return model_dict(s.model); },
           "The model as a dict: the `model` object of the command line's JSON outputs.")
      .def("__repr__", &repr)
      .def("__eq__",
           [](const PyModel& a, py::object other) -> py::object {
             if (!py::isinstance<PyModel>(other)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::bool_(model_dict(a.model).equal(model_dict(other.cast<const PyModel&>().model)));
           })
      .def("__hash__",
           [](const PyModel& s) {
             return py::hash(py::make_tuple(s.model.mass, s.model.amplitude, s.model.omega,
                                            s.model.friction, s.model.x0, s.model.v0, s.model.t0));
           })
      .def(py::pickle([](const PyModel& s) { return state_of(s.input); },
                      [](const State& state) {
                        const ModelInput input = input_of(state);
                        return PyModel{build_model(input), input};
                      }));
}

}  // namespace frictionref::python
