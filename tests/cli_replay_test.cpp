// `imasim run --replay` knows where its stream came from: a stream replayed with
// another patient seed or --static gave another state hash with exit 0; a stream cut short
// replayed its part and an empty one ran 0 steps, both with exit 0; --seconds beyond the stream
// quietly stopped early. Each is refused now, naming the field or the cause.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_process.hpp"

namespace {

using imasim::test::Finished;

const std::string kDir = ::testing::TempDir();
const std::string kScript = IMASIM_SOURCE_DIR "/examples/open_fascia.script";

Finished run(const std::string& args) {
  return imasim::test::run_imasim(args, imasim::test::test_err_file(kDir, "imasim_replay"));
}

std::string lines_without(const std::string& path, const std::string& prefix) {
  std::ifstream in(path);
  std::string out;
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) != 0) out += line + "\n";
  return out;
}

TEST(RunReplay, AStreamReplaysOnlyUnderTheOriginItWasRecordedIn) {
  const std::string stream = kDir + "imasim_origin.stream";
  const Finished recorded = run("run --headless --script " + kScript +
                                " --seconds 0.3 --threads 1 --record-input " + stream + " --json");
  ASSERT_EQ(recorded.exit_code, 0) << recorded.err;
  const auto a = nlohmann::json::parse(recorded.out);
  const Finished same = run("run --headless --replay " + stream + " --threads 1 --json");
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_EQ(nlohmann::json::parse(same.out)["state_hash"], a["state_hash"]);
  EXPECT_EQ(same.err, "");

  const Finished still = run("run --headless --replay " + stream + " --static --json");
  EXPECT_EQ(still.exit_code, 2);
  EXPECT_EQ(still.out, "");
  EXPECT_NE(still.err.find(stream + ": recorded under another origin: heart: recorded beating, "
                                    "this run static"),
            std::string::npos)
      << still.err;
  EXPECT_NE(still.err.find("--replay-anyway plays it regardless"), std::string::npos);
  const Finished seed = run("run --headless --replay " + stream + " --patient-seed 7");
  EXPECT_EQ(seed.exit_code, 2);
  EXPECT_NE(seed.err.find("patient_seed: recorded 0, this run 7"), std::string::npos) << seed.err;

  const Finished anyway =
      run("run --headless --replay " + stream + " --patient-seed 7 --replay-anyway --json");
  ASSERT_EQ(anyway.exit_code, 0) << anyway.err;
  EXPECT_NE(nlohmann::json::parse(anyway.out)["state_hash"], a["state_hash"]);
  EXPECT_NE(anyway.err.find("replayed anyway: recorded under another origin: patient_seed"),
            std::string::npos)
      << anyway.err;

  const Finished longer = run("run --headless --replay " + stream + " --seconds 1");
  EXPECT_EQ(longer.exit_code, 2);
  EXPECT_NE(longer.err.find(stream + " holds 0.3 s (60 steps); --seconds 1 asks for more"),
            std::string::npos)
      << longer.err;
}

TEST(RunReplay, AStreamCutShortOrEmptyIsRefused) {
  const std::string stream = kDir + "imasim_whole.stream";
  ASSERT_EQ(run("run --headless --script " + kScript + " --seconds 0.2 --record-input " + stream)
                .exit_code,
            0);
  const std::string cut = kDir + "imasim_cut.stream";
  {
    std::string text = lines_without(stream, "#! end");
    text.resize(text.size() / 2);  // as a killed run leaves it: no end line, a line half written
    text = text.substr(0, text.rfind('\n') + 1);
    std::ofstream(cut) << text;
  }
  const Finished short_stream = run("run --headless --replay " + cut);
  EXPECT_EQ(short_stream.exit_code, 2);
  EXPECT_NE(short_stream.err.find(cut + ": cut short after "), std::string::npos)
      << short_stream.err;
  EXPECT_EQ(run("run --headless --replay " + cut + " --replay-anyway").exit_code, 0);

  const std::string empty = kDir + "imasim_empty.stream";
  {
    std::ifstream in(stream);
    std::ostringstream head;
    for (std::string line; std::getline(in, line) && line[0] == '#';)
      head << line << "\n";
    std::ofstream(empty) << head.str() << "#! end 0\n";
  }
  for (const std::string& extra : {std::string(), std::string(" --replay-anyway")}) {
    const Finished none = run("run --headless --replay " + empty + extra);
    EXPECT_EQ(none.exit_code, 2);
    EXPECT_NE(none.err.find(empty + ": no steps: an empty stream replays nothing"),
              std::string::npos)
        << none.err;
  }
  const Finished alone = run("run --headless --script " + kScript + " --replay-anyway");
  EXPECT_EQ(alone.exit_code, 2);
  EXPECT_NE(alone.err.find("--replay-anyway goes with --replay"), std::string::npos) << alone.err;
}

}  // namespace
