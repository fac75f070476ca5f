#pragma once
// Scalar and small fixed-size vector types used everywhere. SI units throughout.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace imasim {

// The solver's scalar. double by default: see docs/PERFORMANCE.md ("float or double") for the
// measurement behind the choice; IMASIM_REAL_FLOAT builds the float variant for comparison.
#ifdef IMASIM_REAL_FLOAT
using Real = float;
#else
using Real = double;
#endif

using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;

}  // namespace imasim
