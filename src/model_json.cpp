#include "model_json.hpp"

#include "frictionref/model_json.hpp"

namespace frictionref {

nlohmann::ordered_json detail::model_json(const Model& model) {
  nlohmann::ordered_json json = {{"mass", model.mass},
                                 {"amplitude", model.amplitude},
                                 {"omega", model.omega},
                                 {"friction", model.friction},
                                 {"lambda", model.lambda()}};
  if (model.static_friction) {
    json["static_friction"] = *model.static_friction;
  } else {
    json["static_friction"] = nullptr;
  }
  json["stiffness"] = model.stiffness;
  json["damping"] = model.damping;
  json["force_offset"] = model.force_offset;
  json["harmonics"] = nlohmann::ordered_json::array();
  for (const Harmonic& h : model.harmonics)
    json["harmonics"].push_back({h.amplitude, h.omega, h.phase});
  json["x0"] = model.x0;
  json["v0"] = model.v0;
  json["t0"] = model.t0;
  return json;
}

std::string model_json_text(const Model& model) { return detail::model_json(model).dump(); }

}  // namespace frictionref
