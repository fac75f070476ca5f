#include "metrics/statistics.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <string>

namespace imasim::metrics {

GroupSummary summarize(std::span<const double> values) {
  GroupSummary g;
  g.n = values.size();
  double sum = 0;
  for (const double v : values) {
    if (!std::isfinite(v)) throw StatisticsError("a value is not a finite number");
    sum += v;
  }
  if (g.n == 0) return g;
  g.mean = sum / double(g.n);
  double squares = 0;  // two passes: no cancellation for values far from zero
  for (const double v : values)
    squares += (v - g.mean) * (v - g.mean);
  g.sd = g.n > 1 ? std::sqrt(squares / double(g.n - 1)) : 0;
  return g;
}

double two_sided_p(double t, double df) {
  if (!(df > 0) || !std::isfinite(df)) throw StatisticsError("degrees of freedom must be > 0");
  if (std::isinf(t)) return 0;
  const boost::math::students_t dist(df);
  return 2 * boost::math::cdf(boost::math::complement(dist, std::abs(t)));
}

TwoGroupComparison compare_groups(std::span<const double> a, std::span<const double> b) {
  TwoGroupComparison c;
  c.a = summarize(a);
  c.b = summarize(b);
  if (c.a.n < 2 || c.b.n < 2)
    throw StatisticsError("each group needs at least two values (got " + std::to_string(c.a.n) +
                          " and " + std::to_string(c.b.n) + ")");
  const double na = double(c.a.n), nb = double(c.b.n);
  const double va = c.a.sd * c.a.sd, vb = c.b.sd * c.b.sd;
  if (va == 0 && vb == 0)
    throw StatisticsError("both groups have zero variance: the t statistic is undefined");
  const double diff = c.a.mean - c.b.mean;
  // Welch: se^2 = va/na + vb/nb; df by Welch-Satterthwaite.
  const double wa = va / na, wb = vb / nb;
  c.welch.t = diff / std::sqrt(wa + wb);
  c.welch.df = (wa + wb) * (wa + wb) / (wa * wa / (na - 1) + wb * wb / (nb - 1));
  c.welch.p = two_sided_p(c.welch.t, c.welch.df);
  // Student: pooled variance over na + nb - 2 degrees of freedom.
  const double pooled = ((na - 1) * va + (nb - 1) * vb) / (na + nb - 2);
  c.student.df = na + nb - 2;
  c.student.t = diff / std::sqrt(pooled * (1 / na + 1 / nb));
  c.student.p = two_sided_p(c.student.t, c.student.df);
  c.cohen_d = diff / std::sqrt(pooled);
  return c;
}

}  // namespace imasim::metrics
