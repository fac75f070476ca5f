// Two-group statistics (metrics/statistics.hpp): the paper's Table 1 gives the means and SDs it
// prints and p < 0.001; the t distribution's p-values match closed forms (1, 2 and 3 degrees of
// freedom); Welch and Student differ as they should when the variances and sizes differ.
#include "metrics/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace imasim::metrics {
namespace {

const std::vector<double> kDynamic = {0.583, 0.621, 0.545, 0.602, 0.568,
                                      0.634, 0.592, 0.551, 0.615, 0.577};
const std::vector<double> kStatic = {0.247, 0.268, 0.221, 0.285, 0.238,
                                     0.276, 0.212, 0.257, 0.228, 0.243};

TEST(Statistics, TheSaiTableOfThePaper) {
  const TwoGroupComparison c = compare_groups(kDynamic, kStatic);
  // As printed: 0.589 +- 0.029 and 0.248 +- 0.024 (three decimals).
  EXPECT_NEAR(c.a.mean, 0.589, 0.0005 + 1e-12);
  EXPECT_NEAR(c.a.sd, 0.029, 0.0007);  // 0.0296 by the sample SD: the paper truncates
  EXPECT_NEAR(c.b.mean, 0.248, 0.0005 + 1e-12);
  EXPECT_NEAR(c.b.sd, 0.024, 0.0005);
  EXPECT_LT(c.welch.p, 0.001);
  EXPECT_LT(c.student.p, 0.001);
  // By hand: means 0.5888 and 0.2475, sample SDs 0.0296341 and 0.0239965, equal sizes, so
  // Welch's t equals Student's; df 17.254 (Welch) and 18.
  EXPECT_NEAR(c.a.mean, 0.5888, 1e-12);
  EXPECT_NEAR(c.b.mean, 0.2475, 1e-12);
  EXPECT_NEAR(c.a.sd, 0.0296340645, 1e-9);
  EXPECT_NEAR(c.b.sd, 0.0239965275, 1e-9);
  EXPECT_NEAR(c.welch.t, 28.3043004509, 1e-8);
  EXPECT_NEAR(c.student.t, c.welch.t, 1e-9);
  EXPECT_NEAR(c.welch.df, 17.2539678895, 1e-8);
  EXPECT_EQ(c.student.df, 18);
  EXPECT_NEAR(c.cohen_d, 12.6580679728, 1e-8);
  EXPECT_GT(c.welch.p, 0);  // tiny, not zero
}

TEST(Statistics, PValuesMatchTheClosedFormsOfTheTDistribution) {
  for (const double t : {0.0, 0.3, 1.0, 2.5, 7.0, -1.7}) {
    const double a = std::abs(t);
    EXPECT_NEAR(two_sided_p(t, 1), 1 - 2 / std::numbers::pi * std::atan(a), 1e-12) << t;
    EXPECT_NEAR(two_sided_p(t, 2), 1 - a / std::sqrt(t * t + 2), 1e-12) << t;
    const double u = a / std::sqrt(3.0);
    const double cdf3 = 0.5 + (u / (1 + u * u) + std::atan(u)) / std::numbers::pi;
    EXPECT_NEAR(two_sided_p(t, 3), 2 * (1 - cdf3), 1e-12) << t;
  }
  EXPECT_EQ(two_sided_p(INFINITY, 5), 0);
  EXPECT_THROW(two_sided_p(1, 0), StatisticsError);
}

TEST(Statistics, WelchAndStudentDifferWithUnequalGroups) {
  const std::vector<double> a = {1, 2, 3, 4, 5, 6, 7, 8};  // mean 4.5, variance 6
  const std::vector<double> b = {3, 5};                    // mean 4, variance 2
  const TwoGroupComparison c = compare_groups(a, b);
  // Welch: se^2 = 6/8 + 2/2 = 1.75; df = 1.75^2 / (0.75^2/7 + 1^2/1) = 2.83.
  EXPECT_NEAR(c.welch.t, 0.5 / std::sqrt(1.75), 1e-12);
  EXPECT_NEAR(c.welch.df, 1.75 * 1.75 / (0.75 * 0.75 / 7 + 1), 1e-12);
  // Student: pooled variance (7*6 + 1*2) / 8 = 5.5, se^2 = 5.5 (1/8 + 1/2).
  EXPECT_NEAR(c.student.t, 0.5 / std::sqrt(5.5 * 0.625), 1e-12);
  EXPECT_EQ(c.student.df, 8);
  EXPECT_NEAR(c.cohen_d, 0.5 / std::sqrt(5.5), 1e-12);
  // Two-sided p by numerical integration of the t density (Simpson, 20,000 intervals).
  EXPECT_NEAR(c.welch.p, 0.7319697, 1e-6);
  EXPECT_NEAR(c.student.p, 0.7942321, 1e-6);
  // Swapping the groups flips the signs, not the p-values.
  const TwoGroupComparison s = compare_groups(b, a);
  EXPECT_NEAR(s.welch.t, -c.welch.t, 1e-12);
  EXPECT_NEAR(s.welch.p, c.welch.p, 1e-12);
  EXPECT_NEAR(s.cohen_d, -c.cohen_d, 1e-12);
}

TEST(Statistics, UndefinedComparisonsAreRefused) {
  const std::vector<double> one = {1.0}, flat = {2.0, 2.0, 2.0}, flat2 = {3.0, 3.0};
  const std::vector<double> nan = {1.0, NAN};
  EXPECT_THROW(compare_groups(one, kStatic), StatisticsError);
  EXPECT_THROW(compare_groups(flat, flat2), StatisticsError);
  EXPECT_THROW(compare_groups(nan, kStatic), StatisticsError);
  EXPECT_NO_THROW(compare_groups(flat, kStatic));  // one group's variance is enough
}

}  // namespace
}  // namespace imasim::metrics
