#pragma once
// The study's report as one self-contained HTML page: inline CSS, the images embedded as base64
// data URIs, no network, no external fonts; a small inline script only marks the page ready
// (body data-ready="yes") once every image has loaded with a size, for the browser test.
#include <string>
#include <vector>

#include "report/study_data.hpp"
#include "report/study_summary.hpp"

namespace imasim::report {

// The whole page. Images that cannot be read (missing, not PNG, too large) are named in the page
// instead.
std::string study_report_html(const StudyInfo& info, const std::vector<TrialResult>& trials,
                              const StudySummary& summary,
                              const std::vector<ReportImage>& images = {},
                              const std::vector<ReportTable>& tables = {});

}  // namespace imasim::report
