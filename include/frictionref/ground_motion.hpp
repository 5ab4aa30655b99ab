// A recorded ground motion: the ground's acceleration at increasing times,
// taken as linear between its samples and zero before the first and after
// the last (docs/theory.md 9), read from a file.
//
// Accepted files (docs/cli.md, "Ground-motion records"):
//   - PEER NGA .AT2: three header lines (the third says the units, G), a
//     fourth with NPTS and DT ("NPTS=  5990, DT=   .0100 SEC", or the older
//     "5990   0.0100   NPTS, DT"), then NPTS accelerations, several a line;
//   - a table of time and acceleration: comma-, semicolon- or blank-separated,
//     '#' comments, a header line, a UTF-8 byte-order mark, CRLF, Fortran 'D'
//     exponents: the tolerant reader of another code's time history
//     (time_history.hpp); times increasing, not necessarily uniform;
//   - one column of accelerations, with the step given (record_dt).
// Every error is an InvalidInput naming the file (and line) or the option
// and the rule.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frictionref {

// Units of the accelerations in a file.
enum class AccelUnits { g, m_per_s2, cm_per_s2, ft_per_s2, in_per_s2 };

// "g", "m/s2", "cm/s2", "ft/s2", "in/s2": the words of the CLI's
// --accel-units; from_string gives nothing for any other word.
std::string_view to_string(AccelUnits units);
std::optional<AccelUnits> accel_units_from_string(std::string_view text);
// One standard gravity (9.80665 m/s^2) in `units`: 1, 9.80665, 980.665,
// 9.80665 / 0.3048, 9.80665 / 0.0254.
double standard_gravity_in(AccelUnits units);

// The length unit that standard gravity G (in length per s^2) names, as the
// outputs say it: "m" for 9.80665, "cm" for 980.665, "ft", "in"; for any
// other G, "the length unit in which g = G".
std::string length_unit_of_gravity(double gravity);

struct GroundMotionReadOptions {
  enum class Format { automatic, peer_at2, table };
  // automatic: PEER .AT2 when the file name ends in .at2 (any case) or its
  // first line starts with "PEER"; a table otherwise.
  Format format = Format::automatic;

  // Set: the file is one column of accelerations at this step [s] (> 0,
  // finite), the first at t = 0. Not allowed with a table of two columns or
  // more (its times are in the file) nor with .AT2 (its DT is).
  std::optional<double> record_dt;

  // The units of the file's accelerations. Unset: g. A .AT2 file states
  // its units (G); giving others for it is an error.
  std::optional<AccelUnits> units;

  // Standard gravity in the length unit of the output per s^2 (> 0,
  // finite): 9.80665 gives metres (and m/s^2), 980.665 centimetres, and so
  // on. The record comes out in that unit: a = a_file * gravity / g_file,
  // with g_file = standard_gravity_in(units).
  double gravity = 9.80665;

  // At most one of: a factor on the accelerations (> 0, finite), or the
  // peak ground acceleration to scale to, in g (> 0, finite).
  std::optional<double> scale;
  std::optional<double> target_pga;

  // The record negated (after scaling): the "inverse" polarity.
  bool inverse = false;

  // Throws InvalidInput naming the field and the rule.
  void validate() const;
};

struct GroundMotion {
  std::vector<double> t;  // times [s]; finite, increasing
  std::vector<double> a;  // ground acceleration at t, scaled, in the output unit
                          // (gravity's length per s^2); finite

  // Provenance, for the metadata lines of every output.
  std::string file;                  // the name as given ("standard input" for -)
  std::string sha256;                // of the file's bytes, 64 lower-case hex digits
  std::string format;                // "PEER NGA AT2", "time-acceleration table", "one column"
  std::vector<std::string> header;   // an .AT2 file's four header lines; a table's title lines
  std::size_t npts = 0;              // samples read
  std::optional<double> dt;          // the file's step, if it has one (AT2, one column)
  AccelUnits units = AccelUnits::g;  // of the file
  double pga_as_read = 0;            // max |a| in the file, in its units
  double gravity = 9.80665;          // as GroundMotionReadOptions::gravity
  double factor = 1;                 // a = factor * a_file (units, scaling and sign)
  std::string scaling;               // "none", "scale 2", "target PGA 0.3 g (x 1.25)", "+ inverse"
  std::vector<std::string> notes;    // what the reader did that a reader should know

  std::size_t samples() const { return t.size(); }
  double duration() const { return t.back() - t.front(); }
  double pga() const;  // max |a| after scaling, in the output unit
  // Peak ground velocity: max |v_g| of the ground's velocity v_g, integrated
  // exactly from rest at t[0] (baseline as recorded, no correction).
  double pgv() const;

  // Throws InvalidInput naming the field ("t[7]", "a", ...), the value and
  // the rule: equal lengths, at least 2 samples, finite values, t increasing.
  void validate() const;
};

// Reads `path` ("-" reads standard input). Throws InvalidInput: "file" for
// a file that cannot be read, is empty, is too large (over 1 GiB) or has
// fewer than 2 samples; "<path>:<line>" (and column) for a bad line or value;
// the option's name for options that do not fit the file.
GroundMotion read_ground_motion(const std::string& path,
                                const GroundMotionReadOptions& options = {});

// The same from bytes already read; `name` stands for the file in messages
// and decides the automatic format by its extension.
GroundMotion parse_ground_motion(const std::string& bytes, const std::string& name,
                                 const GroundMotionReadOptions& options = {});

}  // namespace frictionref
