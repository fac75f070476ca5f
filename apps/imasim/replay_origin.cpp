#include "replay_origin.hpp"

namespace imasim::cli {

ReplayVerdict check_replay(const console::RecordedStream& stream, const std::string& path,
                           const console::StreamOrigin& now, bool anyway) {
  ReplayVerdict v;
  const std::size_t steps = stream.steps.size();
  if (steps == 0) {
    v.refused = true;
    v.lines.push_back(path + ": no steps: an empty stream replays nothing");
    return v;
  }
  std::vector<std::string> problems;
  if (!stream.head.origin) {
    v.lines.push_back(path +
                      ": note: recorded before streams carried their origin; its scene, patient, "
                      "heart and solver are not checked");
  } else {
    for (const std::string& d : console::origin_differences(*stream.head.origin, now))
      problems.push_back("recorded under another origin: " + d);
    if (!stream.head.end_steps) {
      problems.push_back("cut short after " + std::to_string(steps) +
                         " steps (no end line: the recording run stopped without closing it)");
    } else if (*stream.head.end_steps != steps) {
      problems.push_back("its end line says " + std::to_string(*stream.head.end_steps) +
                         " steps, but it holds " + std::to_string(steps));
    }
  }
  for (const std::string& p : problems)
    v.lines.push_back(path + ": " + (anyway ? "replayed anyway: " : "") + p);
  if (!problems.empty() && !anyway) {
    v.refused = true;
    v.lines.push_back(path +
                      ": not replayed (the state would not be the recorded one); "
                      "--replay-anyway plays it regardless");
  }
  return v;
}

}  // namespace imasim::cli
