// The last point a phase's search or polish evaluated, kept for the next
// question about the same time: the root solvers ask for f and f' one after
// the other, and a search's last step is often where the next step, the
// polish or the stop's rules look (family.hpp).
#pragma once

#include <limits>

namespace frictionref::detail {

template <class Work, class Point>
class LastPoint {
 public:
  // The point at t: the kept one if it is at t, else evaluate(t), kept.
  template <class Evaluate>
  const Point& at(const Work& t, const Evaluate& evaluate) {
    if (!(t == tau_)) {
      point_ = evaluate(t);
      tau_ = t;
    }
    return point_;
  }
  const Work& tau() const { return tau_; }  // NaN while none is kept
  const Point& point() const { return point_; }
  void forget() { tau_ = std::numeric_limits<Work>::quiet_NaN(); }

 private:
  Work tau_ = std::numeric_limits<Work>::quiet_NaN();
  Point point_{};
};

}  // namespace frictionref::detail
