#pragma once
// Two-group statistics for the dynamic-versus-static comparison (SPEC S6, the paper's Table 1):
// mean and sample standard deviation per group, Welch's t-test (unequal variances, the
// Welch-Satterthwaite degrees of freedom) and Student's t-test (pooled variance), each with its
// two-sided p-value from the t distribution (Boost.Math), and Cohen's d (the difference of the
// means over the pooled standard deviation).
#include <span>
#include <stdexcept>

namespace imasim::metrics {

class StatisticsError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct GroupSummary {
  std::size_t n = 0;
  double mean = 0;
  double sd = 0;  // sample standard deviation (n - 1 in the denominator)
};

struct TTest {
  double t = 0;   // (mean_a - mean_b) / standard error
  double df = 0;  // degrees of freedom
  double p = 1;   // two-sided
};

struct TwoGroupComparison {
  GroupSummary a, b;
  TTest welch, student;
  double cohen_d = 0;  // (mean_a - mean_b) / pooled sd
};

// Throws StatisticsError for a value that is not finite.
GroupSummary summarize(std::span<const double> values);

// Both groups need at least two values each and not both zero variance (StatisticsError
// otherwise: a t statistic would be undefined).
TwoGroupComparison compare_groups(std::span<const double> a, std::span<const double> b);

// The two-sided p-value of a t statistic with df degrees of freedom (df > 0).
double two_sided_p(double t, double df);

}  // namespace imasim::metrics
