// The model in one line, for figure titles.
#include "model_title.hpp"

#include <fmt/format.h>

namespace frictionref::cli {

std::string model_title(const Model& model) {
  std::string title = fmt::format("m={} B={} w={} R={}", model.mass, model.amplitude, model.omega,
                                  model.friction);
  if (model.amplitude > 0) title += fmt::format(" (lambda={})", model.lambda());
  // The general model's terms where they differ from their defaults (a
  // figure of a general model must say which model it shows).
  if (model.static_friction) title += fmt::format(" Rs={}", *model.static_friction);
  if (model.stiffness != 0) title += fmt::format(" k={}", model.stiffness);
  if (model.damping != 0) title += fmt::format(" c={}", model.damping);
  if (model.force_offset != 0) title += fmt::format(" F0={}", model.force_offset);
  for (const Harmonic& h : model.harmonics)
    title += h.phase == 0 ? fmt::format(" +{} sin({} t)", h.amplitude, h.omega)
                          : fmt::format(" +{} sin({} t + {})", h.amplitude, h.omega, h.phase);
  return title + fmt::format(" x0={} v0={} t0={}", model.x0, model.v0, model.t0);
}

}  // namespace frictionref::cli
