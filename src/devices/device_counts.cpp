#include "devices/device_counts.hpp"

#include <string_view>

namespace imasim::devices {

std::uint64_t DeviceCounts::refused_total() const {
  std::uint64_t n = 0;
  for (const std::uint64_t r : refused_by_reason)
    n += r;
  return n;
}

void DeviceCounts::add(const IgtlCounters& c) {
  for (std::size_t r = 0; r < kIgtlRefusals; ++r)
    refused_by_reason[r] += c.refused[r];
  refused_others += c.refused_others;
  for (std::size_t k = 0; k < c.named; ++k) {
    const IgtlNameRefusals& from = c.refused_names[k];
    IgtlNameRefusals* to = nullptr;
    for (std::size_t j = 0; j < named && to == nullptr; ++j)
      if (std::string_view(refused_names[j].name.data()) == std::string_view(from.name.data()))
        to = &refused_names[j];
    if (to == nullptr && named < refused_names.size()) {
      to = &refused_names[named++];
      to->name = from.name;
      to->count = 0;
    }
    if (to != nullptr)
      to->count += from.count;
    else
      refused_others += from.count;
  }
}

}  // namespace imasim::devices
