// frictionref.Model: the model from keyword arguments, by the command line's
// rules and messages (ModelInput), immutable once built.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "frictionref/model.hpp"
#include "frictionref/model_input.hpp"

namespace frictionref::python {

namespace py = pybind11;

struct PyModel {
  Model model;       // validated
  ModelInput input;  // as given, for messages, repr and pickling
};

// What a command takes of the model options (the CLI's ModelOptions::Selection).
struct ModelKeywords {
  bool friction_required = true;  // neither friction nor lambda: refused (else R = 0)
};

// Takes the model's keywords out of `kwargs` (what is left is the caller's)
// and gives them as text. TypeError for a wrong type; ValueError for two
// spellings of one option ("--friction excludes --lambda", as the CLI).
ModelInput take_model_input(py::dict& kwargs, const ModelKeywords& keywords);

// The validated model of `input`: ValueError with the CLI's message. A
// record's file is read without the GIL.
Model build_model(const ModelInput& input);

// ValueError "--ground-accel = FILE: is not taken by <command>: <why>" if the
// model has a record: the CLI's refuse_ground_motion (src/cli/model_options.hpp),
// for the commands that refuse one before the library would.
void refuse_record(const Model& model, const std::string& command, const std::string& why);

// TypeError for any keyword left in `kwargs`, naming `function`.
void refuse_unknown(const py::dict& kwargs, const std::string& function);

// The model as a dict, the `model` object of the CLI's JSON outputs.
py::dict model_dict(const Model& model);

}  // namespace frictionref::python
