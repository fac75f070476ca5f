#pragma once
// The newest value from one producer thread to one consumer thread, without locks or waiting
// (a triple buffer): the physics step publishes its local model at 200 Hz, the 1 kHz haptic loop
// reads the newest one and never waits on physics (SPEC's threads). Each side owns one slot;
// the third is exchanged through one atomic index, whose "fresh" bit says the producer has
// published since the consumer last took it.
#include <array>
#include <atomic>
#include <cstdint>

namespace imasim::haptics {

template <class T>
class LatestValue {
 public:
  // Producer thread only.
  void publish(const T& value) {
    slots_[back_] = value;
    back_ = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel) & kIndex;
  }

  // Consumer thread only: the newest published value into `out`; false until one is published.
  bool read(T& out) {
    if (middle_.load(std::memory_order_acquire) & kFresh) {
      front_ = middle_.exchange(front_, std::memory_order_acq_rel) & kIndex;
      has_value_ = true;
    }
    if (!has_value_) return false;
    out = slots_[front_];
    return true;
  }

 private:
  static constexpr std::uint8_t kIndex = 3, kFresh = 4;
  std::array<T, 3> slots_{};
  std::atomic<std::uint8_t> middle_{1};
  std::uint8_t back_ = 0;   // the producer's slot
  std::uint8_t front_ = 2;  // the consumer's slot
  bool has_value_ = false;
};

}  // namespace imasim::haptics
