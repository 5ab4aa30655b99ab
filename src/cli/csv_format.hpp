// How numbers, metadata and rows are spelled in every file we write
// (docs/cli.md "Output formats"). Numbers use fmt "{}": the shortest text that
// strtod reads back to the same double.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "frictionref/model.hpp"
#include "frictionref/model_fields.hpp"
#include "frictionref/phase.hpp"
#include "frictionref/sampling.hpp"

namespace frictionref::cli {

// Shortest round-trip form: 0.3, 1, 1e-05, -0, inf, nan.
std::string number(double value);

// The command line as one shell-quoted line, for "# command:" (re-runnable):
// "frictionref <args>", argv[0] replaced by the program's name.
std::string command_line(int argc, const char* const* argv);

// The provenance of a ground motion, one line each: file, format, SHA-256;
// the .AT2 header; NPTS, dt, PGA as read, the scaling; the interpolation rule.
std::vector<std::string> record_metadata(const GroundMotion& record);

// "# frictionref <version>", "# model: ...", "# command: ...", the record's
// lines (record_metadata) if the model has one, then one "# <line>" per extra
// line (e.g. "grid: ..."). Comment lines precede the header.
void write_metadata(std::FILE* out, const Model& model, const std::string& command,
                    const std::vector<std::string>& extra_lines);

// events: "phase,t_begin,t_end,x_begin,x_end,v_begin,v_end"
void write_phase_header(std::FILE* out);
void write_phase_row(std::FILE* out, const Phase& phase);

// curve: "t,x,v,a,phase", a sampler's block of rows at a time
void write_state_header(std::FILE* out);
void write_state_rows(std::FILE* out, const StateRows& rows);

}  // namespace frictionref::cli
