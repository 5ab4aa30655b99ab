// The 50-digit reference for the general model (see general_reference_solver.hpp
// for the method and why it is independent of the engine).
#include "general_reference_solver.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace frictionref_general_reference {

namespace {

using boost::multiprecision::abs;
using boost::multiprecision::cos;
using boost::multiprecision::exp;
using boost::multiprecision::sin;
using boost::multiprecision::sqrt;

// The majorant's ratio: past the polynomial, |X_n| h^n <= C theta^(n - N).
const Real kTheta = Real(1) / 2;
// Degree: until the last two scaled coefficients are below this fraction of
// the largest (|x| itself excluded: an offset does not move v).
const Real kSeriesCut("1e-64");
constexpr std::size_t kMinDegree = 12;
constexpr std::size_t kMaxDegree = 400;
// The tail majorant starts at N = D - 1 and needs phi_n free of F_0, F_1.
static_assert(kMinDegree >= 4, "the tail majorant needs N = D - 1 >= 2");

[[noreturn]] void fail(const std::string& what, const Real& t) {
  std::ostringstream text;
  text << std::setprecision(40) << "general reference: " << what << " at t = " << t;
  throw std::runtime_error(text.str());
}

// Sum |a_j| q_j^p over the oscillating terms of F.
Real term_norm(const RealInput& in, int power) {
  Real sum = 0;
  for (const RealTerm& term : in.terms) {
    Real q_power = 1;
    for (int i = 0; i < power; ++i) q_power *= term.omega;
    sum += abs(term.amplitude) * q_power;
  }
  return sum;
}

// F without the record's term, F0 + sum a_j sin(q_j t + p_j), and its rate.
Real oscillating_force(const RealInput& in, const Real& t) {
  Real sum = in.force_offset;
  for (const RealTerm& term : in.terms) sum += term.amplitude * sin(term.omega * t + term.phase);
  return sum;
}

Real oscillating_rate(const RealInput& in, const Real& t) {
  Real sum = 0;
  for (const RealTerm& term : in.terms)
    sum += term.amplitude * term.omega * cos(term.omega * t + term.phase);
  return sum;
}

Real highest_frequency(const RealInput& in) {
  Real w = 0;
  for (const RealTerm& term : in.terms)
    if (term.amplitude != 0 && term.omega > w) w = term.omega;
  return w;
}

// The Taylor expansion of x on [t_a, t_a + h] in a slip of sign s:
//   m x'' + c x' + k x = F(t) - s R,   x(t_a + u) = sum_n X_n u^n,
//   (n + 2)(n + 1) m X_{n+2} = F_n - [n = 0] s R - c (n + 1) X_{n+1} - k X_n,
// F_n the Taylor coefficients of F at t_a: those of sin and cos, plus F0 and
// the record's line -m (a_g(t_a) + a_g' u) in F_0 and F_1. The caller keeps
// [t_a, t_a + h) inside one segment of the record (h ends at most at the next
// sample), so that line is F's record term on the whole step. The tail past
// degree D is bounded by a majorant of the recurrence (tail_bound_).
class SlipSeries {
 public:
  SlipSeries(const RealInput& in, int s, const Real& t_a, const Real& x_a, const Real& v_a,
             const Real& h)
      : h_(h) {
    const Real& m = in.mass;
    const Real& c = in.damping;
    const Real& k = in.stiffness;
    // Per term: a q^n / n! and the phase's sin, cos (F_n cycles through
    // sin, cos, -sin, -cos times that).
    const std::size_t terms = in.terms.size();
    std::vector<Real> scale(terms), sin_phase(terms), cos_phase(terms);
    const std::size_t segment = in.segment(t_a);
    const Real forcing_now = in.force_offset - Real(s) * in.friction -
                             in.mass * in.ground_acceleration(segment, t_a);
    const Real forcing_rate = -in.mass * in.ground_slope(segment);
    for (std::size_t j = 0; j < terms; ++j) {
      const RealTerm& term = in.terms[j];
      const Real phase = term.omega * t_a + term.phase;
      sin_phase[j] = sin(phase);
      cos_phase[j] = cos(phase);
      scale[j] = term.amplitude;
    }
    X_.push_back(x_a);
    X_.push_back(v_a);
    Real largest = abs(v_a) * h;  // max |X_n| h^n over n >= 1
    Real h_power = h;             // h^(n+1) for the coefficient being made
    for (std::size_t n = 0;; ++n) {
      Real forcing = n == 0 ? forcing_now : n == 1 ? forcing_rate : Real(0);
      for (std::size_t j = 0; j < terms; ++j) {
        switch (n % 4) {
          case 0: forcing += scale[j] * sin_phase[j]; break;
          case 1: forcing += scale[j] * cos_phase[j]; break;
          case 2: forcing -= scale[j] * sin_phase[j]; break;
          default: forcing -= scale[j] * cos_phase[j]; break;
        }
        scale[j] *= in.terms[j].omega / Real(n + 1);
      }
      const Real next = (forcing - c * Real(n + 1) * X_[n + 1] - k * X_[n]) /
                        (m * Real(n + 1) * Real(n + 2));
      X_.push_back(next);
      h_power *= h;  // h^(n+2)
      const Real scaled = abs(next) * h_power;
      if (scaled > largest) largest = scaled;
      const std::size_t degree = n + 2;
      const Real previous = abs(X_[degree - 1]) * h_power / h;
      if (degree >= kMinDegree &&
          ((scaled <= kSeriesCut * largest && previous <= kSeriesCut * largest) || largest == 0))
        break;
      if (degree >= kMaxDegree) fail("Taylor series does not converge (step too long)", t_a);
    }
    tail_bound(in, h_power);
    for (std::size_t n = 1; n < X_.size(); ++n) V_.push_back(Real(n) * X_[n]);
  }

  // v(u) = x'(u) of the polynomial, by Horner (the scan's function).
  Real velocity(const Real& u) const {
    Real sum = 0;
    for (std::size_t n = V_.size(); n-- > 0;) sum = sum * u + V_[n];
    return sum;
  }

  std::size_t degree() const { return X_.size() - 1; }

  // x^(order)(u) of the polynomial (order 0..4), by Horner.
  Real derivative(int order, const Real& u) const {
    Real sum = 0;
    for (std::size_t n = X_.size(); n-- > static_cast<std::size_t>(order);) {
      Real factor = 1;
      for (int i = 0; i < order; ++i) factor *= Real(n - i);
      sum = sum * u + factor * X_[n];
    }
    return sum;
  }

  // sup over [0, h] of |x^(order)|: the polynomial's coefficients plus the tail.
  Real sup(int order) const {
    Real sum = 0, h_power = 1;
    for (std::size_t n = order; n < X_.size(); ++n) {
      Real factor = 1;
      for (int i = 0; i < order; ++i) factor *= Real(n - i);
      sum += factor * abs(X_[n]) * h_power;
      h_power *= h_;
    }
    return sum + tail_[order];
  }

  // Bound of |x^(order) - polynomial's| on [0, h].
  const Real& tail(int order) const { return tail_[order]; }

 private:
  // With Y_n = |X_n| h^n, alpha = c/m, beta = k/m, G = sum |a_j| / m,
  // W = max q_j, for n >= 2 (F_0 and F_1 also hold F0, -s R and the record's
  // line, which this bound does not need: it is only used from n = N >= 11 on):
  //   Y_{n+2} <= phi_n + rho_n max(Y_{n+1}, Y_n),
  //   rho_n = alpha h / (n + 2) + beta h^2 / ((n + 2)(n + 1)),
  //   phi_n = G h^2 (W h)^n / (n + 2)!.
  // If rho_n <= theta^2 / 2 and W h / theta <= n + 3 for n >= N = D - 1, then by
  // induction Y_n <= C theta^(n - N) for all n >= N with
  //   C = max(Y_N, Y_{N+1} / theta, 2 G h^2 (W h)^N / ((N + 2)! theta^2)),
  // and the tail of the order-p derivative on [0, h] is at most
  //   h^-p sum_{n > D} n^p Y_n <= h^-p C (D + 1)^p theta^2 / (1 - theta e^(p / (D + 1))).
  void tail_bound(const RealInput& in, const Real& h_power_degree) {
    const std::size_t D = degree();
    const std::size_t N = D - 1;
    const Real& h = h_;
    const Real alpha = in.damping / in.mass, beta = in.stiffness / in.mass;
    const Real G = term_norm(in, 0) / in.mass;
    const Real W = highest_frequency(in);
    const Real rho = alpha * h / Real(N + 2) + beta * h * h / (Real(N + 2) * Real(N + 1));
    if (rho > kTheta * kTheta / 2 || W * h / kTheta > Real(N + 3))
      fail("Taylor step too long for the tail majorant", Real(0));
    Real forcing_term = 2 * G * h * h / (kTheta * kTheta);
    for (std::size_t n = 1; n <= N; ++n) forcing_term *= W * h;
    for (std::size_t n = 1; n <= N + 2; ++n) forcing_term /= Real(n);
    const Real y_N = abs(X_[N]) * h_power_degree / h;
    const Real y_D = abs(X_[D]) * h_power_degree;
    Real C = y_N;
    if (y_D / kTheta > C) C = y_D / kTheta;
    if (forcing_term > C) C = forcing_term;
    Real h_inverse_power = 1;
    for (int p = 0; p <= 4; ++p) {
      const Real ratio = kTheta * exp(Real(p) / Real(D + 1));
      Real d_power = 1;
      for (int i = 0; i < p; ++i) d_power *= Real(D + 1);
      tail_[p] = h_inverse_power * C * d_power * kTheta * kTheta / (1 - ratio);
      h_inverse_power /= h;
    }
  }

  Real h_;
  std::vector<Real> X_, V_;  // x's coefficients, v's (n X_n)
  Real tail_[5];
};

// The first zero of g in (u, w], given g(u) = gu > 0 and g(w) = gw, from
// |g''| <= M on [u, w] and |g - evaluated g| <= error: false if there is none.
// Left half first: the answer is the first zero, and once a sign change is
// bracketed the halving is a bisection to the last bit of Real.
// Intervals narrower than `resolution` (the last bits of t) are not split.
template <class G>
bool first_zero(G& g, const Real& M, const Real& error, const Real& resolution, const Real& u,
                const Real& w, const Real& gu, const Real& gw, Real& root,
                std::uint64_t& unresolved) {
  const Real width = w - u;
  const Real chord_drop = M * width * width / 8 + error;
  if (gu > chord_drop && gw > chord_drop) return false;
  const Real mid = (u + w) / 2;
  if (!(width > resolution && mid > u && mid < w)) {  // at the last bits of t
    if (gw <= 0) {
      root = w;
      return true;
    }
    // Positive at both ends, within the truncation bound of zero: no zero
    // resolvable at 50 digits. This happens next to a root (the band where
    // |g| <= error), a few times; a tangency within the bound would take for
    // ever and is stopped.
    if (++unresolved > 100000) fail("unresolved tangency (g within its error bound)", w);
    return false;
  }
  const Real gm = g(mid);
  if (gm <= 0) {
    if (first_zero(g, M, error, resolution, u, mid, gu, gm, root, unresolved)) return true;
    root = mid;  // unreachable in exact arithmetic: gm <= 0 forces a zero in (u, mid]
    return true;
  }
  if (first_zero(g, M, error, resolution, u, mid, gu, gm, root, unresolved)) return true;
  return first_zero(g, M, error, resolution, mid, w, gm, gw, root, unresolved);
}

// The largest d such that f0 + f1 u + f2 u^2 / 2 - M3 u^3 / 6 > 0 on (0, d],
// for f0 >= 0: half the positive root of f1 + f2 u / 2 - M3 u^2 / 6 (the
// bound divided by u is concave, so positive between 0+ and that root).
// Zero if the bound is not positive just after 0.
Real taylor_zone(const Real& f1, const Real& f2, const Real& M3, const Real& cap) {
  if (f1 < 0 || (f1 == 0 && !(f2 > 0))) return 0;
  if (M3 == 0) {
    if (f2 >= 0) return cap;
    const Real d = -f1 / f2;  // half the root of f1 + f2 u / 2
    return d < cap ? d : cap;
  }
  const Real a = M3 / 6, b = f2 / 2;
  const Real root = (b + sqrt(b * b + 4 * a * f1)) / (2 * a);
  const Real d = root / 2;
  return d < cap ? d : cap;
}

class Solver {
 public:
  Solver(const RealInput& model, const Real& t_end, const Options& options)
      : in_(model), options_(options) {
    result_.model = model;
    result_.t_end = t_end;
    t_end_ = t_end;
    const Real W = highest_frequency(in_);
    const Real natural = sqrt(in_.stiffness / in_.mass);
    const Real decay = in_.damping / in_.mass;
    Real rate = W;
    if (natural > rate) rate = natural;
    if (decay > rate) rate = decay;
    slip_step_ = rate > 0 ? Real(options.step_fraction / rate) : Real(t_end - model.t0);
    stick_step_ = W > 0 ? Real(options.step_fraction / W) : Real(t_end - model.t0);
    force_curvature_ = term_norm(in_, 2);
    force_rate_max_ = term_norm(in_, 1);
    oscillating_ = W > 0;
    forced_ = oscillating_ || !in_.record_t.empty();
  }

  Result run() {
    Real t = in_.t0, x = in_.x0;
    if (in_.v0 != 0) {
      slip(in_.v0 > 0 ? 1 : -1, Start::initial, t, x, in_.v0);
    } else {
      at_rest(Start::initial, t, x);
    }
    return std::move(result_);
  }

 private:
  bool full() {
    if (result_.phases.size() < options_.max_phases) return false;
    result_.phase_limit = true;
    return true;
  }

  // The last bits of t: 2^-162 max(1, |t|), a little above Real's 168-bit
  // spacing, so that intervals measured from a step start (finer there) are
  // not split below what t itself can hold.
  static Real resolution(const Real& t) {
    const Real scale = abs(t) > 1 ? Real(abs(t)) : Real(1);
    return boost::multiprecision::ldexp(scale, -162);
  }

  Real net_force(const Real& t, const Real& x) const { return in_.force(t) - in_.stiffness * x; }

  // The same with the record's segment k's line (at its right end: the left
  // limit), and F' there.
  Real net_force_on(std::size_t k, const Real& t, const Real& x) const {
    return oscillating_force(in_, t) - in_.mass * in_.ground_acceleration(k, t) -
           in_.stiffness * x;
  }
  Real force_rate_on(std::size_t k, const Real& t) const {
    return oscillating_rate(in_, t) - in_.mass * in_.ground_slope(k);
  }

  std::size_t segments_end() const { return in_.record_t.size(); }  // the last segment, n

  // At rest at t: slip at once if |N| > Rs (or |N| = Rs with N moving
  // outward), else stick. Iterates over the whole run (slip and stick call
  // back here), so the loop is flat rather than recursive.
  void at_rest(Start start, Real t, Real x) {
    for (;;) {
      if (full() || t >= t_end_) return;
      const Real N = net_force(t, x);
      const Real rate = in_.force_rate(t);
      const int direction = N > 0 ? 1 : N < 0 ? -1 : (rate > 0 ? 1 : rate < 0 ? -1 : 0);
      const Real excess = abs(N) - in_.static_friction;
      const bool outward = excess == 0 && direction != 0 && Real(direction) * rate > 0;
      Real next_t = 0, next_x = 0;
      if (excess > 0 || outward) {
        const Start slip_start = start == Start::initial ? Start::initial : Start::from_stop;
        if (!slip(direction, slip_start, t, x, 0, next_t, next_x)) return;
      } else {
        int breakaway_direction = 0;
        if (!stick(start, t, x, next_t, breakaway_direction)) return;
        if (!slip(breakaway_direction, Start::breakaway, next_t, x, 0, next_t, next_x)) return;
      }
      start = Start::stop;
      t = next_t;
      x = next_x;
    }
  }

  // A slip with v0 != 0 at t0, then whatever follows.
  void slip(int s, Start start, const Real& t, const Real& x, const Real& v) {
    Real next_t = 0, next_x = 0;
    if (slip(s, start, t, x, v, next_t, next_x)) at_rest(Start::stop, next_t, next_x);
  }

  // A stick from t_a at position x. Returns false if it runs to the horizon,
  // else the breakaway time and direction.
  //
  // Segment by segment of the record (a single one without a record): on
  // segment k, g = Rs - |N| is evaluated with that segment's line up to the
  // left limit at its end, so g is the minimum of two C^2 functions there and
  // the chord test's |g''| <= sum |a_j| q_j^2 holds (a line has no curvature).
  // At the start of each later segment (a sample time) the right limit is
  // checked first: past Rs there (a jump at t_0 or t_{n-1}), or on Rs and
  // moving outward, the stick ends at that sample time.
  bool stick(Start start, const Real& t_a, const Real& x, Real& t_break, int& direction) {
    Phase p;
    p.kind = Kind::stick;
    p.start = start == Start::initial ? Start::initial : Start::stop;
    p.t_begin = t_a;
    p.x_begin = p.x_end = x;
    if (!forced_) return stick_to_horizon(p);  // N constant: the rule at t_a holds for ever

    const Real& Rs = in_.static_friction;
    const Real& M = force_curvature_;
    const std::size_t n = segments_end();
    Real u = t_a;
    for (std::size_t k = in_.segment(t_a);; ++k) {
      if (!(u < t_end_)) return stick_to_horizon(p);
      // [u, stop]: segment k's part still to scan (k = n: to the horizon).
      const Real stop = k < n && in_.record_t[k] < t_end_ ? in_.record_t[k] : t_end_;
      auto g = [&](const Real& t) {
        ++result_.evaluations;
        return Rs - abs(net_force_on(k, t, x));
      };
      Real gu = g(u);
      const Real N_u = net_force_on(k, u, x);
      const Real rate_u = force_rate_on(k, u);
      if (u > t_a) {
        // The right limit at the sample u (at_rest has checked it at t_a).
        const bool outward = gu == 0 && (N_u != 0 ? N_u * rate_u > 0 : rate_u != 0);
        if (gu < 0 || outward)
          return break_away(p, u, N_u, rate_u, true, t_break, direction);
      }
      if (!oscillating_ && in_.ground_slope(k) == 0) {
        // N constant on the segment (no harmonic, a_g constant): g(u) >= 0 holds on it.
        if (gu < 0) fail("stick with |N| > Rs", u);
        u = stop;
        continue;
      }
      // A segment starting on the band's edge (|N| = Rs, N moving inward):
      // a zone free of zeros from the Taylor bound of the branch at the edge,
      // Rs - dir N >= g0 + g1 d - M d^2 / 2, and of the other branch,
      // Rs + dir N >= Rs + |N| - max|N'| d (max|N'| on this segment).
      if (!(gu > M * stick_step_ * stick_step_ / 8)) {
        const int edge = N_u >= 0 ? 1 : -1;
        const Real g1 = -Real(edge) * rate_u;
        if (gu < 0) fail("stick with |N| > Rs", u);
        if (g1 > 0) {
          Real d = (g1 + sqrt(g1 * g1 + 2 * M * gu)) / (M == 0 ? Real(1) : M) / 2;
          const Real other = Rs + abs(N_u);
          const Real rate_max = force_rate_max_ + in_.mass * abs(in_.ground_slope(k));
          if (rate_max > 0 && other / (2 * rate_max) < d) d = other / (2 * rate_max);
          if (d > stick_step_) d = stick_step_;
          u = d < stop - u ? Real(u + d) : stop;
          gu = g(u);
        } else if (gu == 0) {
          fail("stick on the band's edge with N not moving inward", u);
        }
      }
      while (u < stop) {
        Real w = u + stick_step_;
        if (w > stop) w = stop;
        const Real gw = g(w);
        Real root = 0;
        if (first_zero(g, M, Real(0), resolution(u), u, w, gu, gw, root,
                       result_.unresolved_points)) {
          if (root >= t_end_) return stick_to_horizon(p);
          return break_away(p, root, net_force_on(k, root, x), force_rate_on(k, root), false,
                            t_break, direction);
        }
        u = w;
        gu = gw;
      }
      u = stop;
    }
  }

  // The end of a stick at t with N and N' there (at a record jump: the right
  // limits); the slip's direction is N's, or N''s for N = 0 (Rs = 0).
  bool break_away(Phase& p, const Real& t, const Real& N, const Real& rate, bool jump,
                  Real& t_break, int& direction) {
    const Real& Rs = in_.static_friction;
    if (jump)
      direction = N > 0 ? 1 : N < 0 ? -1 : (rate > 0 ? 1 : -1);
    else  // Rs = 0: N crosses 0 and leaves in the direction it moves.
      direction = abs(N) * 2 > Rs ? (N > 0 ? 1 : -1) : (rate > 0 ? 1 : -1);
    p.t_end = t;
    p.net_force_end = N;
    p.net_force_rate_end = rate;
    p.net_force_curvature_end = force_second_derivative(t);
    p.at_record_jump = jump;
    result_.phases.push_back(p);
    t_break = t;
    breakaway_at_jump_ = jump;
    return true;
  }

  // F'' (the record's lines add nothing inside a segment).
  Real force_second_derivative(const Real& t) const {
    Real sum = 0;
    for (const RealTerm& term : in_.terms)
      sum -= term.amplitude * term.omega * term.omega * sin(term.omega * t + term.phase);
    return sum;
  }

  bool stick_to_horizon(Phase& p) {
    p.t_end = t_end_;
    p.at_horizon = true;
    result_.phases.push_back(p);
    return false;
  }

  // A slip of sign s from (t_a, x_a, v_a). Returns false if it runs to the
  // horizon, else the stop time and position (v = 0 there).
  bool slip(int s, Start start, const Real& t_a, const Real& x_a, const Real& v_a,
            Real& t_stop, Real& x_stop) {
    Phase p;
    p.kind = s > 0 ? Kind::slip_forward : Kind::slip_backward;
    p.start = start;
    p.t_begin = t_a;
    p.x_begin = x_a;
    p.v_begin = v_a;
    const Real sign(s);
    Real t = t_a, x = x_a, v = v_a;
    bool first = true;
    for (;;) {
      Real h = slip_step_;
      if (t + h > t_end_) h = t_end_ - t;
      // Never across a sample of the record: [t, t + h) within one segment
      // (record_t[k] is the first sample after t).
      const std::size_t k = in_.segment(t);
      const bool to_sample = k < segments_end() && in_.record_t[k] - t <= h;
      if (to_sample) h = in_.record_t[k] - t;
      const SlipSeries series(in_, s, t, x, v, h);
      ++result_.series_steps;
      if (series.degree() > result_.max_degree) result_.max_degree = series.degree();
      auto f = [&](const Real& u) {
        ++result_.evaluations;
        return sign * series.velocity(u);
      };
      const Real M2 = series.sup(3);  // |f''| = |x'''|
      const Real error = series.tail(1);
      const Real speed_scale = series.sup(1);
      if (speed_scale > 0 && error / speed_scale > result_.max_truncation)
        result_.max_truncation = error / speed_scale;
      Real u = 0;
      if (first) {
        Real f1 = sign * series.derivative(2, 0);
        // At a breakaway |N| = Rs exactly: s v' = (Rs - R) / m there (not at a
        // record jump: |N| > Rs there, the series' value is right).
        if (start == Start::breakaway && !breakaway_at_jump_)
          f1 = (in_.static_friction - in_.friction) / in_.mass;
        p.slope_begin = f1;
        if (v_a == 0) {
          const Real f2 = sign * series.derivative(3, 0);
          u = taylor_zone(f1, f2, series.sup(4), h);
          if (!(u > 0)) fail("a slip from rest that cannot start", t);
        }
        first = false;
      }
      Real root = 0;
      bool stops = false;
      if (u < h) {
        const Real fu = f(u);
        // (A start with s v0 within the truncation bound is fine: the scan
        // then halves towards u until the chord test can decide.)
        if (!(fu > 0)) fail("s v not positive inside a slip", t + u);
        stops = first_zero(f, M2, error, resolution(t), u, h, fu, f(h), root,
                           result_.unresolved_points);
      }
      if (stops && t + root >= t_end_) stops = false;  // a stop on the horizon: cut there
      if (stops) {
        t_stop = t + root;
        x_stop = series.derivative(0, root);
        p.t_end = t_stop;
        p.x_end = x_stop;
        p.v_end = 0;
        p.slope_end = sign * series.derivative(2, root);
        p.curvature_end = sign * series.derivative(3, root);
        result_.phases.push_back(p);
        return true;
      }
      const Real v_next = series.derivative(1, h);
      if (abs(v_next) > p.speed_max) p.speed_max = abs(v_next);
      if (abs(v) > p.speed_max) p.speed_max = abs(v);
      x = series.derivative(0, h);
      v = v_next;
      t = to_sample ? in_.record_t[k] : Real(t + h);  // exactly on the sample
      if (t >= t_end_) {
        p.t_end = t_end_;
        p.x_end = x;
        p.v_end = v;
        p.at_horizon = true;
        result_.phases.push_back(p);
        return false;
      }
    }
  }

  RealInput in_;
  Options options_;
  Result result_;
  Real t_end_, slip_step_, stick_step_, force_curvature_, force_rate_max_;
  bool oscillating_ = false;        // a harmonic with a_j != 0
  bool forced_ = false;             // N can change in a stick: a harmonic or a record
  bool breakaway_at_jump_ = false;  // the last stick ended at a record jump
};

void check_input(const RealInput& in, const Real& t_end) {
  using boost::multiprecision::isfinite;
  std::vector<const Real*> fields = {&in.mass,  &in.friction,     &in.static_friction,
                                     &in.stiffness, &in.damping,  &in.force_offset,
                                     &in.x0,    &in.v0,           &in.t0,
                                     &t_end};
  for (const RealTerm& term : in.terms) {
    fields.push_back(&term.amplitude);
    fields.push_back(&term.omega);
    fields.push_back(&term.phase);
  }
  for (const Real& t : in.record_t) fields.push_back(&t);
  for (const Real& a : in.record_a) fields.push_back(&a);
  for (const Real* f : fields)
    if (!isfinite(*f)) throw std::invalid_argument("general reference: non-finite input");
  if (in.record_t.size() != in.record_a.size() || in.record_t.size() == 1)
    throw std::invalid_argument("general reference: a record needs n >= 2 times and accelerations");
  for (std::size_t i = 1; i < in.record_t.size(); ++i)
    if (!(in.record_t[i] > in.record_t[i - 1]))
      throw std::invalid_argument("general reference: record times must increase strictly");
  if (!(in.mass > 0) || in.friction < 0 || in.static_friction < in.friction ||
      in.stiffness < 0 || in.damping < 0)
    throw std::invalid_argument("general reference: need m > 0, 0 <= R <= Rs, k >= 0, c >= 0");
  for (const RealTerm& term : in.terms)
    if (!(term.omega > 0)) throw std::invalid_argument("general reference: need w_j > 0");
  if (!(t_end > in.t0)) throw std::invalid_argument("general reference: need t_end > t0");
}

}  // namespace

Real RealInput::force(const Real& t) const {
  return oscillating_force(*this, t) - mass * ground_acceleration(t);
}

Real RealInput::force_rate(const Real& t) const {
  return oscillating_rate(*this, t) - mass * ground_slope(segment(t));
}

std::size_t RealInput::segment(const Real& t) const {
  // The number of samples at or before t.
  return static_cast<std::size_t>(std::upper_bound(record_t.begin(), record_t.end(), t) -
                                  record_t.begin());
}

Real RealInput::ground_acceleration(std::size_t k, const Real& t) const {
  if (k == 0 || k >= record_t.size()) return 0;
  return record_a[k - 1] + ground_slope(k) * (t - record_t[k - 1]);
}

Real RealInput::ground_slope(std::size_t k) const {
  if (k == 0 || k >= record_t.size()) return 0;
  return (record_a[k] - record_a[k - 1]) / (record_t[k] - record_t[k - 1]);
}

std::string Input::describe() const {
  std::ostringstream text;
  text << std::setprecision(17) << "m=" << mass << " B=" << amplitude << " w=" << omega
       << " R=" << friction << " Rs=" << static_limit() << " k=" << stiffness
       << " c=" << damping << " F0=" << force_offset;
  for (const Harmonic& h : harmonics)
    text << " +" << h.amplitude << "sin(" << h.omega << "t+" << h.phase << ")";
  if (!record_t.empty())
    text << " record=" << record_t.size() << " samples on [" << record_t.front() << ","
         << record_t.back() << "]";
  text << " x0=" << x0 << " v0=" << v0 << " t0=" << t0;
  return text.str();
}

RealInput RealInput::from_double(const Input& in) {
  RealInput r;
  r.mass = Real(in.mass);
  r.friction = Real(in.friction);
  r.static_friction = Real(in.static_limit());
  r.stiffness = Real(in.stiffness);
  r.damping = Real(in.damping);
  r.force_offset = Real(in.force_offset);
  r.terms.push_back({Real(in.amplitude), Real(in.omega), Real(0)});
  for (const Harmonic& h : in.harmonics)
    r.terms.push_back({Real(h.amplitude), Real(h.omega), Real(h.phase)});
  for (const double t : in.record_t) r.record_t.push_back(Real(t));
  for (const double a : in.record_a) r.record_a.push_back(Real(a));
  r.x0 = Real(in.x0);
  r.v0 = Real(in.v0);
  r.t0 = Real(in.t0);
  return r;
}

const char* to_string(Kind kind) {
  switch (kind) {
    case Kind::stick: return "stick";
    case Kind::slip_forward: return "slip+";
    case Kind::slip_backward: return "slip-";
  }
  return "?";
}

Result solve(const RealInput& model, const Real& t_end, const Options& options) {
  check_input(model, t_end);
  if (!(options.step_fraction > 0 && options.step_fraction <= Real(1) / 2))
    throw std::invalid_argument("general reference: step_fraction must be in (0, 1/2]");
  return Solver(model, t_end, options).run();
}

}  // namespace frictionref_general_reference
