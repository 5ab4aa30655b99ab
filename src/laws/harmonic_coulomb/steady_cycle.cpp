// The seed's steady cycle in 50 digits, and its replay in double-double
// (steady_cycle.hpp, docs/theory.md 3.9).
#include "laws/harmonic_coulomb/steady_cycle.hpp"

#include <boost/math/constants/constants.hpp>
#include <cmath>

#include "frictionref/error.hpp"
#include "frictionref/exact_engine.hpp"
#include "laws/harmonic_coulomb/phase_law.hpp"
#include "numeric/double_double_scalar.hpp"
#include "numeric/sin_cos.hpp"

namespace frictionref::detail {
namespace {
using Pair = SteadyCycle::Pair;
using double_double::add;
using double_double::decided;
using double_double::kErrorPerMagnitude;
using double_double::scaled;
using double_double::split;
}  // namespace

std::optional<SteadyCycle> SteadyCycle::compute(const Model& model) {
  using std::abs;
  using std::asin;
  if (!model.is_harmonic_coulomb() || !(model.amplitude > 0) || !(model.friction < model.amplitude))
    return std::nullopt;
  BasicModel<HighPrecision> start = model_cast<HighPrecision>(model);
  const HighPrecision pi = boost::math::constants::pi<HighPrecision>();
  const HighPrecision alpha = asin(start.friction / start.amplitude);
  start.t0 = alpha / start.omega;
  start.x0 = 0;
  start.v0 = 0;
  const HighPrecision t_end = start.t0 + 6 * pi / start.omega;

  SteadyCycle cycle;
  cycle.half_period_ = pi / start.omega;
  cycle.omega_ = start.omega;
  cycle.alpha_ = alpha;
  cycle.b_ = start.amplitude / (start.mass * start.omega);
  cycle.r_ = start.friction / (start.mass * start.omega);
  try {
    BasicExactEngine<HighPrecision> engine(start, t_end);
    BasicPhase<HighPrecision> p;
    BasicSummary<HighPrecision> before = engine.summary();
    HighPrecision previous_tau = 0;
    while (engine.next(p)) {
      const BasicSummary<HighPrecision>& now = engine.summary();
      // A touch or a merged stick: decided within rounding, not robust.
      if (now.touches != before.touches || now.merged_sticks != before.merged_sticks)
        return std::nullopt;
      const HighPrecision tau = start.omega * p.t_end - alpha;
      if (cycle.phases_.empty() && p.kind != PhaseKind::slip_forward) {
        // The start is a breakaway: only a stick within rounding of it may
        // come first.
        if (!(tau < HighPrecision(1e-40))) return std::nullopt;
        previous_tau = tau;
        before = now;
        continue;
      }
      Phase phase;
      phase.kind = p.kind;
      phase.t_end = p.t_end;
      phase.tau_end = tau;
      phase.x_end = p.x_end;
      phase.acceleration = static_cast<double>(now.final_state.a);
      phase.stop = p.kind != PhaseKind::stick && now.stops != before.stops;
      phase.reversal = now.reversals != before.reversals;
      phase.breakaway = p.kind == PhaseKind::stick && now.breakaways != before.breakaways;
      const HighPrecision length = tau - previous_tau;
      if (cycle.phases_.empty() || length < cycle.shortest_) cycle.shortest_ = length;
      previous_tau = tau;
      before = now;
      cycle.phases_.push_back(phase);
      if (phase.breakaway) break;
      if (p.kind == PhaseKind::stick || !phase.stop || cycle.phases_.size() > 32)
        return std::nullopt;  // a stick that does not break away, the horizon, a long cycle
    }
  } catch (const InvalidInput&) {
    return std::nullopt;  // the 50-digit run's own range checks
  }
  if (cycle.phases_.empty() || !cycle.phases_.back().breakaway) return std::nullopt;
  // The last stick ends at the breakaway alpha + j pi.
  const HighPrecision turns = cycle.phases_.back().tau_end / pi;
  const HighPrecision j = round(turns);
  if (!(j >= 1) || !(abs(turns - j) < HighPrecision(1e-35))) return std::nullopt;
  cycle.half_turns_ = static_cast<std::int64_t>(j);
  for (const Phase& phase : cycle.phases_) {
    cycle.t_end_pairs_.push_back(split(phase.t_end));
    cycle.x_end_pairs_.push_back(split(phase.x_end));
    cycle.x_back_pairs_.push_back(split(cycle.phases_.back().x_end - phase.x_end));
  }
  cycle.half_period_pair_ = split(cycle.half_period_);
  return cycle;
}

SteadyCycle::Shift SteadyCycle::shift(std::int64_t n0, const long double& x0,
                                      std::int64_t c) const {
  Shift shift;
  shift.n = n0 + c * half_turns_;
  shift.forward = shift.n % 2 == 0;
  // x = x0 + d0 (k D + x_i) in cycle c, D = x_end of the last phase (the
  // cycle's move), d0 = +-1 the direction of cycle 0; k = c, or in mirrored
  // cycles (odd j) x = x0 + d0 x_i in even cycles and x0 + d0 (D - x_i) in
  // odd ones (out by D, back again).
  const bool mirrors = half_turns_ % 2 != 0;
  shift.back = mirrors && c % 2 != 0;
  shift.k = mirrors ? 0 : c;
  shift.d0 = n0 % 2 == 0 ? 1 : -1;
  shift.x0 = x0;
  const double n = static_cast<double>(shift.n), k = static_cast<double>(shift.k);
  shift.t = scaled(n, half_period_pair_);
  shift.t_size = std::fabs(n * half_period_pair_.hi);
  shift.x = split(x0);
  if (shift.k != 0) shift.x = add(shift.x, scaled(shift.d0 * k, x_end_pairs_.back()));
  shift.x_size = std::fabs(static_cast<double>(x0)) + std::fabs(k * x_end_pairs_.back().hi);
  return shift;
}

SteadyCycle::End SteadyCycle::end(const Shift& shift, std::size_t i) const {
  const Phase& phase = phases_[i];
  End result{shift.forward ? phase.kind : mirrored(phase.kind), 0, 0,
             shift.forward ? phase.acceleration : -phase.acceleration, 0};
  // t = t_end_i + n pi / w.
  const Pair& t_i = t_end_pairs_[i];
  const Pair t = add(t_i, shift.t);
  if (!decided(t, kErrorPerMagnitude * (std::fabs(t_i.hi) + shift.t_size), result.t)) {
    result.t = static_cast<double>(phase.t_end + HighPrecision(shift.n) * half_period_);
    ++result.rounded_in_50_digits;
  }
  const Pair& x_i = shift.back ? x_back_pairs_[i] : x_end_pairs_[i];
  const Pair x = add(shift.x, scaled(shift.d0, x_i));
  if (!decided(x, kErrorPerMagnitude * (shift.x_size + std::fabs(x_i.hi)), result.x)) {
    result.x = static_cast<double>(exact_x(shift, i));
    ++result.rounded_in_50_digits;
  }
  return result;
}

HighPrecision SteadyCycle::exact_x(const Shift& shift, std::size_t i) const {
  const HighPrecision& move = phases_.back().x_end;
  const HighPrecision& x_i = phases_[i].x_end;
  const HighPrecision offset = shift.back ? move - x_i : HighPrecision(shift.k) * move + x_i;
  return HighPrecision(shift.x0) + HighPrecision(shift.d0) * offset;
}

HighPrecision SteadyCycle::exact_start_x(const Shift& shift) const {
  // Out by D in the odd cycles of a mirrored replay, by k D in the others.
  const HighPrecision& move = phases_.back().x_end;
  const bool mirrors = half_turns_ % 2 != 0;
  const HighPrecision out =
      mirrors ? (shift.back ? move : HighPrecision(0)) : HighPrecision(shift.k) * move;
  return HighPrecision(shift.x0) + HighPrecision(shift.d0) * out;
}

SteadyCycle::Horizon SteadyCycle::horizon(const Shift& shift, std::size_t i, double t_end) const {
  const Phase& phase = phases_[i];
  // The phase starts at rest where phase i - 1 ended (or at the cycle's
  // breakaway).
  const HighPrecision x_start = i > 0 ? exact_x(shift, i - 1) : exact_start_x(shift);
  if (phase.kind == PhaseKind::stick) return {static_cast<double>(x_start), 0, 0};
  const HighPrecision t_exact(t_end);
  const HighPrecision shift_t = HighPrecision(shift.n) * half_period_;
  if (phase.t_end + shift_t <= t_exact)  // stopped at or before the horizon
    return {static_cast<double>(exact_x(shift, i)), 0,
            shift.forward ? phase.acceleration : -phase.acceleration};
  const HighPrecision tau_start =
      alpha_ + HighPrecision(shift.n) * boost::math::constants::pi<HighPrecision>() +
      (i > 0 ? phases_[i - 1].tau_end : HighPrecision(0));
  const PhaseKind kind = shift.forward ? phase.kind : mirrored(phase.kind);
  const PhaseLaw<HighPrecision> law(omega_, b_, r_, kind, tau_start, x_start, HighPrecision(0),
                                    sin_cos(tau_start));
  const auto point = law.point(omega_ * t_exact);
  return {static_cast<double>(law.position(point)),
          static_cast<double>(HighPrecision(law.sign()) * point.speed),
          static_cast<double>(law.acceleration_at(point.at))};
}

}  // namespace frictionref::detail
