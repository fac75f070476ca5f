#include <string_view>

#include "math/text_file.hpp"
#include "report/study_html_parts.hpp"
#include "report/text_format.hpp"

namespace imasim::report::html {

namespace {

// A heat map or a plot is a few hundred KiB; far more is no figure.
constexpr std::uint64_t kMaxImageBytes = 32ull << 20;
constexpr std::string_view kPngSignature = "\x89PNG\r\n\x1a\n";

}  // namespace

std::string figure(const std::string& png_path, const std::string& caption) {
  const TextFile file = read_text_file(png_path, kMaxImageBytes, "image " + png_path);
  std::string problem = file.error;
  if (problem.empty() && !file.text.starts_with(kPngSignature))
    problem = "the image " + png_path + " is not a PNG file";
  if (!problem.empty())
    return "<figure class=\"missing\"><p>Image not available: " + html_escape(problem) +
           "</p><figcaption>" + html_escape(caption) + "</figcaption></figure>";
  return "<figure><img alt=\"" + html_escape(caption) + "\" src=\"data:image/png;base64," +
         base64(file.text) + "\"><figcaption>" + html_escape(caption) + "</figcaption></figure>";
}

std::string heat_maps(const std::vector<TrialResult>& trials, const StudySummary& summary) {
  const SaiComparison& headline = headline_sai(summary);
  std::string h;
  for (const SaiGroup& g : headline.groups) {
    h += "<h3>" + html_escape(g.mode) + ": " + html_escape(mode_phrase(g.mode)) + "</h3>";
    const TrialResult* t = find_trial(trials, g.mode, g.representative_trial);
    if (t == nullptr) {
      h += "<p class=\"none\">No finished trial in this group.</p>";
      continue;
    }
    const std::string why = "trial " + std::to_string(t->trial) + ", whose " +
                            std::string(kHeadlineInstrument) + " SAI " +
                            fixed(t->sai.at(kHeadlineInstrument).sai, 3) +
                            " is the nearest to the group's mean " + fixed(g.summary.mean, 3);
    if (t->heat_maps.empty()) {
      h += "<p class=\"none\">The representative " + html_escape(why) +
           ", has no heat maps (they are drawn when the run's plotting step is built).</p>";
      continue;
    }
    h += "<p>The representative " + html_escape(why) + ".</p><div class=\"figures\">";
    for (const char* tool : kInstruments) {
      if (!t->heat_maps.contains(tool)) continue;
      const std::string score =
          t->sai.contains(tool) ? " (SAI " + fixed(t->sai.at(tool).sai, 3) + ")" : "";
      const std::string caption =
          g.mode + ", trial " + std::to_string(t->trial) + ": " + tool + score;
      h += figure(t->heat_maps.at(tool), caption);
    }
    h += "</div>";
    if (!t->views.empty()) {
      h += "<div class=\"figures\">";
      for (const auto& [when, png] :
           {std::pair<const char*, const char*>{"start", "before"}, {"end", "after the harvest"}}) {
        if (!t->views.contains(when)) continue;
        h += figure(t->views.at(when), g.mode + ", trial " + std::to_string(t->trial) +
                                           ": the scene " + png + " (drawn offscreen)");
      }
      h += "</div>";
    }
  }
  return h;
}

}  // namespace imasim::report::html
