#include "frictionref/stiff_spring.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

#include "frictionref/error.hpp"
#include "frictionref/sampling.hpp"

namespace frictionref {
namespace {

// The force's phase advances from step to step by a rotation through w dt;
// every this many steps sin and cos are recomputed from the step's time, so
// the rotation's rounding (a few ulps per step) never builds up.
constexpr std::uint64_t kResyncSteps = 64;

// Step counts are exact integers in a double up to 2^53.
constexpr double kMaxSteps = 9007199254740992.0;  // 2^53

// Shortest round-trip form, with a plain exponent: 1e7, 6.3e-05 -> 6.3e-5.
std::string text(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  std::string result(buffer, end);
  const auto e = result.find('e');
  if (e == std::string::npos) return result;
  std::string exponent = result.substr(e + 1);
  std::string sign;
  if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) {
    if (exponent[0] == '-') sign = "-";
    exponent.erase(0, 1);
  }
  while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
  return result.substr(0, e + 1) + sign + exponent;
}

void require_finite(const char* name, double value) {
  if (!std::isfinite(value)) throw InvalidInput(name, text(value), "must be a finite number");
}

// output_dt / dt as the number of steps per archive step: dt is kept if it
// divides output_dt to within 1e-9 (relative), else rounded up.
double steps_per_output_for(double output_dt, double dt) {
  const double ratio = output_dt / dt;
  const double nearest = std::round(ratio);
  if (nearest >= 1 && std::fabs(ratio - nearest) <= 1e-9 * ratio) return nearest;
  return std::fmax(1.0, std::ceil(ratio));
}

}  // namespace

double StiffSpringOptions::stability_limit(const Model& model) const {
  // kf + k: the stiffest the mass sees (stuck slider, model spring).
  const double zeta = contact_damping;
  return 2 * (std::sqrt(1 + zeta * zeta) - zeta) * std::sqrt(model.mass / (kf + model.stiffness));
}

std::uint64_t StiffSpringOptions::steps_per_output(const Model& model) const {
  const double wanted = dt > 0 ? dt : auto_step_fraction * stability_limit(model);
  if (!(wanted < output_dt)) return 1;
  return static_cast<std::uint64_t>(steps_per_output_for(output_dt, wanted));
}

double StiffSpringOptions::step(const Model& model) const {
  const double wanted = dt > 0 ? dt : auto_step_fraction * stability_limit(model);
  if (!(wanted < output_dt)) return output_dt;
  const double ratio = steps_per_output_for(output_dt, wanted);
  // A user step that divides output_dt is used exactly as given.
  if (dt > 0 && std::fabs(output_dt / dt - ratio) <= 1e-9 * ratio) return dt;
  return output_dt / ratio;
}

void StiffSpringOptions::validate(const Model& model) const {
  model.validate();
  if (model.one_way)
    throw InvalidInput("one_way", "true",
                       "the penalty model has no one-way slider: run it two-way, or use newmark "
                       "--method slammer for a one-way numerical peer");
  require_finite("kf", kf);
  require_finite("dt", dt);
  require_finite("output_dt", output_dt);
  require_finite("contact_damping", contact_damping);
  if (!(contact_damping >= 0))
    throw InvalidInput("contact_damping", text(contact_damping), "must be >= 0");
  if (!(kf > 0)) throw InvalidInput("kf", text(kf), "must be > 0");
  if (!(dt >= 0)) throw InvalidInput("dt", text(dt), "must be >= 0 (0: automatic)");
  if (!(output_dt > 0)) throw InvalidInput("output_dt", text(output_dt), "must be > 0");
  const double limit = stability_limit(model);
  if (dt > 0 && !(dt < limit)) {
    throw InvalidInput("dt", text(dt),
                       "must be < the stability limit 2 (sqrt(1+zeta^2)-zeta) sqrt(m/(kf+k)) = " +
                           text(limit) + " of the central-difference scheme (kf = " + text(kf) +
                           ", k = " + text(model.stiffness) + ", zeta = " + text(contact_damping) +
                           ", m = " + text(model.mass) + ")");
  }
  if (dt > 0 && output_dt < dt) {
    throw InvalidInput("output_dt", text(output_dt), "must be >= dt = " + text(dt));
  }
  const double wanted = dt > 0 ? dt : auto_step_fraction * limit;
  if (!(wanted > 0) || output_dt / wanted > kMaxSteps) {
    if (dt > 0) {
      throw InvalidInput("output_dt", text(output_dt),
                         "must be at most 2^53 time steps of dt = " + text(dt));
    }
    throw InvalidInput("kf", text(kf),
                       "gives an automatic step " + text(wanted) + " (" + text(auto_step_fraction) +
                           " of the stability limit) more than 2^53 times "
                           "smaller than output_dt = " +
                           text(output_dt));
  }
}

StiffSpringSimulator::StiffSpringSimulator(const Model& model, double t_end,
                                           const StiffSpringOptions& options)
    : model_(model), t_end_(t_end), options_(options) {
  options.validate(model);
  require_finite("t_end", t_end);
  if (!(t_end > model.t0))
    throw InvalidInput("t_end", text(t_end), "must be > t0 = " + text(model.t0));

  limit_ = options.stability_limit(model);
  dt_ = options.step(model);
  ratio_ = options.steps_per_output(model);

  // Times are t0 + k output_dt and t0 + n dt: both steps must advance t.
  const double largest = std::fmax(std::fabs(model.t0), std::fabs(t_end));
  if (!(largest + options.output_dt > largest)) {
    throw InvalidInput("output_dt", text(options.output_dt),
                       "must exceed the spacing of doubles at |t| = " + text(largest));
  }
  if (!(largest + dt_ > largest)) {
    const std::string rule = "gives a time step " + text(dt_) +
                             " below the spacing of doubles at |t| = " + text(largest);
    if (options.dt > 0) throw InvalidInput("dt", text(options.dt), rule);
    throw InvalidInput("kf", text(options.kf), rule);
  }
  const double steps = std::floor((t_end - model.t0) / dt_) + 2;
  if (!(steps <= kMaxSteps)) {
    throw InvalidInput(
        "t_end", text(t_end),
        "needs " + text(steps) + " time steps of dt = " + text(dt_) + ", more than 2^53");
  }
  total_steps_ = static_cast<std::uint64_t>(steps);

  GridOptions grid;
  grid.t_end = t_end;
  grid.dt = options.output_dt;
  total_samples_ = grid.grid_rows(model.t0);
  last_output_limit_ = grid.last_grid_limit();

  kf_ = options.kf;
  friction_ = model.friction;
  slip_elongation_ = model.friction / options.kf;
  t0_ = model.t0;
  omega_ = model.omega;
  // The scheme in increments: dx = x_{n+1} - x_n = dx_prev + dt^2 a_n.
  const double dt2_over_m = dt_ * dt_ / model.mass;
  force_increment_ = model.amplitude * dt2_over_m;
  spring_increment_ = options.kf * dt2_over_m;
  slip_increment_ = model.friction * dt2_over_m;
  half_over_dt_ = 0.5 / dt_;
  sin_step_ = std::sin(omega_ * dt_);
  cos_step_ = std::cos(omega_ * dt_);

  // Start-up: z0 = x0 (unloaded spring, f0 = 0), and the Taylor step
  // x_{-1} = x0 - dt v0 + dt^2/2 a0 with a0 = (F(t0) - k x0 - c v0) / m.
  x_ = model.x0;
  elongation_ = 0;
  dx_ = dt_ * model.v0 - 0.5 * force_increment_ * std::sin(omega_ * t0_);

  general_ = !model.is_harmonic_coulomb() || options.contact_damping > 0;
  if (!general_) return;
  static_force_ = model.static_limit();
  static_elongation_ = static_force_ / options.kf;
  dt2_over_m_ = dt2_over_m;
  contact_dashpot_ = 2 * options.contact_damping * std::sqrt(options.kf * model.mass) / dt_;
  offset_increment_ = model.force_offset * dt2_over_m;
  stiffness_increment_ = model.stiffness * dt2_over_m;
  const double half_damping = 0.5 * model.damping * dt_ / model.mass;
  damping_scale_ = 1 / (1 + half_damping);
  damping_keep_ = (1 - half_damping) * damping_scale_;
  ground_ = static_cast<bool>(model.ground_motion);
  for (const Harmonic& h : model.harmonics) {
    harmonics_.push_back({h.amplitude * dt2_over_m, h.omega, h.phase, 0, 1, std::sin(h.omega * dt_),
                          std::cos(h.omega * dt_)});
  }
  // The Taylor step with the whole a0 (Model::force gives F(t0)).
  const double a0 =
      (model.force(t0_) - model.stiffness * model.x0 - model.damping * model.v0) / model.mass;
  dx_ = dt_ * model.v0 - 0.5 * dt_ * dt_ * a0;
}

template <bool kSample, bool kGeneral>
void StiffSpringSimulator::take_step() {
  const double t = t0_ + static_cast<double>(next_step_) * dt_;
  if (next_step_ % kResyncSteps == 0) {
    sin_ = std::sin(omega_ * t);
    cos_ = std::cos(omega_ * t);
    if (kGeneral) {
      for (Rotation& h : harmonics_) {
        h.sin = std::sin(h.omega * t + h.phase);
        h.cos = std::cos(h.omega * t + h.phase);
      }
    }
  }
  // Return mapping: the trial elongation x_n - z_{n-1}; beyond R / kf the
  // slider moves so that the spring carries exactly R. `kick` is
  // dt^2 f_n / m, written so that the loop-carried chain
  // elongation -> kick -> dx -> elongation is one multiplication and two
  // additions long (the branch is predicted, it is off that chain).
  double f, kick;
  if (!kGeneral) {
    if (elongation_ > slip_elongation_) {
      elongation_ = slip_elongation_;
      f = -friction_;
      kick = -slip_increment_;
    } else if (elongation_ < -slip_elongation_) {
      elongation_ = -slip_elongation_;
      f = friction_;
      kick = slip_increment_;
    } else {
      f = -kf_ * elongation_;
      kick = -spring_increment_ * elongation_;
    }
  } else {
    // A sliding slider goes on while the mass keeps stretching the spring
    // its way; otherwise it is stuck, and breaks loose beyond Rs.
    if (sliding_ > 0 && !(elongation_ >= slip_elongation_)) sliding_ = 0;
    if (sliding_ < 0 && !(elongation_ <= -slip_elongation_)) sliding_ = 0;
    // Stuck: the spring alone decides the breakaway (the dashpot only damps
    // the contact's ringing; judged with it, its force would break the
    // contact loose during the very transient it is there to damp).
    if (sliding_ == 0) {
      if (elongation_ > static_elongation_)
        sliding_ = 1;
      else if (elongation_ < -static_elongation_)
        sliding_ = -1;
    }
    if (sliding_ != 0) {
      elongation_ = sliding_ * slip_elongation_;
      f = -sliding_ * friction_;
      kick = -sliding_ * slip_increment_;
    } else {
      // Held: the spring and the dashpot, together never beyond Rs (the
      // dashpot would otherwise stop a mass that starts moving in one step).
      f = -std::clamp(kf_ * elongation_ + contact_dashpot_ * dx_, -static_force_, static_force_);
      kick = f * dt2_over_m_;
    }
  }
  double dx_next;
  if (!kGeneral) {
    dx_next = (dx_ + force_increment_ * sin_) + kick;
  } else {
    double load = force_increment_ * sin_ + offset_increment_ - stiffness_increment_ * x_ + kick;
    for (const Rotation& h : harmonics_) load += h.increment * h.sin;
    // The record's force -m a_g, linear between samples, times dt^2 / m.
    if (ground_) load -= model_.ground_acceleration(t) * (dt_ * dt_);
    dx_next = damping_keep_ * dx_ + damping_scale_ * load;
  }

  if (kSample) {
    last_.t = t;
    last_.x = x_;
    last_.v = next_step_ == 0 ? model_.v0 : (dx_ + dx_next) * half_over_dt_;
    last_.f = f;
    last_.z = x_ - elongation_;
  }

  x_ += dx_next;
  elongation_ += dx_next;
  dx_ = dx_next;
  // sin and cos of w t_{n+1} = w t_n + w dt.
  const double sin_next = sin_ * cos_step_ + cos_ * sin_step_;
  cos_ = cos_ * cos_step_ - sin_ * sin_step_;
  sin_ = sin_next;
  if (kGeneral) {
    for (Rotation& h : harmonics_) {
      const double h_sin = h.sin * h.cos_step + h.cos * h.sin_step;
      h.cos = h.cos * h.cos_step - h.sin * h.sin_step;
      h.sin = h_sin;
    }
  }
  ++next_step_;
}

void StiffSpringSimulator::run_to(std::uint64_t n) {
  if (next_step_ > n) return;
  if (general_) {
    while (next_step_ < n) take_step<false, true>();
  } else {
    while (next_step_ < n) take_step<false, false>();
  }
  step_once<true>();
}

bool StiffSpringSimulator::next(StiffSample& sample) {
  if (finished_) return false;
  const double t_grid = t0_ + static_cast<double>(output_index_) * options_.output_dt;
  if (t_grid < last_output_limit_) {
    run_to(output_index_ * ratio_);
    sample = last_;
    sample.t = t_grid;
    ++output_index_;
    return true;
  }
  // t_end: between steps n and n + 1 (s = n + fraction), or after the last
  // sample already taken if rounding put it there.
  finished_ = true;
  const double s = (t_end_ - t0_) / dt_;
  double lower = std::floor(s);
  const double taken = next_step_ == 0 ? 0 : static_cast<double>(next_step_ - 1);
  if (lower < taken) lower = taken;
  const double fraction = s - lower;
  run_to(static_cast<std::uint64_t>(lower));
  sample = last_;
  if (fraction > 0) {
    const StiffSample low = last_;
    step_once<true>();
    const auto mix = [fraction](double a, double b) { return a + fraction * (b - a); };
    sample.x = mix(low.x, last_.x);
    sample.v = mix(low.v, last_.v);
    sample.f = mix(low.f, last_.f);
    sample.z = mix(low.z, last_.z);
  }
  sample.t = t_end_;
  return true;
}

}  // namespace frictionref
