// Reading a ground-motion record (ground_motion.hpp): a PEER .AT2 file, a
// table of time and acceleration through the tolerant table reader
// (io/text_table.hpp), or one column at a given step; then the units, the
// scaling and the polarity, recorded with the file's SHA-256.
#include "frictionref/ground_motion.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string_view>

#include "frictionref/detail/number_text.hpp"
#include "frictionref/error.hpp"
#include "frictionref/sha256.hpp"
#include "frictionref/time_history.hpp"
#include "io/text_table.hpp"

namespace frictionref {
namespace {

using io::text;

// Files beyond this are refused before they are read (a record of 10^8
// samples is some 1.5 GB of text; nobody means that).
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(1) << 30;
constexpr double kMaxSamples = 1e8;

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

bool ends_with_at2(const std::string& name) {
  return name.size() >= 4 && upper(std::string_view(name).substr(name.size() - 4)) == ".AT2";
}

// The lines of `bytes` without their ends (LF or CRLF) and a leading BOM.
std::vector<std::string_view> lines_of(std::string_view bytes) {
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
  std::vector<std::string_view> lines;
  while (!bytes.empty()) {
    const std::size_t end = bytes.find('\n');
    std::string_view line = bytes.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    if (end == std::string_view::npos) break;
    bytes.remove_prefix(end + 1);
  }
  return lines;
}

// The raw samples of a file before units and scaling.
struct RawRecord {
  std::vector<double> t, a;
  std::optional<double> dt;
  std::string format;
  std::vector<std::string> header;
  std::vector<std::string> notes;
  AccelUnits units = AccelUnits::g;
};

// The number after `key` and '=' on an .AT2 fourth line ("NPTS=  5990,").
std::optional<std::string> value_after(const std::string& line, const char* key) {
  std::size_t at = line.find(key);
  if (at == std::string::npos) return std::nullopt;
  at += std::string_view(key).size();
  while (at < line.size() && io::is_blank(line[at])) ++at;
  if (at >= line.size() || line[at] != '=') return std::nullopt;
  ++at;
  while (at < line.size() && io::is_blank(line[at])) ++at;
  std::size_t end = at;
  while (end < line.size() && !io::is_blank(line[end]) && line[end] != ',') ++end;
  return line.substr(at, end - at);
}

RawRecord read_at2(std::string_view bytes, const std::string& name,
                   const GroundMotionReadOptions& options) {
  const std::vector<std::string_view> lines = lines_of(bytes);
  const auto where = [&](std::size_t line) { return name + ":" + std::to_string(line); };
  if (lines.size() < 4)
    throw InvalidInput("file", name,
                       "has " + std::to_string(lines.size()) +
                           " lines; a PEER .AT2 record has 4 header lines (title, event, "
                           "units, NPTS and DT) before its data");
  RawRecord raw;
  raw.format = "PEER NGA AT2";
  for (std::size_t i = 0; i < 4; ++i) raw.header.emplace_back(io::trim(lines[i]));

  // Line 3: "ACCELERATION TIME SERIES IN UNITS OF G".
  const std::string units_line = upper(lines[2]);
  if (units_line.find("ACCEL") == std::string::npos)
    throw InvalidInput(where(3), io::snippet(lines[2]),
                       "is not the units line of an acceleration record (a PEER .AT2 file says "
                       "'ACCELERATION TIME SERIES IN UNITS OF G' here; .VT2 and .DT2 files hold "
                       "velocities and displacements)");
  const std::size_t of = units_line.find("UNITS OF");
  if (of != std::string::npos) {
    std::string_view unit = io::trim(std::string_view(units_line).substr(of + 8));
    unit = unit.substr(0, unit.find_first_of(" \t,"));
    if (unit != "G")
      throw InvalidInput(where(3), io::snippet(lines[2]),
                         "states units '" + std::string(unit) +
                             "'; a PEER .AT2 record is read in G (convert the file to a table "
                             "of time and acceleration and give its units with --accel-units)");
  }
  if (options.units && *options.units != AccelUnits::g)
    throw InvalidInput(
        "accel_units", std::string(to_string(*options.units)),
        "does not apply to " + name + ": a PEER .AT2 file states its units (G, line 3)");
  if (options.record_dt)
    throw InvalidInput(
        "record_dt", text(*options.record_dt),
        "does not apply to " + name + ": a PEER .AT2 file states its step (DT, line 4)");

  // Line 4: "NPTS=  5990, DT=   .0100 SEC" or "5990   0.0100   NPTS, DT".
  const std::string dims = upper(lines[3]);
  std::string npts_text, dt_text;
  if (auto n = value_after(dims, "NPTS"), d = value_after(dims, "DT"); n && d) {
    npts_text = *n;
    dt_text = *d;
  } else {
    std::vector<std::string> fields;
    io::split(io::trim(lines[3]), io::Separator::blanks, fields);
    double ignored = 0;
    if (fields.size() >= 2 && io::to_number(fields[0], ignored) &&
        io::to_number(fields[1], ignored) && dims.find("NPTS") != std::string::npos &&
        dims.find("DT") != std::string::npos) {
      npts_text = fields[0];
      dt_text = fields[1];
    } else {
      throw InvalidInput(where(4), io::snippet(lines[3]),
                         "must give the number of points and the step, as 'NPTS= 5990, DT= "
                         ".0100 SEC' or '5990 0.0100 NPTS, DT'");
    }
  }
  double npts = 0, dt = 0;
  if (!io::to_number(npts_text, npts) || !(npts >= 2) || npts > kMaxSamples ||
      npts != std::floor(npts))
    throw InvalidInput(where(4) + " NPTS", npts_text,
                       "must be a whole number of samples from 2 to 10^8");
  if (!io::to_number(dt_text, dt) || !std::isfinite(dt) || !(dt > 0))
    throw InvalidInput(where(4) + " DT", dt_text, "must be a finite step > 0 (seconds)");
  raw.dt = dt;

  const auto expected = static_cast<std::size_t>(npts);
  std::vector<std::string> fields;
  for (std::size_t i = 4; i < lines.size(); ++i) {
    io::split(io::trim(io::strip_comment(lines[i])), io::Separator::blanks, fields);
    for (const std::string& field : fields) {
      double value = 0;
      if (!io::to_number(field, value))
        throw InvalidInput(where(i + 1), field, "must be a number (an acceleration in G)");
      if (!std::isfinite(value)) throw InvalidInput(where(i + 1), field, "must be a finite number");
      if (raw.a.size() == expected)
        throw InvalidInput("file", name,
                           "has more values than NPTS = " + npts_text +
                               " (line 4) says: the header disagrees with the data (the first "
                               "value beyond is on line " +
                               std::to_string(i + 1) + ")");
      raw.a.push_back(value);
    }
  }
  if (raw.a.size() != expected)
    throw InvalidInput("file", name,
                       "has " + std::to_string(raw.a.size()) +
                           " values after its header, but "
                           "NPTS = " +
                           npts_text + " (line 4): the header disagrees with the data");
  raw.t.resize(expected);
  for (std::size_t i = 0; i < expected; ++i) raw.t[i] = static_cast<double>(i) * dt;
  return raw;
}

RawRecord read_table(std::string_view bytes, const std::string& name,
                     const GroundMotionReadOptions& options) {
  io::TableShape shape;
  shape.min_columns = options.record_dt ? 1 : 2;
  shape.what = "a ground-motion record";
  shape.columns_needed =
      "2 (time and acceleration), or 1 (accelerations) with the step given (--record-dt)";
  shape.numbers_needed = "rows of numbers: time and acceleration";
  std::istringstream in{std::string(bytes)};
  io::TextTableReader table(in, name, shape);
  table.open();

  RawRecord raw;
  raw.units = options.units.value_or(AccelUnits::g);
  if (options.record_dt) {
    if (table.columns() != 1)
      throw InvalidInput("record_dt", text(*options.record_dt),
                         "does not apply to " + name + ": it has " +
                             std::to_string(table.columns()) + " columns (line " +
                             std::to_string(table.first_line()) +
                             "), so its times are in the file; --record-dt is for one column "
                             "of accelerations");
    raw.format = "one column";
    raw.dt = *options.record_dt;
    while (table.next_row()) raw.a.push_back(table.number(0));
    table.check_stream();
    // t = i dt exactly as a product, never a running sum.
    raw.t.resize(raw.a.size());
    for (std::size_t i = 0; i < raw.a.size(); ++i) raw.t[i] = static_cast<double>(i) * *raw.dt;
  } else {
    static const char* const time_names[] = {"t", "time", nullptr};
    static const char* const accel_names[] = {"a",   "acc", "accel", "acceleration",
                                              "a_g", "ag",  nullptr};
    std::optional<std::size_t> time = table.find_column(time_names);
    std::optional<std::size_t> accel = table.find_column(accel_names);
    if (table.columns() == 2) {
      if (!time) time = accel ? 1 - *accel : 0;
      if (!accel) accel = 1 - *time;
    }
    if (!time || !accel || *time == *accel)
      throw InvalidInput("file", name,
                         "has " + std::to_string(table.columns()) + " columns (line " +
                             std::to_string(table.first_line()) +
                             "); a record table needs 2 (time, acceleration), or a header "
                             "naming them (t or time; a, acc, accel or acceleration)");
    raw.format = "time-acceleration table";
    std::size_t previous_line = 0;
    while (table.next_row()) {
      const double t = table.number(*time);
      if (!raw.t.empty() && !(t > raw.t.back()))
        throw InvalidInput(table.location(table.line(), *time), table.fields()[*time],
                           "must be > the time on line " + std::to_string(previous_line) + " (" +
                               text(raw.t.back()) + "): the times of a record must increase");
      raw.t.push_back(t);
      raw.a.push_back(table.number(*accel));
      previous_line = table.line();
      if (static_cast<double>(raw.t.size()) > kMaxSamples)
        throw InvalidInput("file", name, "has more than 10^8 samples");
    }
    table.check_stream();
  }
  raw.notes = std::move(table.notes());
  return raw;
}

}  // namespace

std::string_view to_string(AccelUnits units) {
  switch (units) {
    case AccelUnits::g:
      return "g";
    case AccelUnits::m_per_s2:
      return "m/s2";
    case AccelUnits::cm_per_s2:
      return "cm/s2";
    case AccelUnits::ft_per_s2:
      return "ft/s2";
    case AccelUnits::in_per_s2:
      return "in/s2";
  }
  return "?";
}

std::optional<AccelUnits> accel_units_from_string(std::string_view text) {
  for (AccelUnits units : {AccelUnits::g, AccelUnits::m_per_s2, AccelUnits::cm_per_s2,
                           AccelUnits::ft_per_s2, AccelUnits::in_per_s2})
    if (to_string(units) == text) return units;
  return std::nullopt;
}

std::string length_unit_of_gravity(double gravity) {
  for (const AccelUnits units : {AccelUnits::m_per_s2, AccelUnits::cm_per_s2, AccelUnits::ft_per_s2,
                                 AccelUnits::in_per_s2}) {
    if (gravity == standard_gravity_in(units)) {
      const std::string_view text = to_string(units);
      return std::string(text.substr(0, text.find('/')));
    }
  }
  return "the length unit in which g = " + detail::shortest_text(gravity);
}

double standard_gravity_in(AccelUnits units) {
  constexpr double g = 9.80665;  // m/s^2, exact by definition (CGPM 1901)
  switch (units) {
    case AccelUnits::g:
      return 1;
    case AccelUnits::m_per_s2:
      return g;
    case AccelUnits::cm_per_s2:
      return 980.665;
    case AccelUnits::ft_per_s2:
      return g / 0.3048;  // the international foot, exact
    case AccelUnits::in_per_s2:
      return g / 0.0254;
  }
  return 1;
}

void GroundMotionReadOptions::validate() const {
  const auto positive = [](const char* name, double value, const char* what) {
    if (!std::isfinite(value) || !(value > 0))
      throw InvalidInput(name, text(value),
                         std::string("must be a finite number > 0 (") + what + ")");
  };
  if (record_dt) positive("record_dt", *record_dt, "the record's step in seconds");
  positive("gravity", gravity, "standard gravity in the output's length unit per s^2");
  if (scale) positive("scale", *scale, "a factor on the accelerations; --inverse negates");
  if (target_pga) positive("target_pga", *target_pga, "the peak ground acceleration in g");
  if (scale && target_pga)
    throw InvalidInput(
        "target_pga", text(*target_pga),
        "cannot be given with scale = " + text(*scale) + ": choose one way of scaling the record");
}

double GroundMotion::pga() const {
  // Four running maxima, so that the loop is not one chain of dependent
  // comparisons (the engine reads the PGA of every record it solves).
  double peak[4] = {0, 0, 0, 0};
  std::size_t i = 0;
  for (; i + 4 <= a.size(); i += 4)
    for (std::size_t j = 0; j < 4; ++j) peak[j] = std::max(peak[j], std::fabs(a[i + j]));
  for (; i < a.size(); ++i) peak[0] = std::max(peak[0], std::fabs(a[i]));
  return std::max(std::max(peak[0], peak[1]), std::max(peak[2], peak[3]));
}

// The ground's velocity is the integral of the piecewise-linear acceleration
// from rest at t[0]: a quadratic on each interval, extreme at the interval's
// ends or where the acceleration changes sign inside it; constant after the
// last sample (the acceleration is zero there).
double GroundMotion::pgv() const {
  double v = 0;
  double peak = 0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double h = t[i + 1] - t[i];
    if ((a[i] < 0 && a[i + 1] > 0) || (a[i] > 0 && a[i + 1] < 0)) {
      const double s = h * a[i] / (a[i] - a[i + 1]);  // the sign change, in (0, h)
      peak = std::max(peak, std::fabs(v + 0.5 * a[i] * s));
    }
    v += 0.5 * (a[i] + a[i + 1]) * h;
    peak = std::max(peak, std::fabs(v));
  }
  return peak;
}

void GroundMotion::validate() const {
  if (a.size() != t.size())
    throw InvalidInput("a", std::to_string(a.size()) + " values",
                       "must have as many values as t (" + std::to_string(t.size()) + ")");
  if (t.size() < 2)
    throw InvalidInput("t", std::to_string(t.size()) + " values", "needs at least 2 samples");
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i]))
      throw InvalidInput("t[" + std::to_string(i) + "]", text(t[i]), "must be a finite number");
    if (!std::isfinite(a[i]))
      throw InvalidInput("a[" + std::to_string(i) + "]", text(a[i]), "must be a finite number");
    if (i > 0 && !(t[i] > t[i - 1]))
      throw InvalidInput("t[" + std::to_string(i) + "]", text(t[i]),
                         "must be > t[" + std::to_string(i - 1) + "] = " + text(t[i - 1]) +
                             ": the times of a record must increase");
  }
}

GroundMotion parse_ground_motion(const std::string& bytes, const std::string& name,
                                 const GroundMotionReadOptions& options) {
  options.validate();
  if (bytes.size() > kMaxFileBytes)
    throw InvalidInput("file", name, "is larger than 1 GiB; a record is not that large");
  using Format = GroundMotionReadOptions::Format;
  const bool at2 = options.format == Format::peer_at2 ||
                   (options.format == Format::automatic &&
                    (ends_with_at2(name) || upper(std::string_view(bytes).substr(0, 4)) == "PEER"));
  RawRecord raw = at2 ? read_at2(bytes, name, options) : read_table(bytes, name, options);
  if (raw.a.size() < 2)
    throw InvalidInput("file", name,
                       "has " + std::to_string(raw.a.size()) + " sample" +
                           (raw.a.size() == 1 ? "" : "s") + "; a record needs at least 2");

  GroundMotion record;
  record.file = name;
  record.sha256 = sha256_hex(bytes);
  record.format = raw.format;
  record.header = std::move(raw.header);
  record.notes = std::move(raw.notes);
  record.npts = raw.a.size();
  record.dt = raw.dt;
  record.units = raw.units;
  record.gravity = options.gravity;
  for (double value : raw.a) record.pga_as_read = std::max(record.pga_as_read, std::fabs(value));

  // a = a_file * gravity / g_file * s: the unit factor is 1 exactly when the
  // file is already in the output's unit (m/s2 with the default gravity).
  const double g_file = standard_gravity_in(raw.units);
  double s = 1;
  record.scaling = "none";
  if (options.scale) {
    s = *options.scale;
    record.scaling = "scale " + text(s);
  } else if (options.target_pga) {
    if (!(record.pga_as_read > 0))
      throw InvalidInput("target_pga", text(*options.target_pga),
                         "cannot scale " + name + ": every acceleration in it is 0");
    s = *options.target_pga * g_file / record.pga_as_read;
    record.scaling = "target PGA " + text(*options.target_pga) + " g (x " + text(s) + ")";
  }
  if (options.inverse)
    record.scaling = record.scaling == "none" ? "inverse" : record.scaling + ", inverse";
  const double unit_factor = options.gravity == g_file ? 1.0 : options.gravity / g_file;
  record.factor = (options.inverse ? -1.0 : 1.0) * unit_factor * s;
  // A factor out of double's range would turn the record into zeros (or
  // infinities) without a word.
  if (!std::isfinite(record.factor) || record.factor == 0) {
    const std::string rule = "with --gravity " + text(options.gravity) + " and the file's units (" +
                             std::string(to_string(raw.units)) +
                             ") gives the accelerations a factor of " + text(record.factor) +
                             ", outside double's range";
    if (options.scale) throw InvalidInput("scale", text(*options.scale), rule);
    if (options.target_pga) throw InvalidInput("target_pga", text(*options.target_pga), rule);
    throw InvalidInput("gravity", text(options.gravity), rule);
  }
  record.t = std::move(raw.t);
  record.a.resize(raw.a.size());
  for (std::size_t i = 0; i < raw.a.size(); ++i) {
    record.a[i] = raw.a[i] * record.factor;
    if (!std::isfinite(record.a[i]))
      throw InvalidInput(
          "scale", text(s),
          "makes the acceleration of sample " + std::to_string(i) + " in " + name + " overflow");
  }
  if (record.dt && (!std::isfinite(record.t.back()) ||
                    std::adjacent_find(record.t.begin(), record.t.end(), [](double a, double b) {
                      return !(b > a);
                    }) != record.t.end()))
    throw InvalidInput("record_dt", text(*record.dt),
                       "gives " + std::to_string(record.npts) +
                           " sample times i dt that are not finite and increasing in double "
                           "precision");
  return record;
}

GroundMotion read_ground_motion(const std::string& path, const GroundMotionReadOptions& options) {
  options.validate();
  std::string bytes;
  if (path == "-") {
    bytes.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
    if (std::cin.bad()) throw InvalidInput("file", "standard input", "cannot be read");
    return parse_ground_motion(bytes, "standard input", options);
  }
  std::ifstream in = open_time_history_file(path);
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (!error && size > kMaxFileBytes)
    throw InvalidInput("file", path, "is larger than 1 GiB; a record is not that large");
  bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) throw InvalidInput("file", path, "cannot be read (input error)");
  return parse_ground_motion(bytes, path, options);
}

}  // namespace frictionref
