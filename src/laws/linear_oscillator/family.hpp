// The general family of phase laws (docs/theory.md 7): static friction
// Rs >= R, spring, damper, force offset and several harmonics.
//
// A slip ends at the first zero of v, a stick at the first time |N| > Rs;
// both are found by the certified search of numeric/first_zero.hpp on the
// closed forms of slip_law.hpp and net_force.hpp, then polished by the scalar
// type's root solver. At v = 0 the at-rest rule decides what follows, from N
// and, within the time resolution of |N| = Rs, from the direction N moves.
#pragma once

#include <cmath>
#include <limits>

#include "engine/engine_core.hpp"
#include "engine/event_loop.hpp"
#include "engine/motion_range.hpp"
#include "engine/scalar_traits.hpp"
#include "laws/linear_oscillator/net_force.hpp"
#include "laws/linear_oscillator/oscillator.hpp"
#include "laws/linear_oscillator/slip_law.hpp"
#include "numeric/first_zero.hpp"

namespace frictionref::detail {

template <class Real>
class LinearOscillatorFamily {
 public:
  using Work = work_t<Real>;
  using Traits = ScalarTraits<Real>;
  using Search = FirstZeroSearch<Work>;

  LinearOscillatorFamily(const BasicModel<Real>& model, const Real& t_end, const Work& tau0,
                         const Work& tau_end, BasicSummary<Real>& summary)
      : o_(model), tau_end_(tau_end), summary_(&summary) {
    using std::fabs;
    using std::sqrt;
    // A priori bounds (docs/theory.md 7.6): the energy m v^2 / 2 + k x^2 / 2
    // grows at most at rate |v| (F_max + R), so |v| <= sqrt(v0^2 + k x0^2 / m)
    // + (F_max + R) (t - t0) / m.
    const Work m(model.mass);
    Work f_max = fabs(Work(model.force_offset)) + Work(model.amplitude);
    for (const auto& h : model.harmonics) f_max += fabs(Work(h.amplitude));
    const Work v0(model.v0), x0(model.x0), k(model.stiffness);
    const Work span = Work(t_end) - Work(model.t0);
    MotionBounds<Work> bounds;
    bounds.speed = sqrt(v0 * v0 + k * x0 * x0 / m) + (f_max + Work(model.friction)) * span / m;
    bounds.travel = fabs(x0) + bounds.speed * span;
    bounds.acceleration = (f_max + Work(model.static_limit()) + Work(model.damping) * bounds.speed +
                           k * bounds.travel) /
                          m;
    check_motion_bounds(model, t_end, bounds, f_max / (m * Work(model.omega)), "F_max/(m w)");
    check_motion_scales<Real, Work>(model);
    (void)tau0;
  }

  int direction_at_rest(const Work& tau, const Work& x) {
    bool merged = false;
    const int direction = at_rest(tau, o_.omega() * x, merged);
    summary_->merged_sticks += merged;
    return direction;
  }

  Breakaway<Work> stick_end(const Work& tau, const Work& x);
  SlipEnd<Work> slip_end(const PhaseStart<Work>& start);

 private:
  int at_rest(const Work& tau, const Work& y, bool& merged) const;

  // The event-search probe on a closed form: `Law` gives jets and bounds.
  template <class Evaluate, class Bound>
  struct Probe {
    Evaluate evaluate;  // tau -> Jet<Work>
    Bound bound;        // (tau, jet, h) -> sup |f'''|
    std::uint64_t* evaluations;
    Jet<Work> jet(const Work& tau) {
      ++*evaluations;
      return evaluate(tau);
    }
    Work third_bound(const Work& tau, const Jet<Work>& at, const Work& h) {
      return bound(tau, at, h);
    }
    Work derivative(const Work& tau) { return jet(tau).d1; }
    Work second_derivative(const Work& tau) { return jet(tau).d2; }
    template <class F, class DF>
    RootResult<Work> decreasing_root(const F& f, const DF& df, const Work& lo, const Work& hi) {
      return checked(Traits::decreasing_root(f, df, lo, hi, *evaluations));
    }
  };
  template <class Evaluate, class Bound>
  Probe<Evaluate, Bound> probe(Evaluate evaluate, Bound bound) {
    return {evaluate, bound, &summary_->sign_tests};
  }

  Oscillator<Work> o_;
  Work tau_end_;
  BasicSummary<Real>* summary_;
};

template <class Real>
int LinearOscillatorFamily<Real>::at_rest(const Work& tau, const Work& y, bool& merged) const {
  using std::fabs;
  merged = false;
  const NetForce<Work> net(o_, y);
  const auto p = net.point(tau);
  const Work rs = o_.rs();
  const Work an = fabs(p.n);
  // |n| moves by at most |n'| res + |n''| res^2 / 2 within the time
  // resolution; beyond that (and its rounding) the band decides at once.
  const Work res = Traits::time_resolution(tau);
  const Work tolerance = fabs(p.d1) * res + fabs(p.d2) * res * res / 2 + p.e_n;
  const int sign_n = p.n > 0 ? 1 : p.n < 0 ? -1 : 0;
  if (an - rs > tolerance) return sign_n;
  if (rs - an > tolerance) return 0;
  // Within the resolution of a crossing of |n| = rs: the way n moves decides
  // (outward: the stick would end within the resolution, so the slip starts
  // now; inward: the mass stays).
  const int side = rs > tolerance || fabs(p.d1) <= p.e_d1 ? sign_n : p.d1 > 0 ? 1 : -1;
  if (side == 0) return 0;
  if (Work(side) * p.d1 > p.e_d1) {
    merged = an <= rs;
    return side;
  }
  if (Work(side) * p.d1 < -p.e_d1) return 0;
  return an > rs ? side : 0;
}

template <class Real>
Breakaway<typename LinearOscillatorFamily<Real>::Work> LinearOscillatorFamily<Real>::stick_end(
    const Work& tau, const Work& x) {
  using std::fabs;
  const Work y = o_.omega() * x;
  const NetForce<Work> net(o_, y);
  Breakaway<Work> result;
  if (!o_.forcing().oscillates()) {
    // n is constant: the at-rest rule already decided; it holds for ever.
    return result;
  }
  const auto jet_at = [&net](const Work& t) { return net.jet(net.point(t)); };
  auto search = probe(jet_at, [&net](const Work&, const Jet<Work>&, const Work&) {
    return net.third_bound();
  });
  Work from = tau;
  for (int tangencies = 0;; ++tangencies) {
    const Work res = Traits::time_resolution(from);
    if (!(from < tau_end_)) return result;
    if (tangencies > 64) throw SearchStalled{};
    const ZeroBracket<Work> bracket =
        Search::run(search, from, search.jet(from), tau_end_, res, res);
    if (!bracket.found) return result;
    const auto f = [&net](const Work& t) {
      const auto p = net.point(t);
      return (net.jet(p)).f;
    };
    const auto df = [&net](const Work& t) { return net.jet(net.point(t)).d1; };
    const Work root = checked(Traits::decreasing_root(f, df, bracket.lo, bracket.hi,
                                                      summary_->root_function_calls))
                          .root;
    const Jet<Work> at = search.jet(root);
    // A crossing (f falls through zero) is a breakaway; a tangency (|N|
    // touches Rs) is one only if |N| exceeds Rs just after.
    bool breaks = at.d1 < -at.e1;
    if (!breaks) {
      const Work after = root + Traits::time_resolution(root);
      breaks = after < tau_end_ && search.jet(after).f < 0;
    }
    if (breaks) {
      result.found = root < tau_end_;
      result.tau = root;
      const Work n = net.point(root).n;
      result.direction = n > 0 ? 1 : -1;
      return result;
    }
    from = root + Traits::time_resolution(root);
  }
}

template <class Real>
SlipEnd<typename LinearOscillatorFamily<Real>::Work> LinearOscillatorFamily<Real>::slip_end(
    const PhaseStart<Work>& start) {
  const Work omega = o_.omega();
  const LinearSlipLaw<Work> law(o_, start.sign, start.tau, omega * start.x, start.v);
  const auto jet_at = [&law](const Work& t) { return law.jet(law.point(t)); };
  auto search = probe(jet_at, [&law](const Work& t, const Jet<Work>& at, const Work& h) {
    return law.third_bound(t, at, h);
  });
  Work from = start.tau;
  Jet<Work> at_from = law.jet(law.point(start.tau));
  bool from_rest = start.v == 0;
  SlipEnd<Work> result;
  for (int touches = 0;; ++touches) {
    if (touches > 64) throw SearchStalled{};  // touch after touch without progress
    if (from_rest) at_from.f = 0;  // exactly: the slip starts (or goes on) from v = 0
    const Work res = Traits::time_resolution(from);
    ZeroBracket<Work> bracket;
    if (from < tau_end_)
      bracket = Search::run(search, from, at_from, tau_end_, from_rest ? res : Work(0), res);
    if (!bracket.found) {
      const auto q = law.point(tau_end_);
      result.stops = false;
      result.tau = tau_end_;
      result.x = q.y / omega;
      result.v = q.v;
      result.acceleration = law.acceleration(q);
      return result;
    }
    const Work s(start.sign);
    const auto f = [&law, &s](const Work& t) { return s * law.point(t).v; };
    const auto df = [&law, &s](const Work& t) { return s * law.point(t).d1; };
    const Work root = checked(Traits::decreasing_root(f, df, bracket.lo, bracket.hi,
                                                      summary_->root_function_calls))
                          .root;
    const auto q = law.point(root);
    bool merged = false;
    const int next = at_rest(root, q.y, merged);
    if (next == start.sign) {
      // v touches 0 where the force drives on the same way: not a stop.
      ++summary_->touches;
      from = root > from ? root : Work(from + Traits::time_resolution(from));
      at_from = law.jet(q);
      from_rest = true;
      continue;
    }
    summary_->merged_sticks += merged;
    result.stops = true;
    result.tau = root;
    result.x = q.y / omega;
    result.v = 0;
    result.acceleration = law.acceleration(q);
    result.next_direction = next;
    return result;
  }
}

}  // namespace frictionref::detail
