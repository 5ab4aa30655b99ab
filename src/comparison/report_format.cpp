#include "report_format.hpp"

#include <cstdio>

namespace frictionref::comparison {

std::string g(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::string signed_g(double value) { return (value > 0 ? "+" : "") + g(value); }

std::string interval(double start, double end) { return "[" + g(start) + ", " + g(end) + "]"; }

std::string interval(const StickInterval& s) { return interval(s.start, s.end); }

std::string interval_list(const std::vector<StickInterval>& list, std::size_t limit) {
  std::string out;
  for (std::size_t i = 0; i < list.size() && i < limit; ++i)
    out += (i ? ", " : "") + interval(list[i]);
  if (list.size() > limit) out += ", and " + std::to_string(list.size() - limit) + " more";
  return out;
}

std::string steady_text(Regime regime, ClassificationMethod method) {
  std::string s(to_string(regime));
  if (method == ClassificationMethod::simulation) s += " (by simulation)";
  return s;
}

}  // namespace frictionref::comparison
