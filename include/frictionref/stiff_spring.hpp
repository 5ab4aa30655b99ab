// The stiff-spring ("penalty") friction model that the exact solution is used
// to check, as in DYNARACK (USNRC problem 7; docs/stiff-spring.md), for every
// model of the family (model.hpp).
//
// Friction acts through a spring of stiffness kf in series with a Coulomb
// slider at position z:
//
//   m x'' + c x' + k x = F(t) + f,   f = -kf (x - z),
//   F(t) = F0 + B sin(w t) + sum_i B_i sin(w_i t + phi_i).
//
// The slider is stuck (the mass rings on the spring) until the spring force
// |kf (x - z)| exceeds the static friction Rs; then it breaks loose and slides
// with |f| = R exactly (a return mapping, as in elastoplasticity), and it
// sticks again as soon as the mass turns back (the spring unloads). With
// Rs = R this is the seed's rule: the slider moves whenever |f| would exceed R.
//
// Time stepping: the explicit central-difference scheme
//
//   m (x_{n+1} - 2 x_n + x_{n-1}) / dt^2 + c (x_{n+1} - x_{n-1}) / (2 dt) + k x_n
//     = F(t_n) + f_n,   t_n = t0 + n dt,
//
// run in its equivalent increment form (dx = x_{n+1} - x_n = dt v_{n+1/2}):
// (1 + c dt / 2m) dx_{n+1/2} = (1 - c dt / 2m) dx_{n-1/2} + dt^2 (F_n - k x_n + f_n) / m,
// x_{n+1} = x_n + dx_{n+1/2}, which rounds better than 2 x_n - x_{n-1}; the
// spring elongation x - z is carried as its own variable, so the friction force
// never comes from the difference of two large positions. The damper is
// time-centred, so the scheme is second order and stable for
// dt < 2 / sqrt((kf + k) / m), whatever c. The archived velocity is the
// central difference v_n = (x_{n+1} - x_{n-1}) / (2 dt).
//
// Start-up: the slider starts at the mass (z0 = x0: the spring is unloaded,
// f0 = 0, stuck) and x_{-1} comes from a Taylor step,
// x_{-1} = x0 - dt v0 + dt^2 / 2 * (F(t0) - k x0 - c v0) / m. So with v0 != 0
// the first step carries no friction, and the velocity is off by R dt / (2 m)
// until the first stop: first order in dt (docs/stiff-spring.md).
#pragma once

#include <cstdint>
#include <vector>

#include "frictionref/model.hpp"

namespace frictionref {

struct StiffSpringOptions {
  // kf: stiffness of the friction spring [force / length]; finite, > 0.
  // The seed (DYNARACK) uses 1e7 lb/in with m = 1 to mimic a rigid contact.
  double kf = 1e7;

  // Time step [time]; finite, >= 0. 0 = automatic: auto_step_fraction times
  // the stability limit 2 / sqrt(kf / m). Either way the step actually used is
  // the largest step <= this one that divides output_dt an integer number of
  // times (see step()). A nonzero step must be below the stability limit and
  // not above output_dt.
  double dt = 0;

  // Archive step [time]; finite, > 0. Samples at t0 + k output_dt (below
  // t_end - 1e-9 output_dt, the `curve` grid rule) and at t_end itself.
  double output_dt = 0.01;

  // Damping ratio zeta of the friction contact [1]; finite, >= 0, default 0
  // (the seed's undamped spring, as DYNARACK): a dashpot cf = 2 zeta
  // sqrt(kf m) in parallel with the friction spring while the slider is
  // stuck. Why: at every stop the undamped spring rings about its new
  // equilibrium with an overshoot as large as the force change, whatever kf;
  // with Rs > R the ringing reaches Rs and breaks the contact loose again, so
  // the model does not converge to the exact solution as kf grows
  // (docs/stiff-spring.md). zeta near 1 removes the overshoot.
  double contact_damping = 0;

  // The automatic step as a fraction of the stability limit.
  static constexpr double auto_step_fraction = 0.1;

  // The stability limit of the central-difference scheme on the friction
  // spring and the model's spring, 2 (sqrt(1 + zeta^2) - zeta) / sqrt((kf + k) / m)
  // [time] (+inf if it overflows): the contact dashpot is explicit (it uses
  // the velocity of the half step before), which shortens the undamped limit
  // by that factor.
  double stability_limit(const Model& model) const;

  // The time step the simulator uses: dt (or the automatic step), reduced to
  // output_dt / N with N = the number of steps per archive step (a step within
  // 1e-9 relative of dividing output_dt is kept as given). Call validate() first.
  double step(const Model& model) const;

  // Steps per archive step N (output_dt = N * step, up to rounding); >= 1.
  std::uint64_t steps_per_output(const Model& model) const;

  // Throws InvalidInput naming the field ("kf", "dt", "output_dt",
  // "contact_damping"), its value and the rule: NaN or infinity; kf <= 0;
  // dt < 0; output_dt <= 0; contact_damping < 0;
  // dt >= the stability limit (the message gives the limit); output_dt < dt.
  // Validates the model first.
  void validate(const Model& model) const;
};

// One archived state.
struct StiffSample {
  double t = 0;  // time [time]: t0 + k output_dt (from k, never accumulated), or t_end
  double x = 0;  // mass position [length]
  double v = 0;  // central-difference velocity (x_{n+1} - x_{n-1}) / (2 dt) [length / time]
  double f = 0;  // friction force on the mass, -kf (x - z) (- cf x' while stuck) [force];
                 // |f| <= Rs
  double z = 0;  // slider position [length]
};

// Streams samples of the stiff-spring model from t0 to t_end. Memory is flat
// for any horizon and a time step allocates nothing. Each harmonic term
// B_i sin(w_i t_n + phi_i) comes from a rotation through w_i dt (four
// multiplications), re-anchored with std::sin and std::cos of w_i t_n + phi_i
// every 64 steps, so a step of the seed's model costs less than one std::cos
// call. The seed's model (model.hpp's is_harmonic_coulomb()) runs a step
// without the spring, damper and static-friction terms.
//
// The sample at t_end, when t_end is not a time step, is the linear
// interpolation (in t) of the samples of the two steps around it.
class StiffSpringSimulator {
 public:
  // Validates the model and options (StiffSpringOptions::validate), and t_end:
  // finite, > t0; output_dt and the step must exceed the spacing of doubles at
  // max(|t0|, |t_end|); at most 2^53 time steps. Throws InvalidInput (an
  // automatic step that is too small is reported against "kf").
  StiffSpringSimulator(const Model& model, double t_end, const StiffSpringOptions& options = {});

  // Writes the next sample and returns true; false once t_end was written.
  bool next(StiffSample& sample);

  const Model& model() const { return model_; }
  double t_end() const { return t_end_; }
  const StiffSpringOptions& options() const { return options_; }
  double step() const { return dt_; }                        // the time step used
  double stability_limit() const { return limit_; }          // 2 / sqrt(kf / m)
  std::uint64_t steps_per_output() const { return ratio_; }  // output_dt / step()
  // Time steps needed to reach t_end (the last one may be past t_end, for the
  // interpolation there).
  std::uint64_t total_steps() const { return total_steps_; }
  // Samples next() will write in all: the output grid and t_end.
  std::uint64_t total_samples() const { return total_samples_; }
  // Time steps taken so far.
  std::uint64_t steps_taken() const { return next_step_; }

 private:
  void run_to(std::uint64_t n);  // steps until the sample of step n is in last_
  // Step next_step_ (its sample into last_ if kSample), then advance; the
  // seed's model or (kGeneral) any model.
  template <bool kSample, bool kGeneral>
  void take_step();
  template <bool kSample>
  void step_once() {
    general_ ? take_step<kSample, true>() : take_step<kSample, false>();
  }

  Model model_;
  double t_end_;
  StiffSpringOptions options_;
  double limit_;
  double dt_;
  std::uint64_t ratio_;
  std::uint64_t total_steps_;
  std::uint64_t total_samples_;
  double last_output_limit_;  // grid times are kept while below this

  // Scheme state before step next_step_ = n: x_n, the trial elongation
  // x_n - z_{n-1}, dx = x_n - x_{n-1} (= dt v_{n-1/2}), sin and cos of w t_n.
  std::uint64_t next_step_ = 0;
  double x_ = 0;
  double elongation_ = 0;
  double dx_ = 0;
  double sin_ = 0, cos_ = 1;
  // Constants: kf, R, R / kf, t0, w; dt^2 B / m, dt^2 kf / m, dt^2 R / m;
  // 1 / (2 dt); sin and cos of w dt.
  double kf_, friction_, slip_elongation_, t0_, omega_;
  double force_increment_, spring_increment_, slip_increment_;
  double half_over_dt_;
  double sin_step_ = 0, cos_step_ = 1;

  // Any other model (general_): the extra harmonics as rotations, the
  // slider's state, and the constants of the spring, damper and static friction.
  struct Rotation {
    double increment;           // dt^2 B_i / m
    double omega, phase;        // w_i, phi_i
    double sin, cos;            // of w_i t_n + phi_i
    double sin_step, cos_step;  // of w_i dt
  };
  bool general_ = false;
  std::vector<Rotation> harmonics_;
  bool ground_ = false;             // a record: -m a_g(t_n) joins the load
  int sliding_ = 0;                 // +1 / -1: the slider slides that way; 0: stuck
  double static_force_ = 0;         // Rs
  double static_elongation_ = 0;    // Rs / kf
  double contact_dashpot_ = 0;      // cf / dt (times dx: the dashpot's force)
  double dt2_over_m_ = 0;           // dt^2 / m
  double offset_increment_ = 0;     // dt^2 F0 / m
  double stiffness_increment_ = 0;  // dt^2 k / m
  double damping_keep_ = 1;         // (1 - c dt / 2m) / (1 + c dt / 2m)
  double damping_scale_ = 1;        // 1 / (1 + c dt / 2m)

  StiffSample last_;  // sample of step next_step_ - 1
  std::uint64_t output_index_ = 0;
  bool finished_ = false;
};

}  // namespace frictionref
