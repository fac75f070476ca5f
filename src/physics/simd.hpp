#pragma once
// A fixed-width batch of scalars as a GCC/Clang vector extension: element-wise arithmetic and
// comparisons compile to the target's SIMD instructions (AVX2 here; pairs of 128-bit registers
// or scalar code elsewhere). 32 bytes wide: 8 floats or 4 doubles.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <utility>

namespace imasim::physics::simd {

inline constexpr std::size_t kBytes = 32;

template <class S>
struct Batch;

template <>
struct Batch<float> {
  typedef float type __attribute__((vector_size(kBytes)));
  typedef int mask __attribute__((vector_size(kBytes)));
};

template <>
struct Batch<double> {
  typedef double type __attribute__((vector_size(kBytes)));
  typedef long long mask __attribute__((vector_size(kBytes)));
};

template <class S>
using V = typename Batch<S>::type;
template <class S>
using M = typename Batch<S>::mask;
template <class S>
inline constexpr std::size_t kLanes = kBytes / sizeof(S);

template <class S>
inline V<S> splat(S s) {
  return V<S>{} + s;
}

// kLanes<S> values from memory (any alignment).
template <class S>
inline V<S> load(const S* p) {
  V<S> v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// The batch whose lane k is f(k), built in registers. Scalars stored to an array and loaded as
// one batch make the load wait for the narrow stores (store-to-load forwarding cannot merge
// them): XSPH's kernels took 15 % less time this way (docs/PERFORMANCE.md).
template <class S, class F>
inline V<S> lanes(const F& f) {
  return [&]<std::size_t... K>(std::index_sequence<K...>) {
    return V<S>{f(K)...};
  }
  (std::make_index_sequence<kLanes<S>>{});
}

template <class S>
inline V<S> sqrt(V<S> x) {
  for (std::size_t k = 0; k < kLanes<S>; ++k)
    x[k] = std::sqrt(x[k]);
  return x;
}

template <class S>
inline V<S> abs(V<S> x) {
  return x < 0 ? -x : x;
}

// A 3-vector of batches: lane k holds the k-th row's vector.
template <class S>
struct V3 {
  V<S> x, y, z;
  friend V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend V3 operator*(V<S> s, const V3& a) { return {s * a.x, s * a.y, s * a.z}; }
};

template <class S>
inline V<S> dot(const V3<S>& a, const V3<S>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <class S>
inline V3<S> cross(const V3<S>& a, const V3<S>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace imasim::physics::simd
