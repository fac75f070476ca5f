// Proficiency thresholds from a file (metrics/threshold_file.hpp): names checked against the
// metrics, values finite, every error with the file and line.
#include "metrics/threshold_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "metrics/trainee_metrics.hpp"

namespace imasim::metrics {
namespace {

TEST(ThresholdFile, NamesAndValuesReplaceTheDefaults) {
  const auto t = parse_threshold_file(
      "{\n  \"time_to_complete_s\": 300,\n  \"heart_contacts\": 1\n}\n", "t.json");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t.at("time_to_complete_s"), 300);
  EXPECT_EQ(t.at("heart_contacts"), 1);
  EXPECT_TRUE(parse_threshold_file("{}", "empty.json").empty());
  // Every metric can be named.
  for (const std::string& name : trainee_metric_names())
    EXPECT_EQ(parse_threshold_file("{\"" + name + "\": 2.5}", "one.json").at(name), 2.5);
}

TEST(ThresholdFile, ErrorsNameTheFileAndLine) {
  struct Case {
    std::string text, message;
  };
  const Case cases[] = {
      {"{\n  \"time_to_complete\": 300\n}",
       "t.json:2: 'time_to_complete' is no metric; did you "
       "mean 'time_to_complete_s'?"},
      {"{\n\n  \"idle_time_s\": \"long\"\n}",
       "t.json:3: 'idle_time_s': expected a finite number, got \"long\""},
      {"{\n  \"idle_time_s\": 1,\n  oops\n}", "t.json:3: not JSON"},
      {"[1, 2]", "t.json:1: expected a JSON object"},
      {"", "t.json:1: not JSON"},
  };
  for (const Case& c : cases) {
    try {
      parse_threshold_file(c.text, "t.json");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const ThresholdFileError& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos)
          << e.what() << "\n  expected: " << c.message;
    }
  }
  EXPECT_THROW(load_threshold_file("/nonexistent/thresholds.json"), ThresholdFileError);
}

}  // namespace
}  // namespace imasim::metrics
