// The study's statistics and report writer (src/report/) on synthetic trials: the paper's
// Table 1 as the hook's SAI gives 0.589 ± 0.030 and 0.248 ± 0.024, the tests and the
// representative trials; the page is self-contained with the heat maps embedded; results.json
// and trials.csv hold every trial; a side file's scores read back, and a malformed one is refused
// naming the file and the key.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "report/study_files.hpp"
#include "report/study_html.hpp"
#include "report/study_summary.hpp"
#include "report/text_format.hpp"
#include "study_fixtures.hpp"

namespace imasim::report {
namespace {

using test::table1_info;
using test::table1_trials;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count_of(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
    ++n;
  return n;
}

TEST(StudyText, RoundsAsPrintedByHand) {
  EXPECT_EQ(fixed(0.2475, 3), "0.248");  // printf would print the binary 0.24749... as 0.247
  EXPECT_EQ(fixed(0.5888, 3), "0.589");
  EXPECT_EQ(fixed(0.0296340645, 3), "0.030");
  EXPECT_EQ(fixed(-0.0001, 3), "0.000");
  EXPECT_EQ(fixed(-1.25, 1), "-1.3");
  EXPECT_EQ(fixed(NAN, 2), "-");
  EXPECT_EQ(mean_sd(0.5888, 0.0296, 3), "0.589 ± 0.030");
  EXPECT_EQ(p_text(0.00002), "p < 0.001");
  EXPECT_EQ(p_text(0.0342), "p = 0.034");
  EXPECT_EQ(effect_size_words(0.1), "negligible");
  EXPECT_EQ(effect_size_words(-0.6), "medium");
  EXPECT_EQ(effect_size_words(12.66), "huge");
  EXPECT_EQ(clock_text(65), "1:05");
  EXPECT_EQ(clock_text(3725), "1:02:05");
}

TEST(StudyText, Base64AndEscapes) {
  // RFC 4648's test vectors.
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
  EXPECT_EQ(html_escape("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
}

TEST(StudySummary, TheSaiTableOfThePaper) {
  const StudySummary s = summarize_study({"dynamic", "static"}, table1_trials());
  EXPECT_EQ(s.trials_ok, 20u);
  EXPECT_EQ(s.trials_failed, 0u);
  const SaiComparison& hook = headline_sai(s);
  EXPECT_EQ(hook.instrument, "hook");
  ASSERT_EQ(hook.groups.size(), 2u);
  EXPECT_NEAR(hook.groups[0].summary.mean, 0.5888, 1e-12);
  EXPECT_NEAR(hook.groups[0].summary.sd, 0.0296340645, 1e-9);
  EXPECT_NEAR(hook.groups[1].summary.mean, 0.2475, 1e-12);
  EXPECT_NEAR(hook.groups[1].summary.sd, 0.0239965275, 1e-9);
  ASSERT_TRUE(hook.test.has_value());
  EXPECT_NEAR(hook.test->welch.t, 28.3043004509, 1e-8);
  EXPECT_NEAR(hook.test->welch.df, 17.2539678895, 1e-8);
  EXPECT_LT(hook.test->welch.p, 0.001);
  EXPECT_NEAR(hook.test->cohen_d, 12.6580679728, 1e-8);
  // Nearest the means: 0.592 (trial 7) of 0.5888 and 0.247 (trial 1) of 0.2475.
  EXPECT_EQ(hook.groups[0].representative_trial, 7);
  EXPECT_EQ(hook.groups[1].representative_trial, 1);
  // The forceps (half the hook's values in the fixture): half the means, the same t.
  const SaiComparison& forceps = s.sai[0];
  EXPECT_EQ(forceps.instrument, "forceps");
  EXPECT_NEAR(forceps.groups[0].summary.mean, 0.2944, 1e-12);
  EXPECT_NEAR(forceps.test->welch.t, hook.test->welch.t, 1e-9);
  // Metrics: 100 + k s has mean 105.5 and SD sqrt(110/12); heart contacts pass in 3 of 10.
  ASSERT_EQ(s.metrics.size(), 2u);
  EXPECT_EQ(s.metrics[0].name, "time_to_complete_s");
  EXPECT_NEAR(s.metrics[0].groups[1].summary.mean, 105.5, 1e-12);
  EXPECT_NEAR(s.metrics[0].groups[1].summary.sd, std::sqrt(110.0 / 12), 1e-12);
  EXPECT_EQ(s.metrics[0].groups[0].passed, 10u);
  EXPECT_EQ(s.metrics[1].groups[0].passed, 3u);
}

TEST(StudySummary, FailedTrialsAreLeftOutAndTooFewGiveNoTest) {
  std::vector<TrialResult> trials = table1_trials();
  for (TrialResult& t : trials)
    if (t.mode == "static" && t.trial > 1) {
      t.ok = false;
      t.reason = "timed out";
    }
  const StudySummary s = summarize_study({"dynamic", "static"}, trials);
  EXPECT_EQ(s.trials_ok, 11u);
  EXPECT_EQ(s.trials_failed, 9u);
  const SaiComparison& hook = headline_sai(s);
  EXPECT_EQ(hook.groups[1].values.size(), 1u);
  EXPECT_FALSE(hook.test.has_value());
  EXPECT_NE(hook.test_problem.find("at least two"), std::string::npos) << hook.test_problem;
}

TEST(StudyReport, ThePageShowsTable1TheTestsAndTheEmbeddedHeatMaps) {
  const std::string png = ::testing::TempDir() + "imasim_study_heat_map.png";
  test::write_heat_map_png(png);
  std::vector<TrialResult> trials = table1_trials(png);
  trials.push_back(test::synthetic_trial("static", 11, 0));
  trials.back().ok = false;
  trials.back().reason = "timed out after 20 s of wall-clock time (killed)";
  trials.back().heat_maps.clear();
  StudyInfo info = table1_info();
  info.trials_per_mode = 11;
  for (TrialResult& t : trials)
    t.views = {{"start", png}, {"end", png}};
  const StudySummary s = summarize_study(info.modes, trials);
  const std::string page = study_report_html(info, trials, s, {{"A plot", png}});
  // The representative trials' scenes, drawn offscreen, are shown with their heat maps.
  EXPECT_NE(page.find("the scene after the harvest (drawn offscreen)"), std::string::npos);
  EXPECT_NE(page.find("the scene before (drawn offscreen)"), std::string::npos);

  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  // The failed trial is left out of the means: Table 1's values stand.
  EXPECT_NE(page.find("0.589 ± 0.030"), std::string::npos);
  EXPECT_NE(page.find("0.248 ± 0.024"), std::string::npos);
  for (const double v : test::kTable1Dynamic)
    EXPECT_NE(page.find("<td>" + fixed(v, 3) + "</td>"), std::string::npos) << v;
  EXPECT_NE(page.find("t = 28.30 with 17.3 degrees of freedom, p &lt; 0.001"), std::string::npos)
      << "the test in words";
  EXPECT_NE(page.find("Cohen's d is 12.66"), std::string::npos);
  EXPECT_NE(page.find("statistically significant at the 5 % level"), std::string::npos);
  EXPECT_NE(page.find("not a model of surgeons"), std::string::npos);
  EXPECT_NE(page.find("timed out after 20 s of wall-clock time (killed)"), std::string::npos);
  // Representative trials' heat maps (2 groups x 2 instruments), their scenes (2 x 2) and the
  // extra figure, embedded.
  const std::string data = "src=\"data:image/png;base64," + base64(slurp(png)) + "\"";
  EXPECT_EQ(count_of(page, data), 9u);
  EXPECT_NE(page.find("dynamic, trial 7: hook (SAI 0.592)"), std::string::npos);
  EXPECT_NE(page.find("static, trial 1: hook (SAI 0.247)"), std::string::npos);
  // Self-contained: nothing fetched.
  for (const char* outside : {"http:", "https:", "<link", "@import", "url(", "src=\"/", "<iframe"})
    EXPECT_EQ(page.find(outside), std::string::npos) << outside;
  // The metrics per group with pass rates.
  EXPECT_NE(page.find("105.5 ± 3.028"), std::string::npos);
  EXPECT_NE(page.find("3 / 10"), std::string::npos);
}

TEST(StudyReport, AMissingImageIsNamedInThePage) {
  std::vector<TrialResult> trials = table1_trials("/nonexistent/heat.png");
  const StudySummary s = summarize_study({"dynamic", "static"}, trials);
  const std::string page = study_report_html(table1_info(), trials, s);
  EXPECT_NE(page.find("Image not available: cannot open the image /nonexistent/heat.png"),
            std::string::npos);
  EXPECT_EQ(page.find("<img"), std::string::npos);
}

TEST(StudyReport, TheTraineeHistoryTableIsShownEscaped) {
  std::vector<TrialResult> trials = table1_trials();
  const StudySummary s = summarize_study({"dynamic", "static"}, trials);
  const ReportTable history{"Table 5. The sessions of 'A & B'",
                            {"session", "SAI hook"},
                            {{"1", "0.583"}, {"2", "<0.621>"}}};
  const std::string page = study_report_html(table1_info(), trials, s, {}, {history});
  EXPECT_NE(page.find("<h2>Trainee history</h2>"), std::string::npos);
  EXPECT_NE(page.find("<caption>Table 5. The sessions of &#39;A &amp; B&#39;</caption>"),
            std::string::npos)
      << page.substr(page.find("Trainee history"), 300);
  EXPECT_NE(page.find("<th>SAI hook</th>"), std::string::npos);
  EXPECT_NE(page.find("<td>&lt;0.621&gt;</td>"), std::string::npos);
  // Without records there is no history section.
  EXPECT_EQ(study_report_html(table1_info(), trials, s).find("Trainee history"), std::string::npos);
}

TEST(StudyFiles, ResultsJsonAndTrialsCsvHoldEveryTrial) {
  std::vector<TrialResult> trials = table1_trials();
  trials[12].ok = false;
  trials[12].reason = "exited with status 3, a refused step";
  trials[12].sai.clear();  // a failed trial has no scores
  trials[12].metrics.clear();
  const StudySummary s = summarize_study({"dynamic", "static"}, trials);
  const std::string dir = ::testing::TempDir();
  const StudyFiles files = write_study_files(dir, table1_info(), trials, s);
  const nlohmann::json j = nlohmann::json::parse(slurp(files.results_json));
  EXPECT_EQ(j["format"], "imasim study v1");
  for (const char* key :
       {"study", "headline", "sai", "metrics", "trials_ok", "trials_failed", "trials", "files"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["study"]["modes"], nlohmann::json({"dynamic", "static"}));
  EXPECT_EQ(j["headline"]["instrument"], "hook");
  EXPECT_EQ(j["trials_failed"], 1);
  EXPECT_EQ(j["sai"]["hook"]["groups"]["dynamic"]["n"], 10);
  EXPECT_EQ(j["sai"]["hook"]["groups"]["static"]["n"], 9);
  EXPECT_NEAR(j["sai"]["hook"]["groups"]["dynamic"]["mean"].get<double>(), 0.5888, 1e-12);
  EXPECT_LT(j["sai"]["hook"]["test"]["p_welch"].get<double>(), 0.001);
  EXPECT_EQ(j["sai"]["hook"]["test"]["a"], "dynamic");
  EXPECT_EQ(j["metrics"][1]["name"], "heart_contacts");
  EXPECT_NEAR(j["metrics"][1]["groups"]["dynamic"]["pass_rate"].get<double>(), 0.3, 1e-12);
  ASSERT_EQ(j["trials"].size(), 20u);
  EXPECT_EQ(j["trials"][12]["status"], "failed");
  EXPECT_EQ(j["trials"][0]["sai"]["hook"]["sai"], 0.583);
  EXPECT_EQ(j["trials"][0]["metrics"]["time_to_complete_s"]["value"], 101);

  const std::string csv = slurp(files.trials_csv);
  std::stringstream lines(csv);
  std::string header, line;
  std::getline(lines, header);
  EXPECT_EQ(header,
            "mode,trial,patient_seed,operator_seed,status,reason,wall_s,sai_forceps,sai_hook,"
            "time_to_complete_s,heart_contacts");
  int rows = 0;
  while (std::getline(lines, line)) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 10) << line;
    EXPECT_EQ(line.find('"'), std::string::npos) << line;
  }
  EXPECT_EQ(rows, 20);
  // The failed trial: its reason with the comma replaced, no scores.
  EXPECT_NE(csv.find("static,3,1003,2003,failed,exited with status 3; a refused step,12.5,,,,\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("dynamic,1,1001,2001,ok,,12.5,0.2915,0.583,101,1\n"), std::string::npos);
  EXPECT_NE(slurp(files.report_html).find("0.589 ± 0.030"), std::string::npos);
}

TEST(TrialScores, ASideFilesScoresReadBack) {
  nlohmann::json side;
  side["run"]["scores"]["sai"]["radius_m"] = 0.002;
  for (const char* tool : {"forceps", "hook"})
    side["run"]["scores"]["sai"][tool] = {
        {"sai", 0.5}, {"samples", 61}, {"mean_distance_m", 0.003}, {"heart_side_fraction", 0.25}};
  side["run"]["scores"]["metrics"] = nlohmann::json::array({{{"name", "grasps"},
                                                             {"value", 2},
                                                             {"unit", "1"},
                                                             {"threshold", 0},
                                                             {"better", "higher"},
                                                             {"pass", true},
                                                             {"meaning", "grasp events"}}});
  side["run"]["scores"]["heat_maps"] = {{"hook", "/abs/hook.png"}};
  TrialResult t;
  read_trial_scores(side.dump(), "dir/static-01.json", t);
  EXPECT_EQ(t.sai.at("hook").samples, 61u);
  EXPECT_EQ(t.sai.at("forceps").heart_side_fraction, 0.25);
  ASSERT_EQ(t.metrics.size(), 1u);
  EXPECT_TRUE(t.metrics[0].higher_is_better);
  EXPECT_EQ(t.metrics[0].value, 2);
  EXPECT_EQ(t.heat_maps.at("hook"), "/abs/hook.png");
  EXPECT_TRUE(t.views.empty()) << "a recording made without OpenGL has no pictures";
  side["run"]["views"] = {{"start", "/abs/start.png"}, {"end", "/abs/end.png"}};
  read_trial_scores(side.dump(), "dir/static-01.json", t);
  EXPECT_EQ(t.views.at("end"), "/abs/end.png");
  EXPECT_EQ(t.views.size(), 2u);

  nlohmann::json broken = side;
  broken["run"]["views"]["end"] = 3;
  EXPECT_THROW(read_trial_scores(broken.dump(), "x.json", t), StudyDataError);
  broken = side;
  broken["run"]["scores"]["sai"]["hook"].erase("samples");
  try {
    read_trial_scores(broken.dump(), "dir/static-01.json", t);
    FAIL() << "accepted a side file without the hook's samples";
  } catch (const StudyDataError& e) {
    EXPECT_STREQ(e.what(), "dir/static-01.json: key \"run.scores.sai.hook.samples\": missing");
  }
  broken = side;
  broken["run"]["scores"]["metrics"][0]["pass"] = "yes";
  EXPECT_THROW(read_trial_scores(broken.dump(), "x.json", t), StudyDataError);
  EXPECT_THROW(read_trial_scores("{\"run\": ", "x.json", t), StudyDataError);
}

}  // namespace
}  // namespace imasim::report
