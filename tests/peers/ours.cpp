// Our side of the peer comparison (tests/peers/README.md), for one case:
//
//  - the event list of the double engine (the reference times for the peers);
//  - the time of the double engine, streaming with next() (nothing stored): the median of
//    repeated runs, repeated until at least --min-time seconds have been spent;
//  - our own error: the same case with the 50-digit instantiation
//    (BasicExactEngine<HighPrecision>), max |t_double - t_50| over the events;
//  - the stiff-spring simulator (K_f = 1e7, automatic step): its time (streaming, median
//    as above) and, with --stiff-record, its velocity record (t, v as raw float64 pairs)
//    for the event extraction of peer_common.py.
//
// The general model (docs/theory.md section 7) with --static-friction RS, --stiffness K,
// --damping C and --force-offset F0 (m = B = w = 1, lambda = R): the engine takes its general
// path (closed-form phases, certified search for the zeros). The stiff-spring simulator
// models the seed's problem only (B sin(w t), Rs = R, no spring or damper), so it is not
// run for such a model ("stiff": null).
//
// Writes one JSON object to --out: the double engine's events ("events", 17 digits) and the
// 50-digit engine's ("hp_event_times", 30 digits, as strings), which are the reference the
// peers' event times are measured against.
//
// Usage: ours --lambda L --v0 V --t-end T --out FILE [--min-time S] [--stiff-record FILE]
//             [--static-friction RS] [--stiffness K] [--damping C] [--force-offset F0]
#include <frictionref/frictionref.hpp>
#include <frictionref/multiprecision.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

// The event at the boundary between two consecutive phases.
const char* boundary_kind(frictionref::PhaseKind before, frictionref::PhaseKind after) {
  using frictionref::PhaseKind;
  if (before == PhaseKind::stick) return "breakaway";
  if (after == PhaseKind::stick) return "stop";
  if (before != after) return "reversal";
  return "touch";  // not emitted by the engine (a slip goes on through a grazing zero)
}

template <class Real>
std::vector<std::pair<const char*, Real>> events_of(const std::vector<frictionref::BasicPhase<Real>>& phases) {
  std::vector<std::pair<const char*, Real>> events;
  for (std::size_t i = 0; i + 1 < phases.size(); ++i)
    events.emplace_back(boundary_kind(phases[i].kind, phases[i + 1].kind), phases[i].t_end);
  return events;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Runs `body` until at least min_time seconds and min_reps runs; returns the median time.
template <class Body>
double median_time(double min_time, int min_reps, int& reps, Body body) {
  std::vector<double> times;
  double total = 0;
  while (total < min_time || static_cast<int>(times.size()) < min_reps) {
    const auto start = Clock::now();
    body();
    const double dt = seconds_since(start);
    times.push_back(dt);
    total += dt;
  }
  reps = static_cast<int>(times.size());
  std::sort(times.begin(), times.end());
  const std::size_t n = times.size();
  return n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
}

[[noreturn]] void usage() {
  std::fprintf(stderr,
               "usage: ours --lambda L --v0 V --t-end T --out FILE [--min-time S] "
               "[--stiff-record FILE] [--static-friction RS] [--stiffness K] [--damping C] "
               "[--force-offset F0]\n");
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  double lambda = NAN, v0 = 0, t_end = NAN, min_time = 0.2, rs = NAN, k = 0, c = 0, f0 = 0;
  std::string out, stiff_record;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) usage();
    const char* value = argv[++i];
    if (arg == "--lambda") lambda = std::strtod(value, nullptr);
    else if (arg == "--v0") v0 = std::strtod(value, nullptr);
    else if (arg == "--t-end") t_end = std::strtod(value, nullptr);
    else if (arg == "--min-time") min_time = std::strtod(value, nullptr);
    else if (arg == "--out") out = value;
    else if (arg == "--stiff-record") stiff_record = value;
    else if (arg == "--static-friction") rs = std::strtod(value, nullptr);
    else if (arg == "--stiffness") k = std::strtod(value, nullptr);
    else if (arg == "--damping") c = std::strtod(value, nullptr);
    else if (arg == "--force-offset") f0 = std::strtod(value, nullptr);
    else usage();
  }
  if (std::isnan(lambda) || std::isnan(t_end) || out.empty()) usage();

  frictionref::Model model;  // m = B = w = 1, x0 = t0 = 0
  model.friction = lambda;
  model.v0 = v0;
  if (!std::isnan(rs)) model.static_friction = rs;
  model.stiffness = k;
  model.damping = c;
  model.force_offset = f0;
  const bool general = !model.is_harmonic_coulomb();
  try {
    model.validate();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "ours: %s\n", error.what());
    return 2;
  }

  // 1. The double engine: events, then timing (streaming, no storage).
  const frictionref::Solution solution = frictionref::solve(model, t_end);
  const auto events = events_of(solution.phases);
  const frictionref::Summary& summary = solution.summary;

  double checksum = 0;
  int engine_reps = 0;
  const double engine_time = median_time(min_time, 5, engine_reps, [&] {
    frictionref::ExactEngine engine(model, t_end);
    frictionref::Phase phase;
    while (engine.next(phase)) checksum += phase.t_end;
  });

  // 2. The 50-digit engine: our own error.
  using frictionref::HighPrecision;
  const auto hp_start = Clock::now();
  const auto hp_solution = frictionref::solve(frictionref::model_cast<HighPrecision>(model),
                                              HighPrecision(t_end));
  const double hp_time = seconds_since(hp_start);
  const auto hp_events = events_of(hp_solution.phases);
  bool hp_same_sequence = hp_events.size() == events.size();
  double hp_max_abs = 0, hp_max_rel = 0, hp_max_at = 0;
  for (std::size_t i = 0; hp_same_sequence && i < events.size(); ++i) {
    if (std::strcmp(events[i].first, hp_events[i].first) != 0) {
      hp_same_sequence = false;
      break;
    }
    const HighPrecision diff = abs(HighPrecision(events[i].second) - hp_events[i].second);
    const double d = static_cast<double>(diff);
    const double rel = d / std::max(1.0, std::fabs(events[i].second));
    if (d > hp_max_abs) {
      hp_max_abs = d;
      hp_max_at = events[i].second;
    }
    hp_max_rel = std::max(hp_max_rel, rel);
  }

  // 3. The stiff-spring simulator at K_f = 1e7: time (streaming), then the record. It
  //    models the seed's problem only: skipped for the general model.
  frictionref::StiffSpringOptions stiff_options;
  stiff_options.kf = 1e7;
  int stiff_reps = 0;
  std::uint64_t stiff_steps = 0;
  double stiff_dt = 0;
  double stiff_time = 0;
  if (!general) {
    stiff_time = median_time(min_time, 3, stiff_reps, [&] {
      frictionref::StiffSpringSimulator simulator(model, t_end, stiff_options);
      frictionref::StiffSample sample;
      while (simulator.next(sample)) checksum += sample.v;
      stiff_steps = simulator.steps_taken();
      stiff_dt = simulator.step();
    });
  }
  std::uint64_t stiff_samples = 0;
  if (!general && !stiff_record.empty()) {
    std::FILE* record = std::fopen(stiff_record.c_str(), "wb");
    if (!record) {
      std::perror(stiff_record.c_str());
      return 1;
    }
    frictionref::StiffSpringSimulator simulator(model, t_end, stiff_options);
    frictionref::StiffSample sample;
    while (simulator.next(sample)) {
      const double row[2] = {sample.t, sample.v};
      std::fwrite(row, sizeof row, 1, record);
      ++stiff_samples;
    }
    if (std::fclose(record) != 0) {
      std::perror(stiff_record.c_str());
      return 1;
    }
  }

  // 4. JSON.
  const std::string tmp = out + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) {
    std::perror(tmp.c_str());
    return 1;
  }
  std::fprintf(f, "{\n  \"peer\": \"frictionref\",\n  \"version\": \"%s\",\n", frictionref::version);
  std::fprintf(f, "  \"lambda\": %.17g, \"v0\": %.17g, \"t_end\": %.17g,\n", lambda, v0, t_end);
  std::fprintf(f, "  \"general\": %s, \"static\": %.17g, \"stiffness\": %.17g, \"damping\": %.17g, "
               "\"force_offset\": %.17g,\n",
               general ? "true" : "false", model.static_limit(), k, c, f0);
  std::fprintf(f, "  \"termination\": \"%s\",\n",
               std::string(frictionref::to_string(summary.termination)).c_str());
  std::fprintf(f, "  \"phases\": %llu, \"stops\": %llu, \"reversals\": %llu, \"breakaways\": %llu,\n",
               static_cast<unsigned long long>(summary.phases),
               static_cast<unsigned long long>(summary.stops),
               static_cast<unsigned long long>(summary.reversals),
               static_cast<unsigned long long>(summary.breakaways));
  std::fprintf(f, "  \"velocity_evaluations\": %llu, \"sign_tests\": %llu, \"root_function_calls\": %llu,\n",
               static_cast<unsigned long long>(summary.sign_tests + summary.root_function_calls),
               static_cast<unsigned long long>(summary.sign_tests),
               static_cast<unsigned long long>(summary.root_function_calls));
  std::fprintf(f, "  \"time_s\": %.9g, \"reps\": %d,\n", engine_time, engine_reps);
  std::fprintf(f, "  \"hp_time_s\": %.6g, \"hp_same_sequence\": %s, \"hp_events\": %zu,\n", hp_time,
               hp_same_sequence ? "true" : "false", hp_events.size());
  std::fprintf(f, "  \"hp_max_abs_error\": %.6g, \"hp_max_rel_error\": %.6g, \"hp_max_error_at\": %.17g,\n",
               hp_max_abs, hp_max_rel, hp_max_at);
  if (general)
    std::fprintf(f, "  \"stiff\": null,\n");
  else
    std::fprintf(f, "  \"stiff\": {\"kf\": %.17g, \"dt\": %.17g, \"steps\": %llu, \"time_s\": %.9g, "
                 "\"reps\": %d, \"output_dt\": %.17g, \"samples\": %llu},\n",
                 stiff_options.kf, stiff_dt, static_cast<unsigned long long>(stiff_steps), stiff_time,
                 stiff_reps, stiff_options.output_dt, static_cast<unsigned long long>(stiff_samples));
  std::fprintf(f, "  \"checksum\": %.17g,\n", checksum);
  std::fprintf(f, "  \"events\": [");
  for (std::size_t i = 0; i < events.size(); ++i)
    std::fprintf(f, "%s\n    [\"%s\", %.17g]", i ? "," : "", events[i].first, events[i].second);
  std::fprintf(f, "\n  ],\n  \"hp_event_times\": [");
  for (std::size_t i = 0; i < hp_events.size(); ++i) {
    std::ostringstream text;
    text << std::setprecision(30) << hp_events[i].second;
    std::fprintf(f, "%s\n    [\"%s\", \"%s\"]", i ? "," : "", hp_events[i].first, text.str().c_str());
  }
  std::fprintf(f, "\n  ]\n}\n");
  if (std::fclose(f) != 0 || std::rename(tmp.c_str(), out.c_str()) != 0) {
    std::perror(out.c_str());
    return 1;
  }
  return 0;
}
