// Den Hartog's (1931) exact non-stop periodic solution of the forced Coulomb
// oscillator with a spring and no viscous damping (docs/theory.md 8.2):
//
//   m x'' + k x = B sin(w t) - R sign(v),   static friction Rs >= R,
//
// a motion that reverses twice per forcing period without ever sticking,
// antisymmetric (x(t + pi/w) = -x(t)), with amplitude
//
//   X = (B / k) sqrt(V^2 - (R/B)^2 U^2),  V = 1 / (1 - beta^2),
//   U = (1/beta) tan(pi / (2 beta)),      beta = w / sqrt(k / m).
//
// It is a motion only where it exists (V^2 > (R/B)^2 U^2), where the net
// force at each reversal beats static friction (beta^2 X k > Rs, so the mass
// does not stick there), and where the velocity keeps its sign between the
// reversals; den_hartog() checks all three, the last with the certified
// zero search of the engine. It is the steady state only where it is also
// stable: den_hartog() linearises the exact half-cycle map (reversal to
// reversal, folded by the symmetry) with the engine, and the solution is
// stable when both eigenvalues lie inside the unit circle. (It is not at
// beta = 1/2, R = 0.2 B, for instance: from rest the mass settles into a
// motion with a stop per period instead; docs/theory.md 8.2.)
#pragma once

#include <string>

#include "frictionref/model.hpp"

namespace frictionref {

struct DenHartogSolution {
  bool non_stop = false;      // all three conditions hold: a periodic non-stop motion exists
  bool stable = false;        // ... and it attracts the motions near it: growth <= 1 - 1e-6
  double growth = 0;          // spectral radius of the linearised half-cycle map (when non_stop)
  std::string failed;         // the condition that fails, in words ("" when non_stop and stable)
  double frequency_ratio = 0; // beta = w / sqrt(k / m) [1]
  double amplitude = 0;       // X [length]; NaN when the solution does not exist
  double reversal_phase = 0;  // forcing phase w t mod 2 pi of the forward reversal (x = -X) [rad]
  double peak_velocity = 0;   // max |v| over the period [length / time]; NaN when it does not exist
};

// True where the closed form applies: k > 0, c = 0, F0 = 0, B > 0 and no
// extra harmonics (any R >= 0, Rs >= R).
bool den_hartog_applies(const Model& model);

// Requires a valid model where den_hartog_applies(); throws InvalidInput
// naming the first field that keeps it from applying.
DenHartogSolution den_hartog(const Model& model);

// The largest lambda = R / B for which the non-stop motion exists at
// frequency ratio beta = w / sqrt(k/m), with Rs = static_ratio * R
// (static_ratio >= 1): Den Hartog's boundary between non-stop motion and
// motion with stops. 0 where no lambda > 0 gives non-stop motion (at and near
// beta = 1/(2j+1)). Found by bisection to 1e-12 relative.
double den_hartog_boundary(double frequency_ratio, double static_ratio = 1);

}  // namespace frictionref
