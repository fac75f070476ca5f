#include "surgery/input_script_repeat.hpp"

#include <cmath>
#include <string>

namespace imasim::surgery {
namespace {

template <class Key>
void repeat_keys(std::vector<Key>& keys, std::uint32_t times, double period) {
  const std::size_t n = keys.size();
  keys.reserve(n * times);
  for (std::uint32_t copy = 1; copy < times; ++copy) {
    for (std::size_t k = 0; k < n; ++k) {
      Key key = keys[k];
      key.time += copy * period;
      keys.push_back(key);
    }
  }
}

void repeat_track(InstrumentTrack& t, std::uint32_t times, double period) {
  repeat_keys(t.poses, times, period);
  repeat_keys(t.jaw, times, period);
  repeat_keys(t.clutch, times, period);
  repeat_keys(t.pedal, times, period);
  repeat_keys(t.power, times, period);
}

}  // namespace

InputScript repeat_input_script(const InputScript& script, std::uint32_t times, double period) {
  if (times == 0) throw InputScriptError(script.path + ": a script is played at least once");
  if (!std::isfinite(period) || period < script.end_time()) {
    throw InputScriptError(script.path + ": the repeat period (" + std::to_string(period) +
                           " s) is shorter than the script (" + std::to_string(script.end_time()) +
                           " s)");
  }
  InputScript out = script;
  repeat_track(out.left, times, period);
  repeat_track(out.right, times, period);
  repeat_keys(out.camera.optics, times, period);
  repeat_keys(out.camera.insertion, times, period);
  repeat_keys(out.camera.roll, times, period);
  return out;
}

}  // namespace imasim::surgery
