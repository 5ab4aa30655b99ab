// An independent, deliberately simple, 50-digit solution of the rigid block
// under a ground motion (Newmark's block), the oracle for the engine's event
// times on records (docs/accuracy.md, "Records").
//
// Independence from the engine, on purpose:
//   * no frictionref header: the model is this file's own struct, the
//     motion is written again from its definition (docs/theory.md 8 is not
//     read: v' = g(t) - s mu with g = f0 - a_g, a_g linear between samples,
//     0 outside them);
//   * every computation in boost::multiprecision::cpp_bin_float_50 from the
//     double samples converted exactly, in absolute time (no forcing phase),
//     with the state at each sample recomputed from the slip's start by
//     summing exact segment integrals;
//   * stops from both roots of the quadratic on a sample interval taken by
//     the textbook formula at 50 digits (no vertex split, no Newton), the
//     smallest root in the interval where the velocity changes sign or
//     touches 0; breakaways from the linear root.
#pragma once

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cstddef>
#include <vector>

namespace frictionref_reference {

using Decimal50 = boost::multiprecision::cpp_bin_float_50;

struct RecordBlock {
  std::vector<double> t;  // sample times, increasing
  std::vector<double> a;  // ground acceleration at t
  double offset = 0;      // f0 = F0 / m
  double mu = 0;          // R / m
  double mu_static = 0;   // Rs / m (>= mu)
  bool one_way = false;
  double t0 = 0, x0 = 0, v0 = 0;
};

struct RecordEvent {
  Decimal50 t;
  Decimal50 x;
  int kind_after;  // 0 stick, +1 / -1 slip direction
};

// The phase boundaries on (t0, t_end): each breakaway, stop, reversal.
std::vector<RecordEvent> solve_record_block(const RecordBlock& block, double t_end);

}  // namespace frictionref_reference
