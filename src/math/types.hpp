#pragma once
// Scalar and small fixed-size vector types used everywhere. SI units throughout.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace imasim {

// The solver's scalar. double by default: with the SIMD projection double meets the step-time
// targets, and float, 1.25x faster, rounds velocities v = (p - x)/h to 2.4e-5 m/s at 1 m
// (docs/PERFORMANCE.md, "float or double"). IMASIM_REAL_FLOAT builds the float variant.
#ifdef IMASIM_REAL_FLOAT
using Real = float;
#else
using Real = double;
#endif

using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;

}  // namespace imasim
