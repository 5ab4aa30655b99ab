// Links against the installed library and runs the seed's dead-band case.
#include <frictionref/frictionref.hpp>

#include <cstdio>

int main() {
  frictionref::Model model;
  model.friction = 0.7;
  const auto solution = frictionref::solve(model, 30.0);
  const bool dead_bands = frictionref::steady_state(model).regime == frictionref::Regime::dead_bands;
  std::printf("frictionref %s: %zu phases, dead bands: %s\n", frictionref::version,
              solution.phases.size(), dead_bands ? "yes" : "no");
  return dead_bands && solution.summary.count(frictionref::PhaseKind::stick) > 0 ? 0 : 1;
}
