// Newmark's sliding-block analysis (newmark.hpp): one record x KY x polarity
// by the exact engine or by SLAMMER's algorithm, and the batch of them on
// all cores.
#include "frictionref/newmark.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "frictionref/error.hpp"
#include "frictionref/exact_engine.hpp"
#include "frictionref/slammer_rigid_block.hpp"
#include "io/text_fields.hpp"
#include "studies/parallel_for.hpp"

namespace frictionref {
namespace {

// The engine's limit on |w t| with w = 1 (docs/theory.md 4.9): a run after
// the record cannot go beyond it.
constexpr double max_horizon = 1e9;

// The record with its accelerations negated, provenance kept.
std::shared_ptr<const GroundMotion> negated(const GroundMotion& record) {
  auto copy = std::make_shared<GroundMotion>(record);
  for (double& a : copy->a) a = -a;
  copy->factor = -copy->factor;
  return copy;
}

// The largest |v| inside a slip phase. v is continuous and, on each sample
// interval, a quadratic whose derivative a(t) = -a_g(t) -+ mu is linear, so
// |v| peaks at the phase's ends, at a sample time or where a_g crosses -+mu
// inside an interval: every such point is evaluated in closed form.
double slip_peak_speed(const Model& model, const Phase& phase) {
  const PhaseEvaluator state(model, phase);
  double peak = std::max(std::fabs(phase.v_begin), std::fabs(phase.v_end));
  const auto consider = [&](double t) {
    if (t > phase.t_begin && t < phase.t_end) peak = std::max(peak, std::fabs(state(t).v));
  };
  const std::vector<double>& ts = model.ground_motion->t;
  const std::vector<double>& as = model.ground_motion->a;
  const double mu = model.friction / model.mass;
  std::size_t i =
      static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), phase.t_begin) - ts.begin());
  if (i > 0) --i;  // the interval holding t_begin
  for (; i < ts.size() && ts[i] < phase.t_end; ++i) {
    consider(ts[i]);
    if (i + 1 == ts.size()) break;
    const double da = as[i + 1] - as[i];
    if (da == 0) continue;
    for (const double level : {mu, -mu}) {
      const double s = (-level - as[i]) / da;  // a_g = -level: the acceleration's zero
      if (s > 0 && s < 1) consider(ts[i] + s * (ts[i + 1] - ts[i]));
    }
  }
  return peak;
}

NewmarkResult exact_analysis(const std::shared_ptr<const GroundMotion>& model_record,
                             double yield_accel_g, bool one_way) {
  const Model model = newmark_model(model_record, yield_accel_g, one_way);
  const double t_last = model_record->t.back();
  const double horizon = newmark_horizon(model);
  NewmarkResult result;
  ExactEngine engine(model, horizon);
  Phase phase;
  bool at_end_known = false;
  PhaseKind last = PhaseKind::stick;
  while (engine.next(phase)) {
    last = phase.kind;
    if (phase.kind != PhaseKind::stick) {
      ++result.slip_episodes;
      result.max_relative_velocity =
          std::max(result.max_relative_velocity, slip_peak_speed(model, phase));
    }
    if (!at_end_known && phase.t_begin <= t_last && t_last <= phase.t_end) {
      result.displacement_at_record_end =
          phase.t_end == t_last ? phase.x_end : evaluate(model, phase, t_last).x;
      at_end_known = true;
    }
  }
  const Summary& summary = engine.summary();
  if (summary.termination != Termination::reached_end)
    throw std::runtime_error("newmark: the engine stopped early: " + summary.message);
  if (!at_end_known) result.displacement_at_record_end = summary.final_state.x;
  // At rest once the ground is still: the block stays there for good.
  if (last == PhaseKind::stick) result.permanent_displacement = summary.final_state.x;
  return result;
}

// One analysis, given the record as read and negated (either may be null
// when the method and polarity do not need it).
NewmarkResult analysis(const std::shared_ptr<const GroundMotion>& as_read,
                       const std::shared_ptr<const GroundMotion>& negative, double yield_accel_g,
                       bool one_way, Polarity polarity, NewmarkMethod method) {
  NewmarkResult result;
  if (method == NewmarkMethod::exact) {
    // x in the model is SLAMMER's downslope displacement when the model's
    // ground moves against the record (newmark.hpp).
    result =
        exact_analysis(polarity == Polarity::normal ? negative : as_read, yield_accel_g, one_way);
  } else {
    SlammerOptions slammer;
    slammer.yield_accel_g = yield_accel_g;
    slammer.two_way = !one_way;
    slammer.inverse = polarity == Polarity::inverse;
    const SlammerResult run =
        slammer_rigid_block(polarity == Polarity::inverse ? *negative : *as_read, slammer);
    result.displacement_at_record_end = run.displacement;
    // SLAMMER stops at the last sample; its answer is final if the block is
    // at rest there by its own threshold.
    if (run.at_rest_at_end) result.permanent_displacement = run.displacement;
    result.slip_episodes = run.slip_episodes;
    result.max_relative_velocity = run.max_relative_velocity;
  }
  result.record = as_read->file;
  result.yield_accel_g = yield_accel_g;
  result.polarity = polarity;
  result.method = method;
  return result;
}

// SLAMMER integrates at the record's step.
void require_uniform_step(const GroundMotion& record) {
  if (!record.dt)
    throw InvalidInput("record", record.file,
                       "has no uniform step (a table of times); SLAMMER's algorithm integrates "
                       "at the record's step: give an .AT2 file or one column with --record-dt");
}

// The exact method's normal polarity and SLAMMER's inverse one run on the
// record negated.
bool needs_negated(const NewmarkOptions& options) {
  for (const Polarity p : options.polarities) {
    if ((options.method == NewmarkMethod::exact) == (p == Polarity::normal)) return true;
  }
  return false;
}

}  // namespace

Model newmark_model(std::shared_ptr<const GroundMotion> model_record, double yield_accel_g,
                    bool one_way) {
  Model model;
  model.mass = 1;
  model.amplitude = 0;
  model.omega = 1;
  model.friction = yield_accel_g * model_record->gravity;
  model.t0 = std::min(0.0, model_record->t.front());
  model.ground_motion = std::move(model_record);
  model.one_way = one_way;
  return model;
}

std::shared_ptr<const GroundMotion> newmark_record(std::shared_ptr<const GroundMotion> record,
                                                   Polarity polarity) {
  return polarity == Polarity::normal ? negated(*record) : record;
}

double newmark_horizon(const Model& model) {
  const GroundMotion& record = *model.ground_motion;
  const double mu = model.friction / model.mass;
  const double t_last = record.t.back();
  double horizon = t_last;
  if (mu > 0) {
    const double tail = (record.pga() + mu) * (t_last - model.t0) / mu * 1.01 + 1.0;
    horizon = std::min(t_last + tail, std::max(max_horizon, t_last + 1.0));
  }
  // The engine needs a horizon after the start.
  return horizon > model.t0 ? horizon : model.t0 + 1.0;
}

std::string_view to_string(NewmarkMethod method) {
  return method == NewmarkMethod::exact ? "exact" : "slammer";
}

std::string_view to_string(Polarity polarity) {
  return polarity == Polarity::normal ? "normal" : "inverse";
}

std::optional<NewmarkMethod> newmark_method_from_string(std::string_view text) {
  if (text == "exact") return NewmarkMethod::exact;
  if (text == "slammer") return NewmarkMethod::slammer;
  return std::nullopt;
}

std::string yield_accel_rule(double yield_accel_g, NewmarkMethod method) {
  if (!std::isfinite(yield_accel_g) || !(yield_accel_g >= 0))
    return "must be a finite number >= 0 (in g)";
  // SLAMMER divides the ground acceleration by the yield level at rest.
  if (method == NewmarkMethod::slammer && yield_accel_g == 0)
    return "must be > 0 with the slammer method (SLAMMER divides by KY g)";
  return "";
}

void NewmarkOptions::validate() const {
  if (yield_accels_g.empty())
    throw InvalidInput("yield_accels_g", "none", "needs at least one yield acceleration");
  for (const double ky : yield_accels_g) {
    if (const std::string rule = yield_accel_rule(ky, method); !rule.empty())
      throw InvalidInput("yield_accel", io::text(ky), rule);
  }
  if (polarities.empty()) throw InvalidInput("polarities", "none", "needs at least one polarity");
}

NewmarkResult newmark_analysis(const GroundMotion& record, double yield_accel_g, bool one_way,
                               Polarity polarity, NewmarkMethod method) {
  NewmarkOptions options;
  options.yield_accels_g = {yield_accel_g};
  options.polarities = {polarity};
  options.method = method;
  options.validate();
  record.validate();
  // In the calling thread: no pool for one run. The record as read is not
  // copied: a pointer that does not own it, alive for this call.
  const std::shared_ptr<const GroundMotion> as_read(std::shared_ptr<const GroundMotion>(), &record);
  const auto negative = needs_negated(options) ? negated(record) : nullptr;
  if (method == NewmarkMethod::slammer) require_uniform_step(record);
  return analysis(as_read, negative, yield_accel_g, one_way, polarity, method);
}

std::vector<NewmarkResult> newmark_batch(
    const std::vector<std::shared_ptr<const GroundMotion>>& records,
    const NewmarkOptions& options) {
  options.validate();
  for (const auto& record : records) {
    if (!record) throw InvalidInput("records", "null", "every record must be given");
    record->validate();
    if (options.method == NewmarkMethod::slammer) require_uniform_step(*record);
  }
  const std::size_t per_record = options.yield_accels_g.size() * options.polarities.size();
  const std::size_t count = records.size() * per_record;
  // Negated once per record, not once per run (10^4 samples copied 40 times).
  std::vector<std::shared_ptr<const GroundMotion>> negatives(records.size());
  if (needs_negated(options)) {
    for (std::size_t r = 0; r < records.size(); ++r) negatives[r] = negated(*records[r]);
  }
  std::vector<NewmarkResult> results(count);
  detail::parallel_for(
      count, options.threads,
      [&](std::size_t index) {
        const std::size_t r = index / per_record;
        const std::size_t k = index % per_record / options.polarities.size();
        const std::size_t p = index % options.polarities.size();
        results[index] = analysis(records[r], negatives[r], options.yield_accels_g[k],
                                  options.one_way, options.polarities[p], options.method);
      },
      options.progress);
  return results;
}

}  // namespace frictionref
