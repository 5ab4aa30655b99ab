#include "frictionref/model_fields.hpp"

#include "frictionref/detail/number_text.hpp"

namespace frictionref {

std::string model_fields(const Model& model, std::string (*number)(double)) {
  if (number == nullptr) number = detail::shortest_text;
  std::string fields = "mass=" + number(model.mass) + " amplitude=" + number(model.amplitude) +
                       " omega=" + number(model.omega) + " friction=" + number(model.friction) +
                       " lambda=" + number(model.lambda());
  // The general model's fields where they differ from their defaults.
  if (model.static_friction) fields += " static_friction=" + number(*model.static_friction);
  if (model.stiffness != 0) fields += " stiffness=" + number(model.stiffness);
  if (model.damping != 0) fields += " damping=" + number(model.damping);
  if (model.force_offset != 0) fields += " force_offset=" + number(model.force_offset);
  for (const Harmonic& h : model.harmonics)
    fields += " harmonic=" + number(h.amplitude) + "," + number(h.omega) + "," + number(h.phase);
  fields += " x0=" + number(model.x0) + " v0=" + number(model.v0) + " t0=" + number(model.t0);
  // A ground motion: its file (the '# record' lines of a CSV say the rest).
  if (model.ground_motion)
    fields += " ground_accel=" + model.ground_motion->file +
              " sha256=" + model.ground_motion->sha256.substr(0, 16) +
              (model.one_way ? " one_way=true" : "");
  return fields;
}

}  // namespace frictionref
