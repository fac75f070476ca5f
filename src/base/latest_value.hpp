#pragma once
// The newest value from one producer thread to one consumer thread, without locks or waiting (a
// triple buffer): the physics step hands its local model to the 1 kHz haptic loop, its frame to
// the drawing thread and its numbers to the panels; a device's servo thread hands its stylus to
// the loop. Neither side ever waits on the other. Each side owns one slot; the third is
// exchanged through one atomic index, whose "fresh" bit says the producer has published since
// the consumer last took it.
//
// By value (publish(value), read(out)) for small values, or in place (fill back(), then
// publish(); latest()) for a frame of megabytes: its vectors keep their capacity from fill to
// fill, so filling allocates nothing once they have grown.
#include <array>
#include <atomic>
#include <cstdint>

namespace imasim::base {

template <class T>
class LatestValue {
 public:
  // Producer thread only: the slot to fill, then publish() it; or publish a copy of `value`.
  T& back() { return slots_[back_]; }
  void publish() { back_ = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel) & kIndex; }
  void publish(const T& value) {
    back() = value;
    publish();
  }

  // Consumer thread only: the newest published value, or null before the first. It stays valid
  // (and unchanged) until the next call. `fresh` says whether it is new since that call.
  const T* latest(bool* fresh = nullptr) {
    const bool is_new = middle_.load(std::memory_order_acquire) & kFresh;
    if (is_new) {
      front_ = middle_.exchange(front_, std::memory_order_acq_rel) & kIndex;
      has_value_ = true;
    }
    if (fresh) *fresh = is_new;
    return has_value_ ? &slots_[front_] : nullptr;
  }
  // Consumer thread only: the newest published value into `out`; false until one is published.
  bool read(T& out) {
    const T* value = latest();
    if (!value) return false;
    out = *value;
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

}  // namespace imasim::base
