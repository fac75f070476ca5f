#pragma once
// The per-trial SAI of each group as an inline SVG dot plot (one dot a trial, the group's mean as
// a bar and its SD as whiskers): drawn in the page, so the report needs no image for it.
#include <string>

#include "report/study_summary.hpp"

namespace imasim::report {

std::string sai_chart_svg(const SaiComparison& comparison);

// The colour the report gives a mode (dynamic: orange, static: blue, others from a list).
std::string mode_colour(const std::string& mode, std::size_t index);

}  // namespace imasim::report
