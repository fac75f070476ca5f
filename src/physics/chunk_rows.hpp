#pragma once
// Rows gathered over fixed chunks of items in parallel, then appended to one sequence in chunk
// order: the same rows in the same order as one pass over the items, on any thread count
// (the chunks do not depend on it, executor.hpp).
#include <cstddef>
#include <vector>

#include "physics/executor.hpp"

namespace imasim::physics {

template <class Row>
class ChunkRows {
 public:
  // gather(part, begin, end, rows) appends the rows of items [begin, end) to rows, a chunk's own
  // (part: executor.hpp's, for per-part scratch). Each chunk keeps room for rows_per_item rows an
  // item, so that a steady item count does not allocate.
  template <class Gather>
  void gather(const Executor& exec, std::size_t items, std::size_t chunk, std::size_t rows_per_item,
              std::vector<Row>& out, const Gather& gather) {
    const std::size_t chunks = (items + chunk - 1) / chunk;
    if (chunks_.size() < chunks) chunks_.resize(chunks);
    for (std::size_t c = 0; c < chunks; ++c) {
      chunks_[c].clear();
      chunks_[c].reserve(chunk * rows_per_item);
    }
    exec.for_chunks_in_parts(items, chunk,
                             [&](std::size_t part, std::size_t begin, std::size_t end) {
                               gather(part, begin, end, chunks_[begin / chunk]);
                             });
    for (std::size_t c = 0; c < chunks; ++c)
      out.insert(out.end(), chunks_[c].begin(), chunks_[c].end());
  }

 private:
  std::vector<std::vector<Row>> chunks_;
};

}  // namespace imasim::physics
