#pragma once
// Checks on command-line values that CLI11's own validators let through: CLI::Range passes NaN
// (every comparison with it is false), an unsigned option takes "-1" as 2^64 - 1, and an empty
// file name reads as "not given".
#include <CLI/CLI.hpp>

namespace imasim::cli {

// A finite number in [lo, hi] (NaN and infinities refused).
CLI::Validator finite_range(double lo, double hi);

// Decimal digits only (no sign), at most `max`.
CLI::Validator unsigned_at_most(std::uint64_t max);

// A non-empty value (a file name).
CLI::Validator non_empty();

// A trainee's name as the records keep it (metrics/trainee_name.hpp).
CLI::Validator trainee_name();

}  // namespace imasim::cli
