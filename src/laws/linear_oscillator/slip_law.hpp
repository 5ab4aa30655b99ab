// A slip of the linear oscillator in closed form (docs/theory.md 7.2, 7.3).
//
// From (y_a, v_a) at tau_a, with the homogeneous transition functions
// (transition.hpp) and each harmonic's response from rest R_j
// (forced_response.hpp), at u = tau - tau_a:
//
//   y(tau) = Phi11 y_a + G v_a + g0 G1 + d G2 + sum_j Im(A_j R_j(u))
//   v(tau) = -rho^2 G y_a + G' v_a + g0 G + d G1 + sum_j Im(A_j R_j'(u))
//
// with g0 = f0 + r_g(tau_a) - s r, d the slope of the ground record's part
// r_g on its segment (record_forcing.hpp; the law holds up to the segment's
// end) and A_j = a_j e^{i theta_j(tau_a)}. Higher derivatives
// follow from the same closed forms. For the event search (first_zero.hpp)
// the law also bounds |v'''| on [tau, tau + h] rigorously, by the smaller of:
//  (A) w = v' solves w'' + 2 sigma w' + rho^2 w = g'', so S = sqrt(w'^2 +
//      rho^2 w^2) grows at most at rate |g''| <= G2 = sum |a_j| q_j^2, and
//      |v'''| = |g'' - 2 sigma w' - rho^2 w| <= G2 + (2 sigma + rho)(S(tau) + h G2)
//      (good near resonance and for light damping; the record's ramp has
//      r_g'' = 0 on the segment);
//  (B) v''' = v_p''' + z_h' with v_p the steady response (|v_p'''| <= sum
//      |a| |H| q^4) and z_h = v'' - v_p'' a free motion, whose energy
//      rho^2 z_h^2 + z_h'^2 never grows, so |z_h'| stays below its value at
//      tau (good for heavy damping, where (A)'s 2 sigma is huge; infinite at
//      exact resonance). The ramp's steady response is linear in tau (v_p
//      constant or linear), so it adds nothing to v_p'' and v_p'''.
#pragma once

// (GCC 12 warns of a memcpy overread inside small_vector's copy that cannot
// happen: the size it assumes exceeds any vector.)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-overread"
#include <boost/container/small_vector.hpp>
#pragma GCC diagnostic pop
#include <cmath>
#include <limits>

#include "laws/linear_oscillator/oscillator.hpp"
#include "numeric/complex.hpp"
#include "numeric/first_zero.hpp"
#include "numeric/sin_cos.hpp"

namespace frictionref::detail {

template <class Work>
class LinearSlipLaw {
 public:
  // Everything at one time of the slip.
  struct Point {
    Work tau = 0;
    Work y = 0, v = 0;            // y = w x, v
    Work d1 = 0, d2 = 0, d3 = 0;  // dv/dtau, d2v/dtau2, d3v/dtau3 (d3: with bounds only)
    Work e_y = 0, e_v = 0, e_d1 = 0, e_d2 = 0, e_d3 = 0;  // rounding-error bounds
    Work tail = 0;   // (A): S = sqrt(v''^2 + rho^2 v'^2) plus rounding
    Work tail2 = 0;  // (B): sup of |z_h'| from tau on, plus rounding
  };

  // The law holds on [tau_a, segment_end()]: to the end of the record's
  // segment that holds tau_a (for ever without a record).
  LinearSlipLaw(const Oscillator<Work>& oscillator, int sign, const Work& tau_a, const Work& y_a,
                const Work& v_a)
      : o_(&oscillator), s_(sign), tau_a_(tau_a), y_a_(y_a), v_a_(v_a) {
    using std::fabs;
    using std::sqrt;
    const RecordPiece<Work> piece = o_->record().piece_at(tau_a);
    ramp_ = piece.slope;
    segment_end_ = piece.end;
    // g0's rounding: each operation's relative to its result, plus the
    // record value's own (none without one: the bounds stay those of f0 - s r).
    const Work f0 = o_->forcing().constant(), record = piece.value(tau_a);
    g0_ = f0 + record - Work(s_) * o_->r();
    mag_g0_ = fabs(g0_);
    if (record != 0 || piece.slope != 0) mag_g0_ += fabs(f0 + record) + piece.magnitude(tau_a);
    rho_ = sqrt(o_->rho2());
    for (const ForcingTerm<Work>& f : o_->forcing().terms()) {
      const Work theta = f.q * tau_a + f.phase;
      const SinCos<Work> sc = sin_cos(theta);
      // Im(A e^{i q u}) = a sin(theta + q u); theta is rounded by up to
      // |theta| + |phase| ulps (radians per ulp).
      Term term;
      term.a = {f.a * sc.cos, f.a * sc.sin};
      term.arg = fabs(theta) + fabs(f.phase);
      term.ah = term.a * o_->steady()[terms_.size()];
      term.abs_a = fabs(f.a);
      term.q3 = f.q * f.q * f.q;
      term.q4 = term.q3 * f.q;
      term.size_q3 = term.abs_a * o_->steady_abs()[terms_.size()] * term.q3;
      term.size_q4 = term.size_q3 * f.q;
      terms_.push_back(term);
    }
    // c1 = g(tau_a) - s r - rho^2 y_a, the coefficient of G in v, summed once
    // here: the large terms that cancel in it (a stiff spring that breaks
    // away from near its equilibrium: rho^2 y_a ~ g ~ 1 with c1 ~ 1e-16) are
    // then not each carried with G's own rounding, which grows with rho u
    // (theory.md 7.3; a stop ten thousand natural periods into such a slip
    // was taken for a touch within that noise).
    const Work eps = std::numeric_limits<Work>::epsilon();
    c1_ = g0_ - o_->rho2() * y_a_;
    Work mag_c1 = mag_g0_ + o_->rho2() * fabs(y_a_), phase_c1 = 0;
    for (std::size_t i = 0; i < terms_.size(); ++i) {
      c1_ += terms_[i].a.im;
      mag_c1 += fabs(terms_[i].a.im);
      phase_c1 += fabs(o_->forcing().terms()[i].a) * terms_[i].arg;
    }
    e_c1_ = kUlps * eps * mag_c1 + eps * phase_c1;
  }

  int sign() const { return s_; }
  const Work& tau_begin() const { return tau_a_; }
  const Work& segment_end() const { return segment_end_; }

  // The slip from this law's state at tau (its segment's end) on, under the
  // law of the segment that holds tau: the engine and dense output carry a
  // slip across the record's samples this one way.
  LinearSlipLaw continued_at(const Work& tau) const { return continued_from(point(tau, false)); }
  // The same from a point of this law at its segment's end already evaluated
  // (its y and v are those of point(tau, false): the same closed form).
  LinearSlipLaw continued_from(const Point& q) const {
    return LinearSlipLaw(*o_, s_, q.tau, q.y, q.v);
  }

  // The state and derivatives at tau; with_bounds: also v''', the
  // rounding-error bounds and the tail, which only the event search needs
  // (without: y, v, v' and v'', the same values bit for bit; the root
  // polish reads v'' of plain points).
  Point point(const Work& tau, bool with_bounds = true) const {
    return with_bounds ? evaluate<true>(tau) : evaluate<false>(tau);
  }

  // Whether a point with bounds at `from` can be moved to `tau` (moved()):
  // |tau - from| times the fastest rate <= sqrt(eps) (about 2^-32 for long
  // double), so that the terms the Taylor steps leave out, second order in
  // that product for v' and third for y and v, stay below an ulp of the work
  // type: a polish from a good guess ends some 2^-36 away; the 50-digit
  // instance, whose epsilon is far smaller, evaluates afresh.
  bool can_move(const Work& from, const Work& tau) const {
    using std::fabs;
    using std::sqrt;
    static const Work limit = sqrt(std::numeric_limits<Work>::epsilon());
    return fabs(tau - from) * o_->fastest_rate() <= limit;
  }

  // The point with bounds at tau from the one at p.tau by Taylor's theorem,
  // when can_move(p.tau, tau): a stop's polish ends a few ulps from the
  // point it last evaluated, and this costs a few operations where a new
  // evaluation costs a few sin_cos (docs/theory.md 7.4). With a = |tau - p.tau|
  // and v''' = g'' - 2 sigma v'' - rho^2 v' (the slip's equation
  // differentiated; the record's ramp has g'' = 0), the suprema over the
  // step A >= |v'''|, B >= |v''|, C >= |v'| satisfy B <= b0 + a A,
  // C <= c0 + a B, so A (1 - 2 sigma a - rho^2 a^2) <= G2 + 2 sigma b0 +
  // rho^2 (c0 + a b0), with b0, c0 the bounds of |v''|, |v'| at p.tau; each
  // moved value carries its Lagrange remainder and its rounding in its bound.
  // v''' is not moved: its bound becomes infinite, which leaves the tail
  // (A) of third_bound (from v', v'' and their bounds) and drops (B).
  Point moved(const Point& p, const Work& tau) const {
    using std::fabs;
    using std::sqrt;
    const Work eps = std::numeric_limits<Work>::epsilon();
    const Work delta = tau - p.tau, a = fabs(delta);
    const Work sigma2 = 2 * o_->sigma(), rho2 = o_->rho2();
    const Work b0 = fabs(p.d2) + p.e_d2, c0 = fabs(p.d1) + p.e_d1;
    const Work sup3 = 2 * (o_->forcing().bound(2) + sigma2 * b0 + rho2 * (c0 + a * b0));
    const Work sup2 = b0 + a * sup3;
    const Work growth = 1 + 16 * eps;  // the rounding of the bounds themselves
    Point q = p;
    q.tau = tau;
    // y and v to second order (their remainders are third order), v' to first.
    q.y = p.y + delta * (p.v + delta * p.d1 / 2);
    q.v = p.v + delta * (p.d1 + delta * p.d2 / 2);
    q.d1 = p.d1 + p.d2 * delta;
    q.e_y = (p.e_y + p.e_v * a + p.e_d1 * a * a / 2 + sup2 * a * a * a / 6 +
             4 * eps * (fabs(p.y) + a * (fabs(p.v) + a * fabs(p.d1)))) *
            growth;
    q.e_v = (p.e_v + p.e_d1 * a + p.e_d2 * a * a / 2 + sup3 * a * a * a / 6 +
             4 * eps * (fabs(p.v) + a * (fabs(p.d1) + a * fabs(p.d2)))) *
            growth;
    q.e_d1 =
        (p.e_d1 + p.e_d2 * a + sup3 * a * a / 2 + 4 * eps * (fabs(p.d1) + fabs(p.d2 * delta))) *
        growth;
    q.e_d2 = (p.e_d2 + sup3 * a) * growth;
    q.e_d3 = std::numeric_limits<Work>::infinity();
    q.tail = tail_of(q);
    q.tail2 = std::numeric_limits<Work>::infinity();
    return q;
  }

 private:
  template <bool kBounds>
  Point evaluate(const Work& tau) const {
    using std::fabs;
    using std::sqrt;
    const Work eps = std::numeric_limits<Work>::epsilon();
    const Work rho2 = o_->rho2();
    const Work u = tau - tau_a_;
    const Transition<Work> t = o_->transition().template at<kBounds>(u);
    const auto& forcing = o_->forcing().terms();
    const auto& responses = o_->responses();
    RootExp<Work> root_exp;
    bool have_root_exp = false;
    // The harmonics' part of y (Im(A R)) and of v, v', v'', v''' less their
    // G terms (Im(A Q_k)), with magnitudes and argument-rounding terms:
    // R' = i q R + G, so R^(k+1) = Q_k + G^(k) with Q_0 = i q R and
    // Q_(k+1) = i q (Q_k + G^(k)); the G^(k) parts go into c1 (above).
    Work forced_y = 0, mag_forced_y = 0, phase_y = 0;
    Work forced[4] = {0, 0, 0, 0}, mag_forced[4] = {0, 0, 0, 0};
    Work phase[4] = {0, 0, 0, 0};
    // The steady response's v_p'' and v_p''' (for bound (B)), with magnitudes.
    Work steady2 = 0, steady3 = 0, mag_steady2 = 0, mag_steady3 = 0;
    for (std::size_t i = 0; i < forcing.size(); ++i) {
      const Work q = forcing[i].q;
      const ForcedResponse<Work>& response = responses[i];
      const bool beyond_series = response.needs_root_exp(u);
      // e^{i q u}: the response needs it beyond its series only; within,
      // only the bounds' steady response below does, where two Taylor terms
      // do for the tiny u after a start (no sin_cos; exactly 1 at u = 0).
      Complex<Work> e{1, 0};
      if (beyond_series) {
        const SinCos<Work> sc = sin_cos(Work(q * u));
        e = {sc.cos, sc.sin};
      } else if (kBounds && u != 0) {
        e = small_angle(Work(q * u));
      }
      if (!have_root_exp && beyond_series) {
        root_exp = o_->transition().root_exp(u, t);
        have_root_exp = true;
      }
      const HarmonicResponseAt<Work> h = response.template at<kBounds>(u, t, e, root_exp);
      // From R, not from the ODE of R: heavily damped, -2 sigma R' would
      // cancel e^{i q u} to rounding noise of the fast root's size.
      const Complex<Work> iq{0, q};
      const Complex<Work> q0 = iq * h.r;
      const Complex<Work> q1 = iq * (q0 + Complex<Work>{t.g, 0});
      const Complex<Work> q2 = iq * (q1 + Complex<Work>{t.dg, 0});
      const Complex<Work>& a = terms_[i].a;
      forced_y += (a * h.r).im;
      forced[0] += (a * q0).im;
      forced[1] += (a * q1).im;
      forced[2] += (a * q2).im;
      if constexpr (kBounds) {  // v''' only for the bounds
        const Complex<Work> q3c = iq * (q2 + Complex<Work>{t.g2, 0});
        forced[3] += (a * q3c).im;
        const Term& term = terms_[i];
        const Work& abs_a = term.abs_a;
        const Work mag_q0 = q * h.mag_r;
        const Work mag_q1 = q * (mag_q0 + t.mag_g);
        const Work mag_q2 = q * (mag_q1 + t.mag_dg);
        const Work mag_q3 = q * (mag_q2 + t.mag_g2);
        const Work mags[4] = {mag_q0, mag_q1, mag_q2, mag_q3};
        // A's argument theta(tau_a) is rounded by up to `arg` ulps.
        const Work arg = term.arg, qu = q * u;
        mag_forced_y += abs_a * h.mag_r;
        phase_y += abs_a * h.mag_r * arg;
        for (int k = 0; k < 4; ++k) {
          mag_forced[k] += abs_a * mags[k];
          phase[k] += abs_a * mags[k] * arg;
        }
        // v_p = Im(A H i q e^{i q u}): v_p'' = Im(-i q^3 A H e), v_p''' = Im(q^4 A H e).
        const Complex<Work> ahe = term.ah * e;
        steady2 -= term.q3 * ahe.re;
        steady3 += term.q4 * ahe.im;
        mag_steady2 += term.size_q3 * (1 + arg + qu);
        mag_steady3 += term.size_q4 * (1 + arg + qu);
      }
    }
    // The homogeneous part's derivatives from those of G (transition.hpp),
    // not from the ODE with the whole forcing:
    // while the motion decays towards an equilibrium (an overdamped
    // approach) they keep their relative accuracy, where g - rho^2 y would
    // cancel to rounding noise of the force and stall the event search.
    const Work &g2 = t.g2, &g3 = t.g3, &g4 = t.g4;
    Point p;
    p.tau = tau;
    p.y = t.phi11 * y_a_ + t.g * v_a_ + g0_ * t.g1 + forced_y;
    p.v = c1_ * t.g + t.dg * v_a_ + forced[0];
    p.d1 = c1_ * t.dg + g2 * v_a_ + forced[1];
    p.d2 = c1_ * g2 + g3 * v_a_ + forced[2];
    // The record's ramp d u: d G2 in y, d G1 in v, d G in v', and so on.
    const Work& d = ramp_;
    if (d != 0) {
      p.y += d * t.ramp;
      p.v += d * t.g1;
      p.d1 += d * t.g;
      p.d2 += d * t.dg;
    }
    if constexpr (!kBounds) return p;
    p.d3 = c1_ * g3 + g4 * v_a_ + forced[3] + d * g2;
    // Rounding: kUlps ulps of the sum of the terms' magnitudes, plus the
    // rounding of the harmonics' arguments (phase), plus c1's own error
    // times the G^(k) it multiplies (their values: the argument rounding of
    // G^(k) is in the magnitudes, times |c1|).
    const Work &mag_g2 = t.mag_g2, &mag_g3 = t.mag_g3, &mag_g4 = t.mag_g4;
    const Work ay = fabs(y_a_), av = fabs(v_a_), a0 = mag_g0_, ac = fabs(c1_), ad = fabs(d);
    const Work k = kUlps * eps;
    const auto c1_error = [&](const Work& value, const Work& mag) {
      return e_c1_ * (fabs(value) + k * mag);
    };
    const Work mag_y =
        t.mag_phi11 * ay + t.mag_g * av + a0 * t.mag_g1 + ad * t.mag_ramp + mag_forced_y;
    const Work mag_v = ac * t.mag_g + t.mag_dg * av + ad * t.mag_g1 + mag_forced[0];
    const Work mag_d1 = ac * t.mag_dg + mag_g2 * av + ad * t.mag_g + mag_forced[1];
    const Work mag_d2 = ac * mag_g2 + mag_g3 * av + ad * t.mag_dg + mag_forced[2];
    const Work mag_d3 = ac * mag_g3 + mag_g4 * av + ad * mag_g2 + mag_forced[3];
    p.e_y = k * mag_y + eps * phase_y;
    p.e_v = k * mag_v + eps * phase[0] + c1_error(t.g, t.mag_g);
    p.e_d1 = k * mag_d1 + eps * phase[1] + c1_error(t.dg, t.mag_dg);
    p.e_d2 = k * mag_d2 + eps * phase[2] + c1_error(g2, mag_g2);
    p.e_d3 = k * mag_d3 + eps * phase[3] + c1_error(g3, mag_g3);
    // S = sqrt(w'^2 + rho^2 w^2) at tau, w = v' (see the top of this file).
    p.tail = tail_of(p);
    // (B): z_h = v'' - v_p'', z_h' = v''' - v_p''' at tau.
    const Work z = fabs(p.d2 - steady2) + p.e_d2 + k * mag_steady2;
    const Work dz = fabs(p.d3 - steady3) + p.e_d3 + k * mag_steady3;
    p.tail2 = sqrt(rho2 * z * z + dz * dz) * (1 + 16 * eps);
    return p;
  }

 public:
  // The jet of f = s v at a point, for the event search.
  Jet<Work> jet(const Point& q) const {
    const Work s(s_);
    return {s * q.v, s * q.d1, s * q.d2, q.e_v, q.e_d1, q.e_d2, q.tail, q.tail2};
  }

  // >= sup |f'''| on [tau, tau + h], given the point at tau (with bounds).
  Work third_bound(const Work& tau, const Jet<Work>& at, const Work& h) const {
    (void)tau;
    const Work g2 = o_->forcing().bound(2);
    const Work a = g2 + (2 * o_->sigma() + rho_) * (at.tail + h * g2);
    const Work b = o_->steady_bound4() + at.tail2;
    return (b < a ? b : a) * (1 + 64 * std::numeric_limits<Work>::epsilon());
  }

  // Acceleration dv/dt = w dv/dtau.
  Work acceleration(const Point& q) const { return o_->omega() * q.d1; }

 private:
  static constexpr int kUlps = 64;

  // Bound (A)'s S = sqrt(v''^2 + rho^2 v'^2) at a point, from v', v'' and
  // their rounding bounds (the top of this file).
  Work tail_of(const Point& p) const {
    using std::fabs;
    using std::sqrt;
    const Work w = fabs(p.d1) + p.e_d1, dw = fabs(p.d2) + p.e_d2;
    return sqrt(dw * dw + o_->rho2() * w * w) * (1 + 16 * std::numeric_limits<Work>::epsilon());
  }

  // e^{i x}: Taylor to x^3 and x^4 for |x| <= 2^-16 (the terms left out are
  // below 2^-70 of the result), else sin_cos.
  static Complex<Work> small_angle(const Work& x) {
    using std::fabs;
    if (!(fabs(x) <= Work(0x1p-16))) {
      const SinCos<Work> sc = sin_cos(x);
      return {sc.cos, sc.sin};
    }
    const Work x2 = x * x;
    return {1 - x2 / 2 + x2 * x2 / 24, x - x * x2 / 6};
  }

  struct Term {
    Complex<Work> a;  // a e^{i theta(tau_a)}
    Work arg = 0;     // ulps of rounding in theta(tau_a), in radians per ulp
    // For the bounds, once per law: A H, |a|, q^3, q^4, |a| |H| q^3, |a| |H| q^4.
    Complex<Work> ah;
    Work abs_a = 0, q3 = 0, q4 = 0, size_q3 = 0, size_q4 = 0;
  };

  const Oscillator<Work>* o_;
  int s_;
  Work tau_a_, y_a_, v_a_;
  Work ramp_ = 0;           // d: the record's slope on the law's segment
  Work segment_end_ = 0;    // where that segment ends (+infinity without a record)
  Work g0_ = 0;             // f0 + r_g(tau_a) - s r
  Work mag_g0_ = 0;         // the magnitude of its terms
  Work c1_ = 0, e_c1_ = 0;  // g(tau_a) - s r - rho^2 y_a and its rounding bound
  Work rho_ = 0;
  // (Inline for up to four harmonics: a law is built for every slip.)
  boost::container::small_vector<Term, 4> terms_;
};

}  // namespace frictionref::detail
