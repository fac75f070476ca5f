#pragma once
// Scalar and small fixed-size vector types used everywhere. SI units throughout.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace imasim {

// The solver's scalar. float by default: on the cloth benchmark it runs 2.1x faster than double
// for the same physics (docs/PERFORMANCE.md, "float or double"); IMASIM_REAL_DOUBLE builds the
// double variant for comparison. Set-up quantities (rest angles) are computed in double.
#ifdef IMASIM_REAL_DOUBLE
using Real = double;
#else
using Real = float;
#endif

using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;

}  // namespace imasim
