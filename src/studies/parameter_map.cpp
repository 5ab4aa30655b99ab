// Two-parameter maps (parameter_map.hpp): each point is the base model with
// the two axis values set, classified by simulation, on a pool of threads.
#include "frictionref/parameter_map.hpp"

#include <cmath>
#include <string>

#include "enum_names.hpp"
#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "studies/parallel_for.hpp"

namespace frictionref {
namespace {

constexpr detail::EnumNames<MapParameter, 14> kParameterNames{{
    {MapParameter::lambda, "lambda"},
    {MapParameter::static_ratio, "static-ratio"},
    {MapParameter::frequency_ratio, "frequency-ratio"},
    {MapParameter::damping_ratio, "damping-ratio"},
    {MapParameter::mass, "mass"},
    {MapParameter::amplitude, "amplitude"},
    {MapParameter::omega, "omega"},
    {MapParameter::friction, "friction"},
    {MapParameter::static_friction, "static-friction"},
    {MapParameter::stiffness, "stiffness"},
    {MapParameter::damping, "damping"},
    {MapParameter::force_offset, "force-offset"},
    {MapParameter::x0, "x0"},
    {MapParameter::v0, "v0"},
}};

std::string text(double value) { return detail::shortest_text(value); }

// R set to `friction`, a static friction of the base model kept in ratio.
void set_friction(Model& model, const Model& base, double friction) {
  if (base.static_friction && base.friction > 0)
    model.static_friction = friction * (*base.static_friction / base.friction);
  model.friction = friction;
}

double natural_frequency(const Model& model, MapParameter parameter) {
  if (!(model.stiffness > 0))
    throw InvalidInput(std::string(to_string(parameter)), "axis",
                       "needs a spring: the base model's stiffness must be > 0");
  return std::sqrt(model.stiffness / model.mass);
}

}  // namespace

std::string_view to_string(MapParameter parameter) {
  return detail::name_of(kParameterNames, parameter);
}
std::optional<MapParameter> map_parameter_from_string(std::string_view text) {
  return detail::enum_from_name(kParameterNames, text);
}
std::string column_name(MapParameter parameter) {
  std::string name(to_string(parameter));
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}
std::string map_parameter_names() {
  std::string names;
  for (const auto& [value, name] : kParameterNames)
    names += (names.empty() ? "" : ", ") + std::string(name);
  return names;
}

Model with_parameter(const Model& base, MapParameter parameter, double value) {
  Model model = base;
  switch (parameter) {
    case MapParameter::lambda:
      if (!(base.amplitude > 0))
        throw InvalidInput("lambda", "axis", "needs a forcing amplitude B > 0 (R = lambda B)");
      set_friction(model, base, value * base.amplitude);
      break;
    case MapParameter::static_ratio:
      model.static_friction = value * base.friction;
      break;
    case MapParameter::frequency_ratio:
      model.omega = value * natural_frequency(base, parameter);
      break;
    case MapParameter::damping_ratio:
      natural_frequency(base, parameter);
      model.damping = value * 2 * std::sqrt(base.stiffness * base.mass);
      break;
    case MapParameter::mass:
      model.mass = value;
      break;
    case MapParameter::amplitude:
      model.amplitude = value;
      break;
    case MapParameter::omega:
      model.omega = value;
      break;
    case MapParameter::friction:
      set_friction(model, base, value);
      break;
    case MapParameter::static_friction:
      model.static_friction = value;
      break;
    case MapParameter::stiffness:
      model.stiffness = value;
      break;
    case MapParameter::damping:
      model.damping = value;
      break;
    case MapParameter::force_offset:
      model.force_offset = value;
      break;
    case MapParameter::x0:
      model.x0 = value;
      break;
    case MapParameter::v0:
      model.v0 = value;
      break;
  }
  return model;
}

void MapAxis::validate(const std::string& option) const {
  const std::string name = option;
  if (!std::isfinite(from)) throw InvalidInput(name, text(from), "the first value must be finite");
  if (!std::isfinite(to)) throw InvalidInput(name, text(to), "the last value must be finite");
  if (!(to >= from))
    throw InvalidInput(name, text(to), "the last value must be >= the first, " + text(from));
  if (points < 1) throw InvalidInput(name, "0 points", "must have at least 1 point");
  if (points == 1 && to != from)
    throw InvalidInput(name, "1 point", "a single point needs the first value = the last");
  if (points > 1 && to == from)
    throw InvalidInput(name, std::to_string(points) + " points",
                       "must be 1 point when the first value = the last");
  if (points > 1) {
    const std::vector<double> v = values();
    for (std::size_t i = 1; i < v.size(); ++i)
      if (!(v[i] > v[i - 1]))
        throw InvalidInput(name, std::to_string(points) + " points",
                           "the values would repeat (the step is below the spacing of doubles)");
  }
}

std::vector<double> MapAxis::values() const {
  std::vector<double> v(points);
  if (points == 0) return v;
  v[0] = from;
  if (points == 1) return v;
  // In long double, rounded once; the ends exactly as given.
  const long double span = static_cast<long double>(to) - static_cast<long double>(from);
  const long double intervals = static_cast<long double>(points - 1);
  for (std::uint64_t i = 1; i + 1 < points; ++i)
    v[i] = static_cast<double>(from + span * static_cast<long double>(i) / intervals);
  v[points - 1] = to;
  return v;
}

MapAxis MapAxis::parse(std::string_view spec, const std::string& option) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t colon = spec.find(':', begin);
    fields.emplace_back(
        spec.substr(begin, colon == std::string_view::npos ? colon : colon - begin));
    if (colon == std::string_view::npos) break;
    begin = colon + 1;
  }
  const std::string whole(spec);
  if (fields.size() != 4)
    throw InvalidInput(option, whole, "must be NAME:FROM:TO:POINTS, e.g. lambda:0:1.2:241");
  MapAxis axis;
  const auto parameter = map_parameter_from_string(fields[0]);
  if (!parameter)
    throw InvalidInput(
        option, whole,
        "unknown parameter '" + fields[0] + "' (one of " + map_parameter_names() + ")");
  axis.parameter = *parameter;
  const auto number = [&](const std::string& field, const char* what) {
    const char* text_begin = field.c_str();
    char* end = nullptr;
    const double value = std::strtod(text_begin, &end);
    if (field.empty() || end != text_begin + field.size())
      throw InvalidInput(option, whole, std::string(what) + " '" + field + "' must be a number");
    return value;
  };
  axis.from = number(fields[1], "FROM");
  axis.to = number(fields[2], "TO");
  const double points = number(fields[3], "POINTS");
  if (!(points >= 1) || points != std::floor(points) || !(points <= 1e7))
    throw InvalidInput(option, whole, "POINTS must be a whole number from 1 to 10^7");
  axis.points = static_cast<std::uint64_t>(points);
  axis.validate(option);
  return axis;
}

std::vector<MapPoint> parameter_map(const Model& base, const MapAxis& x, const MapAxis& y,
                                    const MapOptions& options, const MapProgress& progress) {
  x.validate("x");
  y.validate("y");
  if (x.parameter == y.parameter)
    throw InvalidInput("y", std::string(to_string(y.parameter)),
                       "must differ from the x axis's parameter");
  options.classify.validate();
  options.shard.validate();
  base.validate();
  base.refuse_ground_motion(
      "is not taken by map: it maps steady states, which a record (a transient) does not have "
      "(newmark runs records x yield accelerations)");
  const std::vector<double> xs = x.values(), ys = y.values();
  const auto model_at = [&](double xv, double yv) {
    return with_parameter(with_parameter(base, x.parameter, xv), y.parameter, yv);
  };
  for (const double xv : {xs.front(), xs.back()})
    for (const double yv : {ys.front(), ys.back()}) model_at(xv, yv).validate();

  ClassifyOptions classify_options = options.classify;
  classify_options.closed_forms = false;
  const Shard::Range block = options.shard.range(xs.size() * ys.size());
  std::vector<MapPoint> points(block.size());
  detail::parallel_for(
      points.size(), options.threads,
      [&](std::size_t i) {
        const std::size_t index = block.begin + i;  // in the whole grid
        const double xv = xs[index / ys.size()], yv = ys[index % ys.size()];
        const Model model = model_at(xv, yv);
        const Classification c = classify(model, classify_options);
        MapPoint& p = points[i];
        p.x = xv;
        p.y = yv;
        p.regime = c.regime;
        p.stops_per_period = c.stops_per_period;
        p.reversals_per_period = c.reversals_per_period;
        p.multiplicity = c.multiplicity;
        p.stuck_fraction = c.stuck_fraction;
        p.transient_periods = c.transient_periods;
      },
      progress);
  return points;
}

}  // namespace frictionref
