// The scales a comparison is relative to (motion_scales.hpp).
#include "frictionref/motion_scales.hpp"

#include <boost/math/constants/constants.hpp>
#include <cmath>

#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"

namespace frictionref {
namespace {

constexpr double two_pi = boost::math::double_constants::two_pi;

bool finite_positive(double value) { return std::isfinite(value) && value > 0; }

MotionScales harmonic_scales(const Model& model, std::string_view purpose) {
  const std::string rule =
      " " + std::string(purpose) + " (velocities are judged relative to B/(m w))";
  if (!(model.amplitude > 0))
    throw InvalidInput("amplitude", detail::shortest_text(model.amplitude), "must be > 0" + rule);
  MotionScales s;
  s.velocity = model.amplitude / (model.mass * model.omega);
  s.displacement = s.velocity / model.omega;
  s.period = two_pi / model.omega;
  s.velocity_name = "B/(m w)";
  s.displacement_name = "B/(m w^2)";
  s.period_unit = "periods";
  s.period_name = "period 2 pi / w";
  if (!finite_positive(s.velocity) || !finite_positive(s.displacement))
    throw InvalidInput("amplitude", detail::shortest_text(model.amplitude),
                       "must give finite, non-zero scales B/(m w) and B/(m w^2)" + rule);
  return s;
}

MotionScales record_scales(const GroundMotion& record, std::string_view purpose) {
  const double pga = record.pga();
  const double pgv = record.pgv();
  const std::string rule = " " + std::string(purpose) +
                           " (velocities are judged relative to the record's peak ground "
                           "velocity PGV)";
  if (!(pga > 0))
    throw InvalidInput("ground_motion", record.file, "must not be zero throughout" + rule);
  MotionScales s;
  s.velocity = pgv;
  s.displacement = pgv * pgv / pga;
  s.period = two_pi * pgv / pga;
  s.velocity_name = "PGV";
  s.displacement_name = "PGV^2/PGA";
  s.period_unit = "T*";
  s.period_name = "T* = 2 pi PGV/PGA";
  if (!finite_positive(s.velocity) || !finite_positive(s.displacement) ||
      !finite_positive(s.period))
    throw InvalidInput("ground_motion", record.file,
                       "must give finite, non-zero scales PGV = " + detail::shortest_text(pgv) +
                           ", PGV^2/PGA and 2 pi PGV/PGA" + rule);
  return s;
}

}  // namespace

MotionScales motion_scales(const Model& model, std::string_view purpose) {
  return model.ground_motion ? record_scales(*model.ground_motion, purpose)
                             : harmonic_scales(model, purpose);
}

}  // namespace frictionref
