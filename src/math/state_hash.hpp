#pragma once
// A 64-bit FNV-1a hash over raw bytes: the "state hash" that determinism tests and replay
// compare. Bit-exact, so two states hash equal only if every byte is equal.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace imasim {

inline constexpr std::uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ull;

std::uint64_t hash_bytes(const void* data, std::size_t size, std::uint64_t seed = kFnvOffsetBasis);

template <class T>
std::uint64_t hash_span(std::span<const T> values, std::uint64_t seed = kFnvOffsetBasis) {
  return hash_bytes(values.data(), values.size_bytes(), seed);
}

// 16 lower-case hex digits.
std::string to_hex(std::uint64_t value);

}  // namespace imasim
