// How many terms a Taylor series needs: for a series whose n-th term is
// bounded by x^n / n! (x = u times a rate bound), the terms after the N-th
// are below eps / 64 of the leading one once x^N / N! <= eps / 64. The table
// holds, for N = 1, 2, ..., the largest x for which N terms are enough, up
// to the series' range `limit`. Shared by the transition functions and the
// harmonic responses of the general laws.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <mutex>
#include <vector>

namespace frictionref::detail {

template <class Work>
class SeriesReach {
 public:
  explicit SeriesReach(double limit) : reach_(&table(limit)) {}

  // The number of terms the largest x in range needs.
  std::size_t max_terms() const { return reach_->size(); }

  // Index i (terms i + 1) of the fewest terms enough at x (<= the limit).
  std::size_t index_for(const Work& x) const {
    const std::vector<Work>& reach = *reach_;
    std::size_t n = 0;
    while (n + 1 < reach.size() && reach[n] < x) ++n;
    return n;
  }

 private:
  // One table per limit, built once and shared: the general laws are built
  // for every phase that dense output evaluates, and the table's pow calls
  // cost more than a phase's rows (a quarter of a dense sample's time).
  static const std::vector<Work>& table(double limit) {
    static std::mutex mutex;
    static std::map<double, std::vector<Work>> tables;  // references stay valid
    const std::lock_guard<std::mutex> lock(mutex);
    auto [it, inserted] = tables.try_emplace(limit);
    if (inserted) it->second = build(limit);
    return it->second;
  }

  static std::vector<Work> build(double limit) {
    using std::pow;
    std::vector<Work> reach;
    const Work tiny = std::numeric_limits<Work>::epsilon() / 64;
    Work factorial = 1;
    for (int terms = 1;; ++terms) {
      factorial *= Work(terms);
      reach.push_back(Work(pow(factorial * tiny, Work(1) / Work(terms))));
      if (reach.back() >= Work(limit)) break;
    }
    return reach;
  }

  const std::vector<Work>* reach_;
};

}  // namespace frictionref::detail
