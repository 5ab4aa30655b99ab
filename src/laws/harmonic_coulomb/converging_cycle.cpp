// The seed's continuous sliding from a reversal near its fixed point: the
// linear transient in double-double with certified bounds, its 50-digit
// fallbacks (converging_cycle.hpp, docs/theory.md 3.10).
#include "laws/harmonic_coulomb/converging_cycle.hpp"

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>

#include "laws/harmonic_coulomb/phase_law.hpp"
#include "numeric/sin_cos.hpp"

namespace frictionref::detail {
namespace {

using double_double::add;
using double_double::decided;
using double_double::kErrorPerMagnitude;
using double_double::scaled;
using double_double::split;

constexpr double kUnit = 0x1p-53;
// Added to every bound: covers what underflow loses in the vanishing
// transient's terms (each at most 2^-1074 absolute).
constexpr double kTiny = 0x1p-1000;
constexpr double kFloor = 0x1p-400;
// The 50-digit sums' own rounding, relative to their terms (about 1e-50).
const HighPrecision kHighSlack("1e-45");

// An upper bound in double of a positive 50-digit value.
double up(const HighPrecision& value) { return static_cast<double>(value) * (1 + 0x1p-50); }

bool even(std::int64_t n) { return n % 2 == 0; }

// kappa^k for kappa < 0.
HighPrecision power(const HighPrecision& kappa, std::int64_t k) {
  const HighPrecision size = pow(-kappa, HighPrecision(k));
  return even(k) ? size : HighPrecision(-size);
}

}  // namespace

long double ConvergingCycle::fixed_phase(long double b, long double r) {
  const long double c = r * boost::math::constants::pi<long double>() / (2 * b);
  // Continuous sliding: the force at the reversal, b sin u*, beats r.
  if (!(b > 0) || !(r > 0) || !(c < 1) || !(b * std::sqrt((1 - c) * (1 + c)) > r))
    return std::numeric_limits<long double>::quiet_NaN();
  return std::acos(c);
}

std::optional<ConvergingCycle> ConvergingCycle::compute(const Model& model) {
  using std::abs;
  if (!model.is_harmonic_coulomb() || !(model.amplitude > 0) || !(model.friction > 0))
    return std::nullopt;
  ConvergingCycle cycle;
  const BasicModel<HighPrecision> m = model_cast<HighPrecision>(model);
  cycle.pi_ = boost::math::constants::pi<HighPrecision>();
  cycle.omega_ = m.omega;
  cycle.b_ = m.amplitude / (m.mass * m.omega);
  cycle.r_ = m.friction / (m.mass * m.omega);
  const HighPrecision& b = cycle.b_;
  const HighPrecision& r = cycle.r_;
  // The fixed point: a slip from rest at u* + n pi reverses at u* + (n+1) pi
  // when 2 b cos u* = r pi (theory.md 5.4).
  const HighPrecision c = r * cycle.pi_ / (2 * b);
  if (!(c < 1)) return std::nullopt;
  cycle.u_star_ = acos(c);
  cycle.cos_star_ = c;
  cycle.sin_star_ = sqrt((1 - c) * (1 + c));
  const HighPrecision s = b * cycle.sin_star_;  // the force at the reversal
  // The next slip must start at once, clearly (no dead band): the force
  // beats friction there.
  if (!(s - r >= HighPrecision(0x1p-20) * b)) return std::nullopt;
  cycle.kappa_ = -(s - r) / (s + r);
  const HighPrecision kappa_abs = abs(cycle.kappa_);
  if (!(kappa_abs <= HighPrecision(0.995))) return std::nullopt;
  // On the ball |u - u*| <= rho (theory.md 3.10): |G'(u) - kappa| <= K |u - u*|
  // with K = b (1 + |kappa|) / (s + r - b rho), so |G'| <= L = |kappa| + K rho;
  // and the slide's derivative varies by at most M |e|,
  // M = (1 + L) (s - r + b rho) + pi b.
  const HighPrecision rho(kMaxDeviation);
  const HighPrecision k_lip = b * (1 + kappa_abs) / (s + r - b * rho);
  const HighPrecision l = kappa_abs + k_lip * rho;
  if (!(l <= HighPrecision(0.996))) return std::nullopt;
  const HighPrecision m_lip = (1 + l) * (s - r + b * rho) + cycle.pi_ * b;
  cycle.phi1_ = cycle.pi_ * (r - s);
  cycle.l_ = l;
  cycle.k_lip_ = k_lip;
  cycle.m_lip_ = m_lip;
  cycle.l_up_ = up(l);
  cycle.kappa_d_ = static_cast<double>(cycle.kappa_);
  cycle.half_period_ = split(cycle.pi_ / cycle.omega_);
  cycle.fixed_time_ = split(cycle.u_star_ / cycle.omega_);
  cycle.slide_ = split(2 * s / cycle.omega_);
  cycle.fixed_acceleration_ = split(cycle.omega_ * (s + r));
  cycle.inverse_omega_up_ = up(1 / cycle.omega_);
  cycle.omega_b_up_ = up(cycle.omega_ * b);
  cycle.cos_star_up_ = up(cycle.cos_star_);
  return cycle;
}

bool ConvergingCycle::start(const long double& tau, const long double& x, int direction) {
  using std::abs;
  const HighPrecision at(tau);
  const HighPrecision turns = round((at - u_star_) / pi_);
  if (!(abs(turns) < HighPrecision(0x1p52))) return false;
  const std::int64_t n = static_cast<std::int64_t>(turns);
  const HighPrecision u = at - HighPrecision(n) * pi_;
  const HighPrecision e = u - u_star_;
  if (!(abs(e) <= HighPrecision(kMaxDeviation))) return false;
  // Forward slips start near u* + 2 k pi, backward ones near u* + (2k+1) pi.
  if ((direction > 0) != even(n)) return false;
  n0_ = n;
  x0_ = x;
  u0_ = u;
  e0_ = e;
  e0_abs_ = up(abs(e));
  x0_pair_ = split(x);
  time_transient_ = static_cast<double>(e / omega_);
  slide_transient_ = static_cast<double>(phi1_ * e / ((1 + kappa_) * omega_));
  acceleration_transient_ = static_cast<double>(omega_ * b_ * cos_star_ * e);
  // The rests (theory.md 3.10): |rho_k| <= (K e0^2 / (2 (1 - L))) L^(k-1),
  // their sum <= K e0^2 / (2 (1 - L)^2), and sum_j (L^j e0)^2 <= e0^2 / (1 - L^2).
  const HighPrecision e2 = e * e;
  rest_per_lk_ = up(k_lip_ * e2 / (2 * (1 - l_) * l_));
  x_rest_ = up((abs(phi1_) * k_lip_ * e2 / (2 * (1 - l_) * (1 - l_)) +
                m_lip_ / 2 * e2 / ((1 - l_) * (1 + l_))) /
               omega_);
  current_ = Cursor{};
  next_ = step(current_);
  steady_x_known_[0] = steady_x_known_[1] = steady_a_known_ = false;
  exact_k_ = 0;
  exact_u_ = u;
  exact_x_ = HighPrecision(x);
  return true;
}

ConvergingCycle::Cursor ConvergingCycle::step(const Cursor& c) const {
  // Subnormal numbers would cost a hundred cycles an operation: kappa^k is
  // dropped (0) below 2^-400, and L^k held at 2^-400 from there (still an
  // upper bound of L^k, and of |kappa|^k, which then enters the bounds).
  Cursor n;
  n.k = c.k + 1;
  n.p = c.p * kappa_d_;
  if (std::fabs(n.p) < kFloor) n.p = 0;
  const double lk = c.lk * l_up_ * (1 + 0x1p-50);
  n.lk = lk > kFloor ? lk : kFloor;
  n.r = rest_per_lk_ * n.lk * (1 + 0x1p-50);
  return n;
}

PhaseKind ConvergingCycle::kind_of_slip(std::int64_t k) const {
  return even(n0_ + k) ? PhaseKind::slip_forward : PhaseKind::slip_backward;
}

HighPrecision ConvergingCycle::time_of(std::int64_t k, const HighPrecision& u) const {
  return (HighPrecision(n0_ + k) * pi_ + u) / omega_;
}

HighPrecision ConvergingCycle::acceleration_of(std::int64_t k, const HighPrecision& u) const {
  // At the end of slip k - 1 (direction (-1)^(n0 + k - 1)), the left limit
  // w (b sin tau - s r) = (-1)^(n0 + k) w (b sin u + r).
  const HighPrecision a = omega_ * (b_ * sin(u) + r_);
  return even(n0_ + k) ? a : HighPrecision(-a);
}

ConvergingCycle::Linear ConvergingCycle::linear(const Cursor& c) const {
  using std::abs;
  Linear v;
  const HighPrecision transient = power(kappa_, c.k) * e0_;
  v.tau = HighPrecision(n0_ + c.k) * pi_ + u_star_ + transient;
  v.t = v.tau / omega_;
  v.t_error = HighPrecision(c.r) / omega_ + kHighSlack * abs(v.t);
  // sum_{j<k} (-kappa)^j = (1 - |kappa|^k) / (1 + kappa), kappa < 0.
  const HighPrecision fixed = c.k % 2 != 0 ? HighPrecision(2 * b_ * sin_star_) : HighPrecision(0);
  const HighPrecision slides =
      fixed + phi1_ * e0_ * (1 - pow(-kappa_, HighPrecision(c.k))) / (1 + kappa_);
  const HighPrecision moved = slides / omega_;
  v.x = HighPrecision(x0_) + (even(n0_) ? moved : HighPrecision(-moved));
  v.x_error = HighPrecision(x_rest_) + kHighSlack * (abs(HighPrecision(x0_)) + abs(moved));
  const HighPrecision a = omega_ * (b_ * (sin_star_ + cos_star_ * transient) + r_);
  v.a = even(n0_ + c.k) ? a : HighPrecision(-a);
  const HighPrecision e = HighPrecision(c.lk) * e0_abs_;
  v.a_error = omega_ * b_ * (cos_star_ * c.r + e * e / 2) + kHighSlack * abs(a);
  return v;
}

ConvergingCycle::Exact ConvergingCycle::exact(std::int64_t k) {
  using std::abs;
  if (k < exact_k_) {
    exact_k_ = 0;
    exact_u_ = u0_;
    exact_x_ = HighPrecision(x0_);
  }
  const HighPrecision resolution("1e-48");
  while (exact_k_ < k) {
    // The next reversal: b (cos u + cos u') = r (pi + u' - u), by Newton
    // from the linear guess (one or two steps from ~1e-30 off).
    const HighPrecision& u = exact_u_;
    const HighPrecision cos_u = cos(u), sin_u = sin(u);
    HighPrecision next = u_star_ + kappa_ * (u - u_star_);
    for (int iteration = 0; iteration < 20; ++iteration) {
      const HighPrecision f = b_ * (cos_u + cos(next)) - r_ * (pi_ + next - u);
      const HighPrecision slope = -(b_ * sin(next) + r_);
      const HighPrecision delta = f / slope;
      next -= delta;
      if (abs(delta) < resolution) break;
    }
    // The slide of that slip, (2.2) with v_a = 0 in the reduced phases.
    const HighPrecision h = pi_ + next - u;
    const HighPrecision slide =
        b_ * cos_u * h + b_ * (sin_u + sin(next)) - r_ * h * h / 2;
    exact_x_ += (even(n0_ + exact_k_) ? slide : HighPrecision(-slide)) / omega_;
    exact_u_ = next;
    ++exact_k_;
  }
  return {exact_u_, exact_x_};
}

ConvergingCycle::End ConvergingCycle::end_at(const Cursor& c) {
  using std::fabs;
  End end{kind_of_slip(c.k - 1), 0, 0, 0, 0};
  const double k = static_cast<double>(c.k);
  const double n = static_cast<double>(n0_ + c.k);
  const bool fast = fallback_ == 0;
  // A transient term's relative error (kappa^k), or once dropped, its size
  // relative to its coefficient.
  const double spread = c.p != 0 ? (2 * k + 8) * kUnit : 0;
  const double dropped = c.p != 0 ? 0 : c.lk;
  // Once kappa^k is dropped, x and |a| depend on k only through the parity,
  // and their bounds only shrink (L^k): decided once, they are kept.
  const bool steady = c.p == 0 && fast;

  // t = (n0 + k) pi / w + u* / w + kappa^k e0 / w.
  const double st = c.p * time_transient_;
  DoubleDouble t = add(scaled(n, half_period_), fixed_time_);
  if (st != 0) t = add(t, DoubleDouble{st, 0});
  const double t_error = kErrorPerMagnitude * (fabs(n * half_period_.hi) + fixed_time_.hi + fabs(st)) +
                         fabs(st) * spread + fabs(time_transient_) * dropped +
                         c.r * inverse_omega_up_ * (1 + 0x1p-50) + kTiny;
  const bool t_done = fast && decided(t, t_error, end.t);

  // x = x0 + (-1)^n0 ([k odd] 2 b sin u* + phi1 e0 (1 - |kappa|^k) / (1 + kappa)) / w.
  const bool odd = c.k % 2 != 0;
  bool x_done = steady && steady_x_known_[odd];
  if (x_done) {
    end.x = steady_x_[odd];
  } else {
    const double sign0 = even(n0_) ? 1 : -1;
    const double q = fabs(c.p);
    const double sx = sign0 * (slide_transient_ - slide_transient_ * q);
    DoubleDouble x = x0_pair_;
    if (odd) x = add(x, DoubleDouble{sign0 * slide_.hi, sign0 * slide_.lo});
    x = add(x, DoubleDouble{sx, 0});
    const double x_error =
        kErrorPerMagnitude * (fabs(x0_pair_.hi) + (odd ? fabs(slide_.hi) : 0) + fabs(sx)) +
        fabs(slide_transient_) * (q * spread + dropped + 4 * kUnit) + x_rest_ + kTiny;
    x_done = fast && decided(x, x_error, end.x);
    if (x_done && steady) {
      steady_x_[odd] = end.x;
      steady_x_known_[odd] = true;
    }
  }

  // a = (-1)^(n0 + k) w (b sin u* + r + b cos u* kappa^k e0).
  double acceleration = steady_a_;
  bool a_done = steady && steady_a_known_;
  if (!a_done) {
    const double sa = c.p * acceleration_transient_;
    const DoubleDouble a = add(fixed_acceleration_, DoubleDouble{sa, 0});
    const double e = c.lk * e0_abs_ * (1 + 0x1p-50);
    const double a_error = kErrorPerMagnitude * (fixed_acceleration_.hi + fabs(sa)) +
                           fabs(sa) * spread + fabs(acceleration_transient_) * dropped +
                           omega_b_up_ * (cos_star_up_ * c.r + 0.5 * e * e) * (1 + 0x1p-48) + kTiny;
    a_done = fast && decided(a, a_error, acceleration);
    if (a_done && steady) {
      steady_a_ = acceleration;
      steady_a_known_ = true;
    }
  }
  end.acceleration = even(n0_ + c.k) ? acceleration : -acceleration;
  if (t_done && x_done && a_done) return end;

  // In 50 digits, the same linear transient with its bounds; else exactly.
  end.rounded_in_50_digits = !t_done + !x_done;
  const Linear v = linear(c);
  const bool linear_only = fallback_ < 2;
  const bool t_linear = t_done || (linear_only && decided(v.t, v.t_error, end.t));
  const bool x_linear = x_done || (linear_only && decided(v.x, v.x_error, end.x));
  const bool a_linear = a_done || (linear_only && decided(v.a, v.a_error, end.acceleration));
  if (t_linear && x_linear && a_linear) return end;
  const Exact exact_end = exact(c.k);
  if (!t_linear) end.t = static_cast<double>(time_of(c.k, exact_end.u));
  if (!x_linear) end.x = static_cast<double>(exact_end.x);
  if (!a_linear) end.acceleration = static_cast<double>(acceleration_of(c.k, exact_end.u));
  return end;
}

ConvergingCycle::End ConvergingCycle::next_end() { return end_at(next_); }

void ConvergingCycle::advance() {
  current_ = next_;
  next_ = step(next_);
}

ConvergingCycle::HighState ConvergingCycle::state_at(std::int64_t k, const HighPrecision& tau_start,
                                                     const HighPrecision& x_start,
                                                     const HighPrecision& t_end) const {
  const PhaseLaw<HighPrecision> law(omega_, b_, r_, kind_of_slip(k), tau_start, x_start,
                                    HighPrecision(0), sin_cos(tau_start));
  const auto point = law.point(omega_ * t_end);
  return {law.position(point), HighPrecision(law.sign()) * point.speed,
          law.acceleration_at(point.at)};
}

ConvergingCycle::Horizon ConvergingCycle::horizon(double t_end) {
  using std::abs;
  const HighPrecision horizon_time(t_end);
  // Whether this slip's exact end (the next reversal) lies at or before t_end.
  const Cursor& next = next_;
  const Linear at_end = linear(next);
  bool stopped;
  if (fallback_ < 2 && at_end.t + at_end.t_error <= horizon_time)
    stopped = true;
  else if (fallback_ < 2 && at_end.t - at_end.t_error > horizon_time)
    stopped = false;
  else
    stopped = time_of(next.k, exact(next.k).u) <= horizon_time;
  if (stopped) {
    const End end = end_at(next);
    return {end.x, 0, end.acceleration};
  }
  // Inside the slip from reversal k: its start from the linear transient,
  // off by at most r_k in phase (so v by (b + r) r_k, x by that times the
  // slip's length over w, plus the start's own bound); a does not depend on
  // the start.
  const std::int64_t k = current_.k;
  const Linear at_start = linear(current_);
  const HighPrecision& tau_start = at_start.tau;
  const HighState state = state_at(k, tau_start, at_start.x, horizon_time);
  const HighPrecision phase_error(current_.r);
  const HighPrecision length = abs(omega_ * horizon_time - tau_start) + phase_error;
  const HighPrecision scale = b_ + r_ * (1 + length);
  const HighPrecision v_error = (b_ + r_) * phase_error + kHighSlack * scale;
  const HighPrecision x_error = at_start.x_error + length * (b_ + r_) * phase_error / omega_ +
                                kHighSlack * (abs(state.x) + scale * (1 + length) / omega_);
  Horizon result{0, 0, static_cast<double>(state.a)};
  if (fallback_ < 2 && decided(state.x, x_error, result.x) && decided(state.v, v_error, result.v))
    return result;
  const Exact exact_start = exact(k);
  const HighState exact_state = state_at(k, HighPrecision(n0_ + k) * pi_ + exact_start.u,
                                         exact_start.x, horizon_time);
  return {static_cast<double>(exact_state.x), static_cast<double>(exact_state.v),
          static_cast<double>(exact_state.a)};
}

}  // namespace frictionref::detail
