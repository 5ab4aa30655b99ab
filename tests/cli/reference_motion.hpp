// An independent, deliberately simple solution of the seed problem's model
// (m = B = w = 1, x0 = 0, t0 = 0) in long double, used as the expected values
// of the CLI tests: THEORY.md's closed forms, slip ends by scanning for a
// sign change of v and bisecting, breakaways at asin(lambda) + 2 pi k and
// pi + asin(lambda) + 2 pi k. Shares no code with the library.
#pragma once

#include <string>
#include <vector>

namespace frictionref::cli_test {

struct RefPhase {
  std::string kind;  // "stick", "slip+", "slip-"
  long double t_begin, t_end, x_begin, x_end, v_begin, v_end;
};

struct RefState {
  long double x, v, a;
  std::string kind;
};

class ReferenceMotion {
 public:
  ReferenceMotion(long double lambda, long double v0, long double t_end);
  const std::vector<RefPhase>& phases() const { return phases_; }
  // The state at t inside `phase` (closed form); a is the phase's acceleration.
  RefState state(const RefPhase& phase, long double t) const;
  // The phase with t_begin <= t < t_end (the last one also owns t_end).
  const RefPhase& phase_at(long double t) const;
  std::size_t count(const std::string& kind) const;

 private:
  long double velocity(int sign, long double a, long double va, long double t) const;
  long double position(int sign, long double a, long double xa, long double va,
                       long double t) const;

  long double lambda_;
  std::vector<RefPhase> phases_;
};

}  // namespace frictionref::cli_test
