#pragma once
// The newest frame from the physics thread to the drawing thread without locks or copies: a
// triple buffer like haptics::LatestValue, but each side fills or reads its slot in place (a
// RenderFrame is megabytes; its vectors keep their capacity from frame to frame, so filling
// allocates nothing once they have grown). The drawing thread never waits for physics and
// physics never waits for drawing.
#include <array>
#include <atomic>
#include <cstdint>

namespace imasim::ui {

template <class T>
class TripleBuffer {
 public:
  // Producer thread only: the slot to fill, then publish() it.
  T& back() { return slots_[back_]; }
  void publish() { back_ = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel) & kIndex; }

  // Consumer thread only: the newest published value, or null before the first. It stays
  // valid (and unchanged) until the next call. `fresh` says whether it is new since that call.
  const T* latest(bool* fresh = nullptr) {
    const bool is_new = middle_.load(std::memory_order_acquire) & kFresh;
    if (is_new) {
      front_ = middle_.exchange(front_, std::memory_order_acq_rel) & kIndex;
      has_value_ = true;
    }
    if (fresh) *fresh = is_new;
    return has_value_ ? &slots_[front_] : nullptr;
  }

 private:
  static constexpr std::uint8_t kIndex = 3, kFresh = 4;
  std::array<T, 3> slots_{};
  std::atomic<std::uint8_t> middle_{1};
  std::uint8_t back_ = 0;
  std::uint8_t front_ = 2;
  bool has_value_ = false;
};

}  // namespace imasim::ui
