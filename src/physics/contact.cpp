#include "physics/contact.hpp"

namespace imasim::physics {

std::size_t ContactSet::touching(std::uint32_t first_tag, std::uint32_t end_tag) const {
  std::size_t n = 0;
  for (const ContactRow& c : rows)
    n += (c.tag >= first_tag && c.tag < end_tag && c.depth > 0) ? 1 : 0;
  return n;
}

}  // namespace imasim::physics
