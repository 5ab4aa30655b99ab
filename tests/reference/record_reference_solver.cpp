// The 50-digit rigid block under a ground motion (record_reference_solver.hpp).
#include "record_reference_solver.hpp"

#include <algorithm>
#include <limits>

namespace frictionref_reference {
namespace {

using D = Decimal50;

// g(t) = f0 - a_g(t) on interval k: [T[k], T[k+1]) with the convention
// T[0] = -inf, T[1..n] = samples, T[n+1] = +inf.
struct Net {
  const RecordBlock& b;
  std::size_t n() const { return b.t.size(); }
  D begin(std::size_t k) const { return k == 0 ? D(-1e300) : D(b.t[k - 1]); }
  D end(std::size_t k) const { return k >= n() ? D(1e300) : D(b.t[k]); }
  // g = p + q (t - begin) on interval k.
  void line(std::size_t k, D& p, D& q) const {
    if (k == 0 || k >= n()) {
      p = D(b.offset);
      q = 0;
      return;
    }
    const D a0(b.a[k - 1]), a1(b.a[k]);
    p = D(b.offset) - a0;
    q = -(a1 - a0) / (D(b.t[k]) - D(b.t[k - 1]));
  }
  std::size_t interval_of(const D& t) const {
    std::size_t k = 0;
    while (k < n() && D(b.t[k]) <= t) ++k;
    return k;
  }
};

int at_rest(const RecordBlock& b, const D& g, const D& slope) {
  const D ms(b.mu_static);
  if (g > ms || (g == ms && slope > 0)) return 1;
  if (b.one_way) return 0;
  if (g < -ms || (g == -ms && slope < 0)) return -1;
  return 0;
}

}  // namespace

std::vector<RecordEvent> solve_record_block(const RecordBlock& block, double t_end_double) {
  const Net net{block};
  const D t_end(t_end_double);
  std::vector<RecordEvent> events;
  D t(block.t0), x(block.x0), v(block.v0);
  int mode;  // 0 stick, +-1 slip
  {
    const std::size_t k = net.interval_of(t);
    D p, q;
    net.line(k, p, q);
    const D g = p + q * (t - net.begin(k == 0 ? 0 : k));
    mode = v > 0 ? 1 : v < 0 ? -1 : at_rest(block, k == 0 ? p : g, q);
  }
  for (int guard = 0; guard < 10000000 && t < t_end; ++guard) {
    std::size_t k = net.interval_of(t);
    if (mode == 0) {
      // Stuck: the first time |g| > mu_static (one-way: g > mu_static).
      bool found = false;
      for (; k <= net.n() && !found; ++k) {
        D p, q;
        net.line(k, p, q);
        const D from = std::max(t, net.begin(k)), to = std::min(t_end, net.end(k));
        if (!(from < t_end)) break;
        const D base = k == 0 || k >= net.n() ? D(0) : net.begin(k);
        const D g_from = k == 0 || k >= net.n() ? p : p + q * (from - base);
        const int d = at_rest(block, g_from, q);
        if (d != 0 && from > t) {
          t = from;
          mode = d;
          found = true;
          break;
        }
        if (q == 0) continue;
        const D g_to = p + q * (to - base);
        for (int side : {1, -1}) {
          if (side < 0 && block.one_way) continue;
          if (side * g_to > D(block.mu_static) && side * q > 0) {
            t = base + (side * D(block.mu_static) - p) / q;
            if (t < from) t = from;
            mode = side;
            found = true;
            break;
          }
        }
      }
      if (!found) return events;
      v = 0;
      events.push_back({t, x, mode});
      continue;
    }
    // Sliding with sign s: v(t) = v_a + (p' ) h + q h^2 / 2 on each interval,
    // p' = g(start) - s mu.
    const int s = mode;
    bool stopped = false;
    for (; k <= net.n(); ++k) {
      D p, q;
      net.line(k, p, q);
      const D base = k == 0 || k >= net.n() ? t : net.begin(k);
      const D from = std::max(t, base);
      const D to = std::min(t_end, net.end(k));
      if (!(to > from)) continue;
      D acc = (k == 0 || k >= net.n() ? p : p + q * (from - base)) - s * D(block.mu);
      if (v == 0 && s * acc < 0) acc = 0;
      const D a2 = q / 2, a1 = acc, a0 = v;
      const D len = to - from;
      // Smallest root h in (0, len] of a2 h^2 + a1 h + a0 where s v stops being > 0.
      D root = -1;
      if (a2 == 0) {
        if (a1 != 0) {
          const D h = -a0 / a1;
          if (h > 0 && h <= len) root = h;
        }
      } else {
        const D disc = a1 * a1 - 4 * a2 * a0;
        if (disc >= 0) {
          const D sq = sqrt(disc);
          D r1 = (-a1 - sq) / (2 * a2), r2 = (-a1 + sq) / (2 * a2);
          if (r1 > r2) std::swap(r1, r2);
          for (const D& r : {r1, r2})
            if (r > 0 && r <= len) {
              // Only where s v actually reaches 0 from above (a double root
              // counts: a touch).
              const D mid = r / 2;
              if (s * (a0 + mid * (a1 + mid * a2)) > 0 || a0 == 0) {
                root = r;
                break;
              }
            }
        }
      }
      if (root >= 0) {
        x = x + root * (v + root * (acc / 2 + root * q / 6));
        t = from + root;
        v = 0;
        const std::size_t after = net.interval_of(t);
        D pa, qa;
        net.line(after, pa, qa);
        const D g = after == 0 || after >= net.n() ? pa : pa + qa * (t - net.begin(after));
        const int next = at_rest(block, g, qa);
        if (next == s) {  // a touch: goes on
          mode = s;
          stopped = true;
          break;
        }
        mode = next;
        events.push_back({t, x, mode});
        stopped = true;
        break;
      }
      x = x + len * (v + len * (acc / 2 + len * q / 6));
      v = v + len * (acc + len * q / 2);
      t = to;
      if (!(t < t_end)) return events;
    }
    if (!stopped) return events;
  }
  return events;
}

}  // namespace frictionref_reference
