#include "devices/tremor_filter.hpp"

#include <cmath>
#include <complex>
#include <numbers>

namespace imasim::devices {

TremorFilter::TremorFilter(const TremorFilterParams& p) {
  enabled_ = p.cutoff_hz > 0 && p.sample_hz > 2 * p.cutoff_hz;
  if (!enabled_) return;
  // H(s) = 1 / (s^2 + sqrt(2) s + 1) at s = (1/K) (z - 1)/(z + 1), K = tan(pi fc / fs).
  const Real k = std::tan(std::numbers::pi_v<Real> * p.cutoff_hz / p.sample_hz);
  const Real q = std::numbers::sqrt2_v<Real>;
  const Real norm = 1 / (1 + q * k + k * k);
  b0_ = k * k * norm;
  b1_ = 2 * b0_;
  b2_ = b0_;
  a1_ = 2 * (k * k - 1) * norm;
  a2_ = (1 - q * k + k * k) * norm;
  sample_hz_ = p.sample_hz;
}

Vec3 TremorFilter::filter(const Vec3& x) {
  if (!enabled_) return x;
  if (!started_ || !x.allFinite()) {
    // At rest at x (a non-finite sample restarts rather than poisoning the state). The filter
    // runs on the motion since then, so a hand held still comes out exactly where it is.
    origin_ = x;
    x1_ = x2_ = y1_ = y2_ = Vec3::Zero();
    started_ = x.allFinite();
    return x;
  }
  const Vec3 u = x - origin_;
  const Vec3 y = b0_ * u + b1_ * x1_ + b2_ * x2_ - a1_ * y1_ - a2_ * y2_;
  x2_ = x1_, x1_ = u, y2_ = y1_, y1_ = y;
  return origin_ + y;
}

Real TremorFilter::gain_at(Real f) const {
  if (!enabled_) return 1;
  const std::complex<Real> z = std::polar(Real(1), 2 * std::numbers::pi_v<Real> * f / sample_hz_);
  const std::complex<Real> zi = Real(1) / z;
  return std::abs((b0_ + b1_ * zi + b2_ * zi * zi) / (Real(1) + a1_ * zi + a2_ * zi * zi));
}

}  // namespace imasim::devices
