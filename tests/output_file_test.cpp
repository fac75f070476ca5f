// Files written while a run goes on (metrics/output_file.hpp, metrics/event_csv.hpp).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "metrics/event_csv.hpp"
#include "metrics/output_file.hpp"

namespace imasim::metrics {
namespace {

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(OutputFile, DataReachesTheFileAtAFlushNotBefore) {
  const std::string path = ::testing::TempDir() + "imasim_output_file.txt";
  OutputFile f(path, "the test file");
  f.write("one\n");
  EXPECT_EQ(contents(path), "");
  const auto now = std::chrono::steady_clock::now();
  f.flush_if_due(now);  // not yet a second since the file was opened
  EXPECT_EQ(contents(path), "");
  f.flush_if_due(now + kFlushInterval);
  EXPECT_EQ(contents(path), "one\n");
  f.write("two\n");
  f.close();
  EXPECT_EQ(contents(path), "one\ntwo\n");
  EXPECT_FALSE(f.is_open());
}

TEST(OutputFile, AFullDiskIsReportedAtTheFlush) {
  OutputFile f("/dev/full", "the events file");
  f.write("lost\n");
  try {
    f.flush();
    FAIL() << "no error from a full disk";
  } catch (const OutputError& e) {
    EXPECT_STREQ(e.what(), "cannot write the events file /dev/full: No space left on device");
  }
}

TEST(OutputFile, TheCloseReportsWhatTheLastFlushCouldNotWrite) {
  OutputFile f("/dev/full", "the events file");
  f.write("lost\n");
  EXPECT_THROW(f.close(), OutputError);
  EXPECT_FALSE(f.is_open());
}

TEST(OutputFile, RefusesAnInputFileADirectoryAndAMissingFolder) {
  const std::string input = ::testing::TempDir() + "imasim_output_input.txt";
  std::ofstream(input) << "keep me\n";
  const std::string inputs[] = {input};
  try {
    OutputFile f(::testing::TempDir() + "./imasim_output_input.txt", "the events file", inputs);
    FAIL() << "an input file was opened for writing";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("is the input file " + input), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(contents(input), "keep me\n");
  EXPECT_THROW(OutputFile(::testing::TempDir(), "the events file"), OutputError);
  try {
    OutputFile f("/nonexistent-folder/events.csv", "the events file");
    FAIL();
  } catch (const OutputError& e) {
    EXPECT_STREQ(e.what(),
                 "cannot create the events file /nonexistent-folder/events.csv: No such file or "
                 "directory");
  }
}

TEST(EventCsv, TheHeaderIsWrittenAtOnceAndEventsAsTheyCome) {
  const std::string path = ::testing::TempDir() + "imasim_events.csv";
  EventCsvWriter writer(OutputFile(path, "the events file"));
  EXPECT_EQ(contents(path), kEventCsvHeader);  // an empty run leaves a valid file
  surgery::EventLog log;
  log.add(0.5, surgery::EventKind::cautery_on, 1, surgery::Tissue::none, 0, 40);
  writer.append_new(log);
  log.add(1.25, surgery::EventKind::fascia_cut, 1, surgery::Tissue::fascia, 3);
  writer.finish(log);
  EXPECT_EQ(writer.written(), 2u);
  EXPECT_EQ(contents(path), std::string(kEventCsvHeader) +
                                "0.5000,cautery_on,right,none,0,40\n"
                                "1.2500,fascia_cut,right,fascia,3,0\n");
}

}  // namespace
}  // namespace imasim::metrics
