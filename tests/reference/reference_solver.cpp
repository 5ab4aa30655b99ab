// The 50-digit reference solver (see reference_solver.hpp for the method).
#include "reference_solver.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <boost/math/constants/constants.hpp>

namespace frictionref_reference {

namespace {

const Real& pi() {
  static const Real value = boost::math::constants::pi<Real>();
  return value;
}

// s v along a slip of sign s that starts at tau = a with velocity v_a:
//   f(tau) = s v_a + s b (cos a - cos tau) - r (tau - a),
// positive while the slip lasts; its second derivative is s b cos tau, so
// |f''| <= b everywhere (r drops out).
class SlipSpeed {
 public:
  SlipSpeed(int s, const Real& a, const Real& v_a, const Real& b, const Real& r,
            std::uint64_t& evaluations)
      : s_(s), a_(a), b_(b), r_(r), evaluations_(evaluations) {
    using boost::multiprecision::cos;
    constant_ = Real(s) * (v_a + b * cos(a));
  }

  Real operator()(const Real& tau) {
    using boost::multiprecision::cos;
    ++evaluations_;
    return constant_ - Real(s_) * b_ * cos(tau) - r_ * (tau - a_);
  }

  const Real& b() const { return b_; }

 private:
  int s_;
  Real a_, b_, r_, constant_;
  std::uint64_t& evaluations_;
};

// The first zero of f in (u, w], given f(u) = fu > 0 and f(w) = fw, using
// only |f''| <= b: returns false if there is none. Halves the interval, left
// half first, so the answer is the first zero and, once a sign change is
// bracketed, the halving is a bisection to the last bit of Real.
bool first_zero(SlipSpeed& f, const Real& u, const Real& w, const Real& fu, const Real& fw,
                Real& root, std::uint64_t& refinements) {
  const Real width = w - u;
  const Real bound = f.b() * width * width / 8;
  if (fu > bound && fw > bound) return false;  // above the chord minus b h^2 / 8
  const Real m = (u + w) / 2;
  if (!(m > u && m < w)) {  // at the resolution of Real
    if (fw <= 0) {
      root = w;
      return true;
    }
    std::ostringstream text;
    text << std::setprecision(50) << "reference: unresolved tangency of v near tau = " << w
         << " (s v = " << fu << ", " << fw << ")";
    throw std::runtime_error(text.str());
  }
  ++refinements;
  const Real fm = f(m);
  if (fm <= 0) {
    // A zero in (u, m] for sure; search it (it may not be the only one).
    if (first_zero(f, u, m, fu, fm, root, refinements)) return true;
    // Unreachable in exact arithmetic: fm <= 0 forces a zero in (u, m].
    root = m;
    return true;
  }
  if (first_zero(f, u, m, fu, fm, root, refinements)) return true;
  return first_zero(f, m, w, fm, fw, root, refinements);
}

void check_input(const RealInput& in, const Real& t_end) {
  using boost::multiprecision::isfinite;
  const Real* fields[] = {&in.mass, &in.amplitude, &in.omega, &in.friction,
                          &in.x0,   &in.v0,        &in.t0,    &t_end};
  for (const Real* f : fields)
    if (!isfinite(*f)) throw std::invalid_argument("reference: non-finite input");
  if (!(in.mass > 0) || !(in.omega > 0) || in.amplitude < 0 || in.friction < 0)
    throw std::invalid_argument("reference: need m > 0, w > 0, B >= 0, R >= 0");
  if (!(t_end > in.t0)) throw std::invalid_argument("reference: need t_end > t0");
}

// What comes next: a slip of sign `sign` (0: a rest decision) from (tau, x, v).
struct Next {
  int sign = 0;
  Start start = Start::initial;
  Real tau = 0, x = 0, v = 0;
  bool done = false;
};

class Solver {
 public:
  Solver(const RealInput& model, const Real& t_end, const Options& options)
      : model_(model), options_(options) {
    check_input(model, t_end);
    result_.model = model;
    result_.t_end = t_end;
    m_ = model.mass;
    B_ = model.amplitude;
    R_ = model.friction;
    w_ = model.omega;
    b_ = B_ / (m_ * w_);
    r_ = R_ / (m_ * w_);
    tau_end_ = w_ * t_end;
    has_breakaway_ = B_ > R_;
    if (has_breakaway_) {
      using boost::multiprecision::asin;
      breakaway_ = asin(R_ / B_);
    }
  }

  Result run() {
    // A loop over phases: each step is a slip or a rest decision.
    Next next;
    next.tau = w_ * model_.t0;
    next.x = model_.x0;
    next.v = model_.v0;
    next.start = Start::initial;
    next.sign = model_.v0 > 0 ? 1 : model_.v0 < 0 ? -1 : 0;
    while (!next.done && !full()) {
      if (next.sign == 0)
        next = at_rest(next.start, next.tau, next.x);
      else
        next = slip(next.sign, next.start, next.tau, next.x, next.v);
    }
    return std::move(result_);
  }

 private:
  Real time_of(const Real& tau, Start start) const {
    // t0 and the horizon are kept exactly; every other boundary is tau / w.
    if (start == Start::initial && result_.phases.empty()) return model_.t0;
    return tau / w_;
  }

  Real accel(int s, const Real& tau) const {
    using boost::multiprecision::sin;
    return (B_ * sin(tau) - Real(s) * R_) / m_;
  }

  bool full() {
    if (result_.phases.size() < options_.max_phases) return false;
    result_.phase_limit = true;
    return true;
  }

  static Next slip_next(int s, Start start, const Real& tau, const Real& x) {
    Next n;
    n.sign = s;
    n.start = start;
    n.tau = tau;
    n.x = x;
    n.v = 0;
    return n;
  }

  // Which closed-form crossing of |B sin tau| = R lies within kSnap of tau:
  // +1 / -1 a forward / backward breakaway (alpha, pi + alpha), 0 a release
  // (pi - alpha, 2 pi - alpha: the force falls back into the band), 2 none.
  // Breakaways win ties (lambda = 0, where the band has no width).
  int near_crossing(const Real& tau, Real& crossing) const {
    using boost::multiprecision::abs;
    using boost::multiprecision::round;
    if (!has_breakaway_) return 2;
    const Real two_pi = 2 * pi();
    const Real snap = Real("1e-20") * (abs(tau) > 1 ? Real(abs(tau)) : Real(1));
    const Real bases[4] = {breakaway_, pi() + breakaway_, pi() - breakaway_,
                           two_pi - breakaway_};
    const int kinds[4] = {1, -1, 0, 0};
    for (int i = 0; i < 4; ++i) {
      const Real c = bases[i] + two_pi * round((tau - bases[i]) / two_pi);
      if (abs(c - tau) <= snap) {
        crossing = c;
        return kinds[i];
      }
    }
    return 2;
  }

  // The mass is at rest at tau with position x: slip at once, or stick.
  // The rule of THEORY.md (B sin tau > R: forward, < -R: backward, else
  // stick), except within 1e-20 rad of a closed-form crossing of |F| = R,
  // where the crossing decides: there the sign of B sin tau -+ R is not
  // resolved by a root that is itself only known to ~1e-25 at a tangency
  // (a touch: v = 0 at a minimum of s v). At 1e-20 rad both outcomes give
  // the same motion to far below double resolution.
  Next at_rest(Start start, const Real& tau, const Real& x) {
    using boost::multiprecision::ceil;
    using boost::multiprecision::sin;
    Real crossing = 0;
    const int near = near_crossing(tau, crossing);
    if (near != 2 && !result_.phases.empty()) result_.phases.back().decided_by_crossing = true;
    if (near == 1 || near == -1) {
      const Real from = crossing > tau ? crossing : tau;
      if (from >= tau_end_) return stick_to_horizon(start, tau, x);
      if (from > tau) emit_stick(start, tau, from, x, false);
      return slip_next(near, Start::breakaway, from, x);
    }
    if (near == 2) {
      const Real force = B_ * sin(tau);
      const Start slip_start = start == Start::initial ? start : Start::from_stop;
      if (force > R_) return slip_next(1, slip_start, tau, x);
      if (force < -R_) return slip_next(-1, slip_start, tau, x);
    }
    // Stuck until the next breakaway after tau, if any.
    if (!has_breakaway_) return stick_to_horizon(start, tau, x);
    const Real two_pi = 2 * pi();
    const Real forward = breakaway_ + two_pi * ceil((tau - breakaway_) / two_pi);
    const Real backward = pi() + breakaway_ + two_pi * ceil((tau - pi() - breakaway_) / two_pi);
    const int direction = forward <= backward ? 1 : -1;
    const Real next = direction > 0 ? forward : backward;
    if (next >= tau_end_) return stick_to_horizon(start, tau, x);
    if (next > tau) emit_stick(start, tau, next, x, false);
    return slip_next(direction, Start::breakaway, next > tau ? next : tau, x);
  }

  Next stick_to_horizon(Start start, const Real& tau, const Real& x) {
    emit_stick(start, tau, tau_end_, x, true);
    Next n;
    n.done = true;
    return n;
  }

  void emit_stick(Start start, const Real& tau_a, const Real& tau_b, const Real& x,
                  bool at_horizon) {
    Phase p;
    p.kind = Kind::stick;
    p.start = start == Start::initial ? Start::initial : Start::stop;
    p.tau_begin = tau_a;
    p.tau_end = tau_b;
    p.t_begin = time_of(tau_a, start);
    p.t_end = at_horizon ? result_.t_end : tau_b / w_;
    p.x_begin = p.x_end = x;
    p.at_horizon = at_horizon;
    result_.phases.push_back(p);
  }

  // A slip of sign s from tau = a with (x_a, v_a); chains into what follows.
  Next slip(int s, Start start, const Real& a, const Real& x_a, const Real& v_a) {
    using boost::multiprecision::cos;
    using boost::multiprecision::sin;
    SlipSpeed f(s, a, v_a, b_, r_, result_.velocity_evaluations);

    // Where the scan may begin: f(a) = s v_a > 0, or, at v_a = 0, the end of
    // a zone (a, a + d0] in which Taylor's bound proves f > 0:
    //   f(a + d) >= p1 d - b d^2 / 2           (> 0 for d < 2 p1 / b)
    //   f(a + d) >= p1 d + p2 d^2 / 2 - b d^3 / 6  (> 0 for d < 3 p2 / b, p1 >= 0)
    // with p1 = f'(a) = s b sin a - r (0 at a breakaway, exactly) and
    // p2 = f''(a) = s b cos a.
    Real u = a;
    if (v_a == 0) {
      const Real p1 = start == Start::breakaway ? Real(0) : Real(s) * b_ * sin(a) - r_;
      const Real p2 = Real(s) * b_ * cos(a);
      Real d0 = 0;
      if (p1 > 0) d0 = p1 / b_;
      if (p1 >= 0 && p2 > 0 && 1.5 * p2 / b_ > d0) d0 = 1.5 * p2 / b_;
      if (!(d0 > 0))
        throw std::runtime_error("reference: a slip from rest that cannot start");
      if (d0 > options_.step) d0 = options_.step;
      u = a + d0;
    }

    Real stop = 0;
    bool stops = false;
    if (u < tau_end_) {
      Real fu = f(u);
      if (!(fu > 0)) throw std::runtime_error("reference: s v not positive after a slip start");
      for (;;) {
        Real w = u + options_.step;
        if (w > tau_end_) w = tau_end_;
        const Real fw = f(w);
        if (first_zero(f, u, w, fu, fw, stop, result_.refinements)) {
          stops = true;
          break;
        }
        if (w == tau_end_) break;
        u = w;
        fu = fw;
      }
    }

    Phase p;
    p.kind = s > 0 ? Kind::slip_forward : Kind::slip_backward;
    p.start = start;
    p.tau_begin = a;
    p.tau_end = stops ? stop : tau_end_;
    p.t_begin = time_of(a, start);
    p.t_end = stops ? stop / w_ : result_.t_end;
    p.x_begin = x_a;
    p.v_begin = v_a;
    p.at_horizon = !stops;
    p.accel_begin = accel(s, a);
    p.accel_end = accel(s, p.tau_end);
    p.jerk_end = B_ * w_ * cos(p.tau_end) / m_;
    const Real h = p.tau_end - a;
    p.x_end = x_a + (v_a * h + b_ * (h * cos(a) - (sin(p.tau_end) - sin(a))) -
                     Real(s) * r_ * h * h / 2) /
                        w_;
    p.v_end = stops ? Real(0) : v_a + b_ * (cos(a) - cos(p.tau_end)) - Real(s) * r_ * h;
    result_.phases.push_back(p);
    Next n;
    if (stops) {
      n.tau = stop;
      n.x = p.x_end;
      n.start = Start::stop;
    } else {
      n.done = true;
    }
    return n;
  }

  RealInput model_;
  Options options_;
  Result result_;
  Real m_, B_, R_, w_, b_, r_, tau_end_, breakaway_;
  bool has_breakaway_ = false;
};

}  // namespace

std::string Input::describe() const {
  std::ostringstream text;
  text << std::setprecision(17) << "m=" << mass << " B=" << amplitude << " w=" << omega
       << " R=" << friction << " x0=" << x0 << " v0=" << v0 << " t0=" << t0;
  return text.str();
}

RealInput RealInput::from_double(const Input& in) {
  RealInput r;
  r.mass = Real(in.mass);
  r.amplitude = Real(in.amplitude);
  r.omega = Real(in.omega);
  r.friction = Real(in.friction);
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
  if (!(options.step > 0)) throw std::invalid_argument("reference: step must be > 0");
  return Solver(model, t_end, options).run();
}

StateR evaluate(const RealInput& model, const Phase& phase, const Real& t) {
  using boost::multiprecision::cos;
  using boost::multiprecision::sin;
  StateR st;
  const int s = sign_of(phase.kind);
  if (s == 0) {
    st.x = phase.x_begin;
    return st;
  }
  const Real b = model.amplitude / (model.mass * model.omega);
  const Real r = model.friction / (model.mass * model.omega);
  const Real a = phase.tau_begin;
  const Real tau = model.omega * t;
  const Real h = tau - a;
  st.v = phase.v_begin + b * (cos(a) - cos(tau)) - Real(s) * r * h;
  st.x = phase.x_begin +
         (phase.v_begin * h + b * (h * cos(a) - (sin(tau) - sin(a))) - Real(s) * r * h * h / 2) /
             model.omega;
  st.a = (model.amplitude * sin(tau) - Real(s) * model.friction) / model.mass;
  return st;
}

Real regime_threshold() {
  using boost::multiprecision::sqrt;
  return 2 / sqrt(4 + pi() * pi());
}

}  // namespace frictionref_reference
