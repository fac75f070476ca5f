#include "report/study_summary.hpp"

#include <cmath>

namespace imasim::report {

namespace {

SaiGroup sai_group(const std::string& mode, const std::string& instrument,
                   const std::vector<TrialResult>& trials) {
  SaiGroup g;
  g.mode = mode;
  std::vector<int> numbers;
  for (const TrialResult& t : trials) {
    if (!t.ok || t.mode != mode || !t.sai.contains(instrument)) continue;
    g.values.push_back(t.sai.at(instrument).sai);
    numbers.push_back(t.trial);
  }
  g.summary = metrics::summarize(g.values);
  double nearest = INFINITY;
  for (std::size_t i = 0; i < g.values.size(); ++i) {
    const double gap = std::abs(g.values[i] - g.summary.mean);
    if (gap < nearest) {
      nearest = gap;
      g.representative_trial = numbers[i];
    }
  }
  return g;
}

SaiComparison compare_instrument(const std::vector<std::string>& modes,
                                 const std::string& instrument,
                                 const std::vector<TrialResult>& trials) {
  SaiComparison c;
  c.instrument = instrument;
  for (const std::string& mode : modes)
    c.groups.push_back(sai_group(mode, instrument, trials));
  if (c.groups.size() < 2) {
    c.test_problem = "one group only: nothing to compare";
    return c;
  }
  try {
    c.test = metrics::compare_groups(c.groups[0].values, c.groups[1].values);
  } catch (const metrics::StatisticsError& e) {
    c.test_problem = e.what();
  }
  return c;
}

std::vector<MetricSummary> summarize_metrics(const std::vector<std::string>& modes,
                                             const std::vector<TrialResult>& trials) {
  std::vector<MetricSummary> out;
  auto find = [&out](const std::string& name) -> MetricSummary* {
    for (MetricSummary& m : out)
      if (m.name == name) return &m;
    return nullptr;
  };
  for (const TrialResult& t : trials) {
    if (!t.ok) continue;
    for (const MetricValue& v : t.metrics) {
      if (find(v.name)) continue;
      MetricSummary m;
      m.name = v.name;
      m.unit = v.unit;
      m.threshold = v.threshold;
      m.higher_is_better = v.higher_is_better;
      out.push_back(m);
    }
  }
  for (MetricSummary& m : out) {
    for (const std::string& mode : modes) {
      MetricGroup g;
      g.mode = mode;
      std::vector<double> values;
      for (const TrialResult& t : trials) {
        if (!t.ok || t.mode != mode) continue;
        for (const MetricValue& v : t.metrics) {
          if (v.name != m.name) continue;
          values.push_back(v.value);
          g.passed += v.pass ? 1 : 0;
        }
      }
      g.summary = metrics::summarize(values);
      m.groups.push_back(g);
    }
  }
  return out;
}

}  // namespace

StudySummary summarize_study(const std::vector<std::string>& modes,
                             const std::vector<TrialResult>& trials) {
  StudySummary s;
  for (const char* instrument : kInstruments)
    s.sai.push_back(compare_instrument(modes, instrument, trials));
  s.metrics = summarize_metrics(modes, trials);
  for (const TrialResult& t : trials)
    (t.ok ? s.trials_ok : s.trials_failed) += 1;
  return s;
}

const SaiComparison& headline_sai(const StudySummary& summary) {
  for (const SaiComparison& c : summary.sai)
    if (c.instrument == kHeadlineInstrument) return c;
  throw StudyDataError("the study summary has no SAI of the headline instrument");
}

}  // namespace imasim::report
