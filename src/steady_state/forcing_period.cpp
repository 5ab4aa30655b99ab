// The forcing's common period (classification.hpp): each frequency ratio is
// recognised as a fraction by its continued-fraction convergents.
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>

#include "frictionref/classification.hpp"

namespace frictionref {
namespace {

constexpr std::int64_t kMaxDenominator = 1000;
constexpr double kRatioTolerance = 1e-12;

struct Fraction {
  std::int64_t p, q;
};

// The first convergent p/q of x > 0 with q <= kMaxDenominator within
// kRatioTolerance (relative), if any.
std::optional<Fraction> as_fraction(double x) {
  // Convergents h_n / k_n from the continued fraction x = [a0; a1, a2, ...].
  std::int64_t h_prev = 1, h = static_cast<std::int64_t>(std::floor(x));
  std::int64_t k_prev = 0, k = 1;
  double rest = x - std::floor(x);
  for (int n = 0; n < 64; ++n) {
    if (std::fabs(static_cast<double>(h) / static_cast<double>(k) - x) <= kRatioTolerance * x)
      return Fraction{h, k};
    if (rest <= 0) return std::nullopt;
    const double inverse = 1 / rest;
    const double a_float = std::floor(inverse);
    if (!(a_float < 1e12)) return std::nullopt;
    const auto a = static_cast<std::int64_t>(a_float);
    rest = inverse - a_float;
    const std::int64_t h_next = a * h + h_prev, k_next = a * k + k_prev;
    if (k_next > kMaxDenominator) return std::nullopt;
    h_prev = h, h = h_next, k_prev = k, k = k_next;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> forcing_period(const Model& model) {
  const double two_pi = boost::math::constants::two_pi<double>();
  std::vector<double> frequencies;
  if (model.amplitude != 0) frequencies.push_back(model.omega);
  for (const Harmonic& h : model.harmonics)
    if (h.amplitude != 0) frequencies.push_back(h.omega);
  if (frequencies.empty()) return two_pi / model.omega;
  // Every frequency as (p / q) times the first; the fundamental is the first
  // times G / L, L the lcm of the q, G the gcd of the p L / q.
  const double base = frequencies.front();
  std::vector<Fraction> ratios;
  std::int64_t lcm = 1;
  for (const double f : frequencies) {
    const auto fraction = as_fraction(f / base);
    if (!fraction) return std::nullopt;
    ratios.push_back(*fraction);
    lcm = std::lcm(lcm, fraction->q);
    if (lcm > kMaxDenominator) return std::nullopt;
  }
  std::int64_t gcd = 0;
  for (const Fraction& r : ratios) gcd = std::gcd(gcd, r.p * (lcm / r.q));
  // T = 2 pi / (base G / L) = (L / G) periods of the first frequency.
  const double periods = static_cast<double>(lcm) / static_cast<double>(gcd);
  if (periods > kMaxDenominator) return std::nullopt;
  return periods * two_pi / base;
}

}  // namespace frictionref
