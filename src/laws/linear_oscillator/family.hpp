// The general family of phase laws (docs/theory.md 7): static friction
// Rs >= R, spring, damper, force offset and several harmonics, and a ground
// record with any of them (docs/theory.md 9.6), two-way or one-way (never
// towards negative x: a stick then ends only at the band's upper edge, and a
// decision to slide backwards is one to stay).
//
// A slip ends at the first zero of v, a stick at the first time |N| > Rs;
// both are found by the certified search of numeric/first_zero.hpp on the
// closed forms of slip_law.hpp and net_force.hpp, then polished by the scalar
// type's root solver. At v = 0 the at-rest rule decides what follows, from N
// and, within the time resolution of |N| = Rs, from the direction N moves.
// With a record the closed forms hold on one of its segments (the record is
// linear there): both searches walk the segments in order, carrying the
// slip's state across each segment's end.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "engine/engine_core.hpp"
#include "engine/event_loop.hpp"
#include "engine/motion_range.hpp"
#include "engine/scalar_traits.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "laws/linear_oscillator/duration_guess.hpp"
#include "laws/linear_oscillator/net_force.hpp"
#include "laws/linear_oscillator/oscillator.hpp"
#include "laws/linear_oscillator/slip_law.hpp"
#include "numeric/first_zero.hpp"
#include "numeric/halley_polish.hpp"
#include "numeric/last_point.hpp"

namespace frictionref::detail {

// kSkipInsideSegments: a stick on a record skips the segments a test in
// double proves well inside the band (stick_band); false only for the test
// that compares the phase tables of both ways (test_general_record_skip.cpp).
template <class Real, bool kSkipInsideSegments = true>
class LinearOscillatorFamily {
 public:
  using Work = work_t<Real>;
  using Traits = ScalarTraits<Real>;
  using Search = FirstZeroSearch<Work>;

  LinearOscillatorFamily(const BasicModel<Real>& model, const Real& t_end, const Work& tau0,
                         const Work& tau_end, BasicSummary<Real>& summary)
      : o_(model),
        one_way_(model.one_way),
        tau_end_(tau_end),
        summary_(&summary),
        slip_guess_(frequencies(o_)),
        stick_guess_(frequencies(o_)) {
    using std::fabs;
    using std::sqrt;
    // A priori bounds (docs/theory.md 7.6): the energy m v^2 / 2 + k x^2 / 2
    // grows at most at rate |v| (F_max + R), so |v| <= sqrt(v0^2 + k x0^2 / m)
    // + (F_max + R) (t - t0) / m.
    const Work m(model.mass);
    Work f_max = fabs(Work(model.force_offset)) + Work(model.amplitude);
    for (const auto& h : model.harmonics) f_max += fabs(Work(h.amplitude));
    if (model.ground_motion) f_max += m * Work(model.ground_motion->pga());
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
    check_static_deflection<Real, Work>(model);
    check_time_scales<Real, Work>(model, t_end);
    shortest_segment_ = check_record_resolution(model);
    (void)tau0;
  }

  int direction_at_rest(const Work& tau, const Work& x) {
    const AtRest decision = at_rest(tau, o_.omega() * x);
    summary_->merged_sticks += decision.merged;
    return decision.direction;
  }

  Breakaway<Work> stick_end(const Work& tau, const Work& x);
  SlipEnd<Work> slip_end(const PhaseStart<Work>& start);

 private:
  // The first breakaway in (tau, to] with n as `net` gives it (one segment
  // of the record, or the whole run without one).
  Breakaway<Work> stick_end_on(const NetForce<Work>& net, const Work& tau, const Work& to);
  // What the at-rest rule says at v = 0: the direction of the slip that
  // follows (0: the mass stays), and whether a stick shorter than the
  // resolution was merged into it.
  struct AtRest {
    int direction = 0;
    bool merged = false;
  };
  // N at a stop from the slip's own closed form, n = v' + 2 sigma v + s r,
  // with |N| - Rs = s (v' + 2 sigma v) + (r - rs) while s n >= 0 (no
  // cancellation against r when Rs = R), and the rounding bound of both:
  // relative to the slip's start, so free of the cancellation in
  // g - rho^2 y that a far equilibrium (|F0| = 4e12 with N = 1e-8) brings to
  // N computed from the position.
  struct ForceAtStop {
    Work n = 0, e_n = 0;
    Work excess = 0, e_excess = 0;  // |N| - Rs
  };
  // A stick's band for the test in double on a record's samples
  // (RecordForcing::strictly_inside), in units of w n: a segment that passes
  // it has |n| < rs on all of it by more than twice the at-rest rule's
  // tolerance (the move of n within the time resolution, n's rounding) and
  // than the harmonics' whole amplitude, so that neither the at-rest rule at
  // its start nor the search on it can find anything: it is skipped.
  struct StickBand {
    double offset = 0;      // w (f0 - rho^2 y)
    double band = 0;        // w rs, rounded towards 0
    double extra = 0;       // the harmonics, their move, 2^-39 of the offset's terms
    double per_change = 0;  // the record's move within the resolution, per |a_k - a_{k-1}|
  };
  StickBand stick_band(const Work& y, const Work& tau) const;
  // One-way, a decision to slide backwards is one to stay.
  AtRest at_rest(const Work& tau, const Work& y, const ForceAtStop* at_stop = nullptr) const {
    const AtRest decision = at_rest_two_way(tau, y, at_stop);
    if (one_way_ && decision.direction < 0) return {};
    return decision;
  }
  AtRest at_rest_two_way(const Work& tau, const Work& y, const ForceAtStop* at_stop) const;
  // The zero of a decreasing f in a bracket of the event search: certified
  // Halley steps where the scalar type polishes that way, else (or if they
  // do not settle) the scalar type's bracketing solver. `third` bounds
  // |f'''| on the bracket; the polish starts from `guess` where there is one
  // (duration_guess.hpp), else from the secant of the bracket's ends.
  template <class JetAt, class F, class DF>
  Work root_in(const ZeroBracket<Work>& bracket, const JetAt& jet_at, const Work& third, const F& f,
               const DF& df, const std::optional<Work>& guess);

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

  // Throws InvalidInput (naming the record) if two samples are closer than
  // the time resolution: the laws hold on one interval each, and an interval
  // the engine cannot resolve can hold a whole impulse (a_g = 6e247 for
  // 2e-70 s, a velocity change of 1e178 that a stop's root, resolved to the
  // resolution, straddled: found by fuzzing). The rigid block's quadratic
  // roots take such intervals in their stride and are not concerned.
  // Returns a lower bound of the shortest interval in tau (for stick_band).
  // An interval far above the resolution passes on a test in double (2^-30
  // of max(1, |w t|) against 2^-49; one pass over the record per engine, and
  // batches build one engine per record and yield acceleration).
  static Work check_record_resolution(const BasicModel<Real>& model) {
    using std::fabs;
    if (!model.ground_motion) return 0;
    const std::vector<double>& t = model.ground_motion->t;
    const Work omega(model.omega);
    const double w = static_cast<double>(model.omega);
    double shortest_step = std::numeric_limits<double>::infinity();  // passed in double
    Work shortest = std::numeric_limits<Work>::infinity();           // the others
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
      const double step = t[i + 1] - t[i];
      if (step * w > 0x1p-30 * std::fmax(1.0, fabs(w * t[i + 1]))) {
        if (step < shortest_step) shortest_step = step;
        continue;
      }
      const Work a = omega * Work(t[i]), b = omega * Work(t[i + 1]);
      if (b - a < shortest) shortest = b - a;
      const Work resolution = Traits::time_resolution(b);
      if (!(b - a > resolution))
        throw InvalidInput("ground_motion", model.ground_motion->file,
                           "samples t[" + std::to_string(i) + "] = " + to_text(t[i]) + " and t[" +
                               std::to_string(i + 1) + "] = " + to_text(t[i + 1]) +
                               " are closer than the engine's time resolution " +
                               to_text(static_cast<double>(resolution / omega)) +
                               " (8 ulps of max(1, |w t|) / w): with a spring, damper or harmonic "
                               "force the motion between them cannot be resolved; resample the "
                               "record (docs/theory.md 9.6)");
    }
    // (step rounds the difference of the times by up to 2^-53 |t|, far below
    // 2^-20 of it where the test in double passed.)
    const Work passed = omega * Work(shortest_step) * Work(1 - 0x1p-20);
    return passed < shortest ? passed : shortest;
  }

  // The event search's step cap for (from, to]: a fixed allowance plus 256
  // steps per radian of the fastest oscillation (about 2 are used: ~10 per
  // natural period of a stiff spring's ringing), so that a long slip of a
  // stiff spring is searched to its end and a stall is still caught.
  std::int64_t step_budget(const Work& from, const Work& to) const {
    const double radians = static_cast<double>((to - from) * o_.fastest_rate());
    const double budget = static_cast<double>(Search::kDefaultMaxSteps) + 256 * radians;
    return budget < 1e18 ? static_cast<std::int64_t>(budget) : std::int64_t(1e18);
  }

  static std::vector<double> frequencies(const Oscillator<Work>& o) {
    std::vector<double> q;
    for (const ForcingTerm<Work>& f : o.forcing().terms()) q.push_back(static_cast<double>(f.q));
    return q;
  }

  // The event search's aim for a predicted phase end (first_zero.hpp): a
  // little past it, 2^-36 of the fastest motion's time scale, so that a
  // prediction a few ulps early still has its root inside the aimed bracket
  // and the polish's step from the aim stays within LinearSlipLaw::can_move.
  Work aim_after(const std::optional<Work>& predicted) const {
    return predicted ? Work(*predicted + Work(0x1p-36) / o_.fastest_rate())
                     : std::numeric_limits<Work>::quiet_NaN();
  }

  Oscillator<Work> o_;
  bool one_way_;  // a record's downslope block: never towards negative x
  Work tau_end_;
  BasicSummary<Real>* summary_;
  // First guesses for the polish of slip and stick ends: slips by their
  // direction, sticks by that of the slip that stopped into them.
  DurationGuess<Work> slip_guess_, stick_guess_;
  int last_stop_sign_ = 0;
  Work stick_start_ = 0;
  Work shortest_segment_ = 0;  // the record's shortest sample interval in tau (none: 0)
};

template <class Real, bool kSkipInsideSegments>
auto LinearOscillatorFamily<Real, kSkipInsideSegments>::at_rest_two_way(
    const Work& tau, const Work& y, const ForceAtStop* at_stop) const -> AtRest {
  using std::fabs;
  // A stop whose own N (from the slip) lies outside the band, or inside it,
  // by more than its rounding and than any move of N within the time
  // resolution, bounded without the forcing's phase (|n'| <= sum |a| q,
  // |n''| <= sum |a| q^2, doubled for their rounding), is decided without N
  // from the position, which costs a sin_cos per harmonic: a reversal, or a
  // stop well inside the band. (A record's N moves by its segment's slope
  // and jumps at its ends: the full rule below.)
  if (at_stop && !o_.record().present() && fabs(at_stop->n) > at_stop->e_n) {
    const Work res = Traits::time_resolution(tau);
    const Forcing<Work>& forcing = o_.forcing();
    const Work tolerance =
        2 * (forcing.bound(1) * res + forcing.bound(2) * res * res / 2) + at_stop->e_excess;
    if (at_stop->excess > tolerance) return {at_stop->n > 0 ? 1 : -1, false};
    if (-at_stop->excess > tolerance) return {0, false};
  }
  const NetForce<Work> net(o_, y, o_.record().piece_at(tau));
  auto p = net.point(tau);
  const Work rs = o_.rs();
  Work excess = -p.gap;  // |N| - Rs
  Work e_excess = p.e_gap;
  // N's value from the stopping slip where that is the sharper of the two
  // (its slope at rest, g', does not depend on y: NetForce's is exact).
  if (at_stop && at_stop->e_excess < e_excess) {
    p.n = at_stop->n;
    p.e_n = at_stop->e_n;
    excess = at_stop->excess;
    e_excess = at_stop->e_excess;
  }
  // |n| moves by at most |n'| res + |n''| res^2 / 2 within the time
  // resolution; beyond that (and its rounding) the band decides at once.
  const Work res = Traits::time_resolution(tau);
  const Work move = fabs(p.d1) * res + fabs(p.d2) * res * res / 2;
  const Work tolerance = move + e_excess;
  const int sign_n = p.n > 0 ? 1 : p.n < 0 ? -1 : 0;
  if (excess > tolerance) return {sign_n, false};
  if (-excess > tolerance) return {0, false};
  // Within the resolution of a crossing of |n| = rs: the way n moves decides
  // (outward: the stick would end within the resolution, so the slip starts
  // now; inward: the mass stays). Which edge is crossed comes from the slope
  // only where the sign of n is itself lost in rounding (rs within the
  // tolerance): a mass never slides against a resolvable N. (Following the
  // slope of a resolvably positive N that was falling, a slip that stopped
  // went on backwards against it, a touch at a time until the cap: found
  // by fuzzing at a far equilibrium.)
  const bool sign_resolved = fabs(p.n) > p.e_n;
  int side = sign_n;
  if (!(rs > tolerance) && !sign_resolved && fabs(p.d1) > p.e_d1) side = p.d1 > 0 ? 1 : -1;
  if (side == 0) return {0, false};
  if (Work(side) * p.d1 > p.e_d1) return {side, excess <= 0};
  // Inward, but so fast that n crosses the whole band and leaves it on the
  // other side within the resolution: the stick is shorter than the engine
  // resolves, merged into a slip the other way at once (a stick of zero
  // length between two slips the same way showed as a touch cut in two: a
  // subnormal v0 against a huge harmonic, found by the low-end sweep).
  const Work fall = fabs(p.d1) * res - fabs(p.d2) * res * res / 2 - p.e_d1 * res;
  if (Work(side) * p.d1 < -p.e_d1 && fall > fabs(p.n) + rs + p.e_n) return {-side, true};
  // Inward, or N within rounding of the band's edge and not moving beyond
  // rounding either: nothing resolvable drives the mass, it stays
  // (|N| <= Rs within rounding). Sliding in the latter case followed the
  // sign of rounding noise: a free oscillation decayed to the state's
  // rounding, with R = Rs = 0, reversed every millisecond (found by fuzzing).
  return {0, false};
}

template <class Real, bool kSkipInsideSegments>
template <class JetAt, class F, class DF>
auto LinearOscillatorFamily<Real, kSkipInsideSegments>::root_in(const ZeroBracket<Work>& bracket,
                                                                const JetAt& jet_at,
                                                                const Work& third, const F& f,
                                                                const DF& df,
                                                                const std::optional<Work>& guess)
    -> Work {
  // A bracket closed by a sign test at the resolution may end where f is
  // within rounding of zero but positive: the zero is there.
  if (bracket.at_hi.f > 0) return bracket.hi;
  if (!(bracket.at_lo.f > 0)) return bracket.lo;
  if constexpr (Traits::halley_polish) {
    const Work first = guess ? *guess : secant_guess(bracket);
    if (const auto root = halley_polish(jet_at, bracket.lo, bracket.hi, first, third,
                                        summary_->root_function_calls))
      return *root;
  }
  return checked(
             Traits::decreasing_root(f, df, bracket.lo, bracket.hi, summary_->root_function_calls))
      .root;
}

template <class Real, bool kSkipInsideSegments>
auto LinearOscillatorFamily<Real, kSkipInsideSegments>::stick_band(const Work& y,
                                                                   const Work& tau) const
    -> StickBand {
  using std::fabs;
  const Work w = o_.omega();
  const Forcing<Work>& f = o_.forcing();
  const Work horizon = fabs(tau) > fabs(tau_end_) ? fabs(tau) : fabs(tau_end_);
  const Work res = Traits::time_resolution(horizon);  // >= the resolution anywhere on the stick
  // Twice over: the harmonics' values and their phases' rounding (below
  // 2^-63 |q tau| of them), their move within res; and, for the rounding of
  // n and of this test, 2^-39 of the terms (n's own is 2^-57).
  const Work terms = fabs(f.constant()) + o_.rho2() * fabs(y) + o_.rs();
  const Work extra = w * (terms * Work(0x1p-39) + 2 * f.bound(0) +
                          2 * (f.bound(1) * res + f.bound(2) * res * res));
  StickBand b;
  b.offset = static_cast<double>(w * (f.constant() - o_.rho2() * y));
  b.band = NetAcceleration<Work>::band_in_double(w * o_.rs());
  b.extra = static_cast<double>(extra) * (1 + 0x1p-30);
  // The record moves n by |a_k - a_{k-1}| res / (w dtau) within res (twice).
  b.per_change = static_cast<double>(2 * res / shortest_segment_) * (1 + 0x1p-30);
  return b;
}

template <class Real, bool kSkipInsideSegments>
Breakaway<typename LinearOscillatorFamily<Real, kSkipInsideSegments>::Work>
LinearOscillatorFamily<Real, kSkipInsideSegments>::stick_end(const Work& tau, const Work& x) {
  const Work y = o_.omega() * x;
  const RecordForcing<Work>& record = o_.record();
  Breakaway<Work> result;
  stick_start_ = tau;
  if (!o_.forcing().oscillates() && !record.present()) {
    // n is constant: the at-rest rule already decided; it holds for ever.
    return result;
  }
  // Segment by segment of the record (one piece without a record). The
  // interior segments that begin after tau and end before the horizon are
  // skipped where a test in double on their samples proves them well inside
  // the band (stick_band): most of a stick's segments.
  std::size_t k = 0, last = 0;
  StickBand band;
  if (record.present()) {
    k = record.segment_at(tau);
    last = std::min(record.first_ending_at_or_after(tau_end_), record.samples());
    band = stick_band(y, tau);
  }
  const auto inside = [&](std::size_t segment) {
    return record.strictly_inside(segment, band.offset, band.band, band.extra, band.per_change,
                                  one_way_);
  };
  for (Work from = tau;; ++k) {
    if (kSkipInsideSegments && from > tau && k < last && inside(k)) {
      const std::size_t skipped_from = k;
      while (k + 1 < last && inside(k + 1)) ++k;
      summary_->sign_tests += k + 1 - skipped_from;
      from = record.segment_end(k);
      continue;
    }
    const RecordPiece<Work> piece = record.present() ? record.piece(k) : RecordPiece<Work>{};
    if (from > tau) {
      // A new segment: n turns there, or jumps (at the record's ends); the
      // at-rest rule decides at its start as at any other instant.
      const AtRest decision = at_rest(from, y);
      if (decision.direction != 0) {
        summary_->merged_sticks += decision.merged;
        return {true, from, decision.direction};
      }
    }
    const Work to = piece.end < tau_end_ ? piece.end : tau_end_;
    if (o_.forcing().oscillates() || piece.slope != 0) {
      result = stick_end_on(NetForce<Work>(o_, y, piece, from, to), from, to);
      if (result.found) return result;
    }
    if (!(piece.end < tau_end_)) return result;
    from = piece.end;
  }
}

template <class Real, bool kSkipInsideSegments>
Breakaway<typename LinearOscillatorFamily<Real, kSkipInsideSegments>::Work>
LinearOscillatorFamily<Real, kSkipInsideSegments>::stick_end_on(const NetForce<Work>& net,
                                                                const Work& tau, const Work& to) {
  using std::fabs;
  Breakaway<Work> result;
  // The search runs on f + E, E a bound of f's rounding error over the stick:
  // the mass breaks away only where |N| exceeds Rs by more than rounding (at
  // the time |N| crossed Rs); a tangency of |N| to Rs within rounding, as at
  // R = B with a spring, leaves it at rest (|N| <= Rs). One-way, f = Rs - N:
  // only the upper edge ends the stick.
  const Work horizon = fabs(tau) > fabs(tau_end_) ? fabs(tau) : fabs(tau_end_);
  const Work margin =
      2 * (one_way_ ? net.value_error_bound_upper(horizon) : net.value_error_bound(horizon));
  // |n| can never exceed rs by more than rounding: at rest for good.
  if (net.magnitude_bound() * (1 + 64 * std::numeric_limits<Work>::epsilon()) <= o_.rs() &&
      (o_.rs() - net.magnitude_bound()) * (o_.rs() + net.magnitude_bound()) + margin > 0)
    return result;
  const bool one_way = one_way_;
  // One point kept: the search's last (the bracket's end, where the polish
  // starts when it is the aim below) serves the polish and the direction.
  LastPoint<Work, typename NetForce<Work>::Point> last;
  const auto point_at = [&net, &last ](const Work& t) -> const auto& {
    return last.at(t, [&net](const Work& u) { return net.point(u); });
  };
  const auto jet_of = [&net, &point_at, one_way](const Work& t) {
    const auto& p = point_at(t);
    return one_way ? net.jet_upper(p) : net.jet(p);
  };
  const auto third_of = [&net, one_way](const Jet<Work>& at, const Work& h) {
    return one_way ? net.third_bound_upper() : net.third_bound(at, h);
  };
  const auto shifted = [&jet_of, margin](const Work& t) {
    Jet<Work> j = jet_of(t);
    j.f += margin;
    return j;
  };
  auto search = probe(shifted, [&third_of](const Work&, const Jet<Work>& at, const Work& h) {
    return third_of(at, h);
  });
  const Work res = Traits::time_resolution(tau);
  // The predicted breakaway and, a little past it, the search's aim (as for
  // slips: the bracket then ends where the polish starts).
  const std::optional<Work> predicted = stick_guess_.after(last_stop_sign_, stick_start_);
  const Work aim = aim_after(predicted);
  const ZeroBracket<Work> bracket =
      Search::run(search, tau, search.jet(tau), to, res, res, step_budget(tau, to), aim);
  if (!bracket.found) return result;
  // n > 0 or < 0 beyond the band's edge at the bracket's end.
  const Work n_beyond = point_at(bracket.hi).n;
  const auto f = [&jet_of](const Work& t) { return jet_of(t).f; };
  const auto df = [&jet_of](const Work& t) { return jet_of(t).d1; };
  // The crossing of f = 0 (not f + margin) inside the bracket.
  ZeroBracket<Work> crossing = bracket;
  crossing.at_lo.f -= margin;
  crossing.at_hi.f -= margin;
  Work root;
  if (!(crossing.at_lo.f > 0)) {
    root = crossing.lo;  // |N| reached Rs within rounding before the certain excess
  } else {
    root = root_in(crossing, jet_of, third_of(crossing.at_lo, crossing.hi - crossing.lo), f, df,
                   polish_start(predicted, aim, crossing.lo, crossing.hi));
    if (root < tau_end_) stick_guess_.remember(last_stop_sign_, stick_start_, root);
  }
  result.found = root < tau_end_;
  result.tau = root;
  result.direction = one_way_ || n_beyond > 0 ? 1 : -1;
  return result;
}

template <class Real, bool kSkipInsideSegments>
SlipEnd<typename LinearOscillatorFamily<Real, kSkipInsideSegments>::Work>
LinearOscillatorFamily<Real, kSkipInsideSegments>::slip_end(const PhaseStart<Work>& start) {
  using std::fabs;
  using std::sqrt;
  const Work omega = o_.omega();
  // The law of the record's segment that holds the slip's current start
  // (the whole slip without a record); replaced at each segment's end.
  LinearSlipLaw<Work> law(o_, start.sign, start.tau, omega * start.x, start.v);
  // The points with error bounds, the last one kept: the search's first
  // step often lands where the noise level after a start was just taken
  // (one resolution on), and the stop's point is the bracket's end (or is
  // moved from it).
  using SlipPoint = typename LinearSlipLaw<Work>::Point;
  LastPoint<Work, SlipPoint> bounded;
  const auto bounded_point = [&law, &bounded](const Work& t) -> const SlipPoint& {
    return bounded.at(t, [&law](const Work& u) { return law.point(u); });
  };
  const auto jet_at = [&law, &bounded_point](const Work& t) { return law.jet(bounded_point(t)); };
  auto search = probe(jet_at, [&law](const Work& t, const Jet<Work>& at, const Work& h) {
    return law.third_bound(t, at, h);
  });
  const Work s(start.sign);
  // The root solvers ask for f and f' at the same time, one after the other:
  // one evaluation serves both.
  LastPoint<Work, SlipPoint> cache;
  const auto at = [&law, &cache](const Work& t) -> const SlipPoint& {
    return cache.at(t, [&law](const Work& u) { return law.point(u, /*with_bounds=*/false); });
  };
  const auto f = [&at, &s](const Work& t) { return s * at(t).v; };
  const auto df = [&at, &s](const Work& t) { return s * at(t).d1; };
  Work from = start.tau;
  Jet<Work> at_from = law.jet(bounded_point(start.tau));
  // Zeros are not looked for within `blind` of `from` after a start (or a
  // touch) at v = 0: the stretch where v stays within a few rounding errors
  // of zero, from the jet there (f' u + f'' u^2 / 2 = 4 e0), and at least
  // the time resolution. After a breakaway with Rs = R (f' = 0) it is about
  // sqrt(8 e0 / f''): no stop can be told apart from rounding sooner. (Up to
  // e0 only, v ended the stretch in its noise, where the search's sign test
  // counts it as zero: a spurious stop.)
  // With f' < 0 < f'' and f' within the rounding of the decision that let
  // the mass slide (v dips below 0 before rising) the stretch runs over the
  // dip, to the later root: the dip is as unresolvable as the slope that
  // makes it. That rounding is the larger of f''s own and that of N from
  // the position, which decides breakaways: a breakaway taken a rounding
  // early starts with f' slightly below 0. (Stepped one stretch at a time, a
  // dip of 46 resolutions hit the cap on touches; a stop in each dip gave a
  // cascade of stops and breakaways: both found by fuzzing.)
  const auto blind_after_rest = [this](const Jet<Work>& j, const Work& tau, const Work& y,
                                       const Work& res) {
    const Work level = 4 * j.e0 + (j.f < 0 ? Work(-j.f) : Work(0));
    // (N from the position is evaluated only where it can decide.)
    const auto within_slope_noise = [&] {
      return -j.d1 <= j.e1 ||
             -j.d1 <= NetForce<Work>(o_, y, o_.record().piece_at(tau)).point(tau).e_gap;
    };
    Work stretch;
    if (j.d1 < 0 && j.d2 > 0 && within_slope_noise()) {
      stretch = (-j.d1 + sqrt(j.d1 * j.d1 + 2 * j.d2 * level)) / j.d2;
    } else {
      const Work slope = j.d1 > 0 ? j.d1 : Work(0);
      const Work curvature = fabs(j.d2) > 0 ? Work(fabs(j.d2)) : Work(1);
      stretch = 2 * level / (slope + sqrt(slope * slope + 2 * curvature * level));
    }
    return stretch > res ? stretch : res;
  };
  // The stretch is set by the noise at its start; where that noise decays
  // within it (the rounding of a far start state fading with the transient)
  // the stretch is cut to where the noise is still a sixteenth of it, so that
  // no oscillation of v resolvable later in it is skipped (a stretch of 68
  // time units passed over ten reversals: found by fuzzing).
  const auto within_noise = [&bounded_point](const Work& from_tau, Work stretch, const Work& e0,
                                             const Work& res) {
    for (int i = 0; i < 64 && stretch > res; ++i) {
      if (bounded_point(from_tau + stretch).e_v * 16 >= e0) break;
      stretch /= 2;
    }
    return stretch > res ? stretch : res;
  };
  // At the start itself the closed form is exact (e0 = 0): the noise level
  // of the stretch is that one resolution later. (With e0 = 0 the stretch
  // was one resolution long and v, far below its noise there, was taken for
  // a stop at once: a slip at a time, for ever, found by fuzzing.)
  // The point there is moved from the start's by Taylor's theorem where it
  // can be (LinearSlipLaw::moved: its bounds carry the start's derivatives'
  // rounding over the resolution, as the closed form's own do there), and
  // kept: it is the search's first point when the stretch is one resolution.
  Work blind = 0;
  Work moved_tau = std::numeric_limits<Work>::quiet_NaN();  // where `bounded` holds a moved point
  if (start.v == 0) {
    const Work res = Traits::time_resolution(from);
    Jet<Work> noisy = at_from;
    const Work next = from + res;
    if (law.can_move(from, next)) {
      const SlipPoint at_start = bounded.point();
      bounded.at(next, [&law, &at_start](const Work& t) { return law.moved(at_start, t); });
      moved_tau = next;
    }
    const Jet<Work> later = law.jet(bounded_point(next));
    if (later.e0 > noisy.e0) noisy.e0 = later.e0;
    if (later.e1 > noisy.e1) noisy.e1 = later.e1;
    blind = within_noise(from, blind_after_rest(noisy, from, omega * start.x, res), noisy.e0, res);
  }
  // Where the slip should end, from the matching earlier slip
  // (duration_guess.hpp), and a little past it the search's aim
  // (first_zero.hpp): in a steady state its bracket then ends at the aim.
  const std::optional<Work> predicted = slip_guess_.after(start.sign, start.tau);
  const Work aim = aim_after(predicted);
  // The twin's first proven step, tried first by the slip's first search;
  // that search's own is remembered for the slips to come.
  Work first_step = slip_guess_.first_step(start.sign, start.tau);
  bool first_search = true;
  SlipEnd<Work> result;
  bool touched_against = false;  // the last touch had v resolvably against the slip
  // Touches that follow each other within 64 resolutions (no progress) are
  // counted; a slip may touch v = 0 any number of times far apart (R = 0
  // driven by a harmonic: once a period).
  for (int touches = 0;; ++touches) {
    if (touches > 64) throw SearchStalled{};  // touch after touch without progress
    if (!(from < law.segment_end()) && law.segment_end() < tau_end_) {
      // The law's segment of the record is over: the next one's law, from
      // the state there.
      // The state there from the search's last point where it was evaluated
      // at the segment's end (the same closed form: the same y and v as an
      // evaluation without bounds), else from a new evaluation.
      const bool evaluated_there = bounded.tau() == from && !(moved_tau == from);
      law = evaluated_there ? law.continued_from(bounded.point()) : law.continued_at(from);
      bounded.forget();
      cache.forget();
      at_from = law.jet(bounded_point(from));
    }
    if (blind > 0) at_from.f = 0;  // exactly: the slip starts (or goes on) from v = 0
    const Work res = Traits::time_resolution(from);
    // The search ends at the horizon or at the end of the law's segment.
    const Work to = law.segment_end() < tau_end_ ? law.segment_end() : tau_end_;
    ZeroBracket<Work> bracket;
    if (from < to) {
      bracket = Search::run(search, from, at_from, to, blind, res, step_budget(from, to), aim,
                            first_search ? first_step : Work(0));
      if (first_search) first_step = bracket.first_step;
      first_search = false;
    }
    if (!bracket.found && to < tau_end_) {
      const Jet<Work> at_to = law.jet(bounded_point(to));
      if (at_to.f > 0) {
        // v keeps its sign to the segment's end: the slip goes on under the
        // next segment's law (at the loop's top).
        from = to;
        blind = 0;
        touched_against = false;
        touches = -1;  // progress: the loop's ++ starts the count again
        continue;
      }
      // Within rounding of 0 there: the stop is at the segment's end.
      bracket = {true, to, to, at_to, at_to};
    }
    if (!bracket.found) {
      const auto q = law.point(tau_end_, false);
      result.stops = false;
      result.tau = tau_end_;
      result.x = q.y / omega;
      result.v = q.v;
      result.acceleration = law.acceleration(q);
      return result;
    }
    // The polish starts from the aim where the search's bracket ends there
    // (its point with bounds is at hand), else from the prediction inside the
    // bracket, else from the secant. From either of the first two it usually
    // accepts after that one evaluation, a few ulps from the root: the point
    // at the stop is then moved there from it (LinearSlipLaw::moved) instead
    // of evaluated afresh.
    const std::optional<Work> guess = polish_start(predicted, aim, bracket.lo, bracket.hi);
    const auto cached_jet = [&](const Work& t) {
      return law.jet(guess && t == *guess ? bounded_point(t) : at(t));
    };
    const Work third = law.third_bound(bracket.lo, bracket.at_lo, bracket.hi - bracket.lo);
    // A bracket that starts where the slip starts (from rest, or after a
    // touch) comes from the jump over the stretch where v is within rounding
    // of 0 (first_zero.hpp): the slip ends, unresolvably, inside that
    // stretch; its end is taken as the stop, not the start (where the at-rest
    // rule has just said "slide").
    const Work root =
        bracket.at_lo.f > 0 ? root_in(bracket, cached_jet, third, f, df, guess) : bracket.hi;
    // With its rounding bounds: N at the stop and whether v turned back.
    const auto q = bounded.tau() == root || !law.can_move(bounded.tau(), root)
                       ? bounded_point(root)
                       : law.moved(bounded.point(), root);
    const Work eps = std::numeric_limits<Work>::epsilon();
    const Work damping = 2 * o_.sigma() * q.v;
    ForceAtStop at_stop;
    const Work along = s * (q.d1 + damping);  // s n - r
    at_stop.n = s * (along + o_.r());
    const Work slip_error =
        q.e_d1 + 2 * o_.sigma() * q.e_v + 4 * eps * (fabs(q.d1) + fabs(damping));
    at_stop.e_n = slip_error + 4 * eps * o_.r();
    if (along + o_.r() >= 0) {  // N still along the slip: r - rs is exact (Rs near R)
      at_stop.excess = along + (o_.r() - o_.rs());
      at_stop.e_excess = slip_error + 4 * eps * (o_.rs() - o_.r());
    } else {
      at_stop.excess = -(along + o_.r()) - o_.rs();
      at_stop.e_excess = slip_error + 4 * eps * (o_.r() + o_.rs());
    }
    AtRest decision = at_rest(root, q.y, &at_stop);
    // At the end of a stretch where v was within rounding of 0 (a bracket
    // from a jump over it) the slip's own v may be resolvably against its
    // direction while the at-rest rule, which takes v = 0, says "on the same
    // way" (N within its rounding, or v' and N both noise at a far
    // equilibrium). A touch carries on a law whose v runs against the slip:
    // the stretch after it covers v's way back (blind_after_rest). Where v
    // is not resolvably turning back, or that way back already failed once
    // (the touch before was against the slip too), the next search would
    // stop at once again: touches one resolution apart until the cap (R =
    // Rs = 0, velocities at twice their rounding at equilibria 1e15 to 1e20
    // from 0: found by fuzzing and by a sweep of such models). Nothing
    // resolvable drives the mass on: it stays (|N| <= Rs within rounding),
    // and the stick's own search finds when N does drive it.
    const bool against = !(bracket.at_lo.f > 0) && s * q.v < -q.e_v;
    const bool turned = against && (!(s * q.d1 > q.e_d1) || touched_against);
    if (decision.direction == start.sign && turned) decision = AtRest{};
    if (decision.direction == start.sign) {
      // v touches 0 where the force drives on the same way: not a stop. The
      // search goes on past the stretch where v is within a few rounding
      // errors of 0 (blind_after_rest; f'' > 0 at a touch).
      ++summary_->touches;
      touched_against = against;
      // (The touch's jet from a fresh evaluation: the search goes on from it.)
      const auto& touch = bounded_point(root);
      at_from = law.jet(touch);
      blind = within_noise(root, blind_after_rest(at_from, root, touch.y, res), at_from.e0, res);
      if (root > from + 64 * res) touches = 0;
      from = root > from ? root : Work(from + res);
      continue;
    }
    summary_->merged_sticks += decision.merged;
    slip_guess_.remember(start.sign, start.tau, root, first_step);
    last_stop_sign_ = start.sign;
    result.stops = true;
    result.tau = root;
    result.x = q.y / omega;
    result.v = 0;
    result.acceleration = law.acceleration(q);
    result.next_direction = decision.direction;
    return result;
  }
}

}  // namespace frictionref::detail
