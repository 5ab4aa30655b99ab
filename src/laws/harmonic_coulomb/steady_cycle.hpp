// The seed's steady cycle, computed once in 50 digits and replayed
// (docs/theory.md 3.9).
//
// With lambda < 1 the motion after a breakaway depends on nothing but the
// breakaway: the force is B sin(w t), nothing depends on x, and a slip from
// rest at a breakaway time alpha + n pi (forward for even n, backward for odd
// n; the motion is odd under t -> t + pi / w, x -> -x) follows the same law
// whatever came before. So once the mass has stuck and broken away, the
// phases up to the next breakaway, at alpha + (n + j) pi, repeat exactly:
// those of the cycle from alpha (n = 0, x = 0), shifted by n pi / w in time
// and by the position at the breakaway in x, mirrored for odd n.
//
// This class holds that cycle from the 50-digit engine and gives the ends of
// its phases in any later cycle: each time and position is a double-double
// sum with an error bound, rounded to double where the bound decides the
// rounding (Ziv's strategy), else summed in 50 digits. Either way the double
// is the correctly rounded value of the exact continuation from the position
// at the cycle's first breakaway.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "frictionref/model.hpp"
#include "frictionref/multiprecision.hpp"
#include "frictionref/types.hpp"
#include "numeric/double_double_scalar.hpp"

namespace frictionref::detail {

// The kind of a phase under x -> -x: slip+ and slip- swap, a stick stays.
inline PhaseKind mirrored(PhaseKind kind) {
  return kind == PhaseKind::slip_forward    ? PhaseKind::slip_backward
         : kind == PhaseKind::slip_backward ? PhaseKind::slip_forward
                                            : PhaseKind::stick;
}

class SteadyCycle {
 public:
  // A phase of the cycle from the forward breakaway at alpha with x = 0.
  struct Phase {
    PhaseKind kind = PhaseKind::stick;
    HighPrecision t_end;      // the end (alpha + offset) / w
    HighPrecision tau_end;    // the end's forcing phase minus alpha [rad]
    HighPrecision x_end;      // x at the end
    double acceleration = 0;  // left limit at the end
    bool stop = false;        // a slip that ends with v = 0
    bool reversal = false;    // ... followed at once by a slip the other way
    bool breakaway = false;   // a stick that ends in a slip
  };

  using Pair = DoubleDouble;  // hi + lo, |lo| <= ulp(hi) / 2

  // The end of a phase in a later cycle, rounded to double.
  struct End {
    PhaseKind kind;
    double t;
    double x;
    double acceleration;
    int rounded_in_50_digits;  // 0, 1 or 2 of t and x
  };

  // The cycle of the seed's model (is_harmonic_coulomb(), lambda < 1) from a
  // forward breakaway to the next breakaway, by the 50-digit engine; none if
  // the motion does not stick and break away again within three periods, or
  // grazes or merges a stick (decided within rounding: not robust).
  static std::optional<SteadyCycle> compute(const Model& model);

  std::size_t size() const { return phases_.size(); }
  const Phase& phase(std::size_t i) const { return phases_[i]; }
  // The next breakaway is j half periods of the force after the cycle's
  // first: j odd ends in the other direction (the next cycle is mirrored).
  std::int64_t half_turns() const { return half_turns_; }
  // The shortest phase of the cycle [rad of forcing phase].
  const HighPrecision& shortest() const { return shortest_; }

  // Cycle c of a replay whose cycle 0 starts at the breakaway alpha + n0 pi
  // with x = x0: it starts at alpha + (n0 + c j) pi. What its phases share.
  struct Shift {
    std::int64_t n = 0;   // starts at alpha + n pi
    bool forward = true;  // n even
    bool back = false;    // mirrored and odd: x0 + d0 (D - x_i)
    std::int64_t k = 0;   // else x0 + d0 (k D + x_i)
    double d0 = 1;        // direction of cycle 0
    long double x0 = 0;
    Pair t;  // n pi / w
    double t_size = 0;
    Pair x;  // x0 + d0 k D
    double x_size = 0;
  };
  Shift shift(std::int64_t n0, const long double& x0, std::int64_t c) const;
  // The end of phase i in that cycle.
  End end(const Shift& shift, std::size_t i) const;

  // The state at t_end inside phase i of that cycle (t_end before the
  // phase's end, as doubles), as the event loop gives it at its horizon: a
  // slip whose exact stop lies at or before t_end ends there stopped; else x,
  // v and a at t_end from the 50-digit law of the slip.
  struct Horizon {
    double x, v, acceleration;
  };
  Horizon horizon(const Shift& shift, std::size_t i, double t_end) const;

 private:
  // x at the end of phase i of that cycle, in 50 digits.
  HighPrecision exact_x(const Shift& shift, std::size_t i) const;
  // x at the start of that cycle.
  HighPrecision exact_start_x(const Shift& shift) const;

  std::vector<Phase> phases_;
  std::int64_t half_turns_ = 0;
  HighPrecision shortest_;
  HighPrecision half_period_;            // pi / w
  HighPrecision omega_, alpha_, b_, r_;  // b = B / (m w), r = R / (m w)
  // The same in double-double, for the fast sums.
  // x_back: D - x_end, D the last phase's x_end (the cycle's move): x in a
  // mirrored cycle, without the cancellation of D - x_end in double-double.
  std::vector<Pair> t_end_pairs_, x_end_pairs_, x_back_pairs_;
  Pair half_period_pair_;
};

}  // namespace frictionref::detail
