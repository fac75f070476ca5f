// The scoring tools' command-line contracts (`imasim stats`, `imasim sai`), as other checks and
// scripts call them: exactly the documented JSON keys, the paper's Table 1, a SAI with a known
// answer, and bad input refused naming the file and line.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_process.hpp"

namespace {

using imasim::test::Finished;

const std::string kDir = ::testing::TempDir();
std::string err_file() {
  return imasim::test::test_err_file(kDir, "imasim_scores");
}

Finished run(const std::string& args) {
  return imasim::test::run_imasim(args, err_file());
}

// In the order printed (an ordered parse: nlohmann::json would sort them).
std::vector<std::string> keys_of(const nlohmann::ordered_json& j) {
  std::vector<std::string> k;
  for (auto it = j.begin(); it != j.end(); ++it)
    k.push_back(it.key());
  return k;
}

void write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

TEST(StatsCommand, TheTableOfThePaperWithExactlyTheContractsKeys) {
  const Finished r =
      run("stats --a 0.583,0.621,0.545,0.602,0.568,0.634,0.592,0.551,0.615,0.577 "
          "--b 0.247,0.268,0.221,0.285,0.238,0.276,0.212,0.257,0.228,0.243 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(keys_of(j),
            (std::vector<std::string>{"mean_a", "sd_a", "mean_b", "sd_b", "t_welch", "df_welch",
                                      "p_welch", "t_student", "p_student", "cohen_d"}));
  EXPECT_NEAR(j["mean_a"].get<double>(), 0.5888, 1e-12);
  EXPECT_NEAR(j["mean_b"].get<double>(), 0.2475, 1e-12);
  EXPECT_LT(j["p_welch"].get<double>(), 0.001);
  EXPECT_LT(j["p_student"].get<double>(), 0.001);
  EXPECT_NEAR(j["t_welch"].get<double>(), 28.3043004509, 1e-8);
}

TEST(StatsCommand, UndefinedOrBadGroupsAreClearErrors) {
  const Finished one = run("stats --a 1 --b 2,3 --json");
  EXPECT_EQ(one.exit_code, 2);
  EXPECT_NE(one.err.find("at least two values"), std::string::npos) << one.err;
  const Finished flat = run("stats --a 1,1 --b 2,2");
  EXPECT_EQ(flat.exit_code, 2);
  EXPECT_NE(flat.err.find("zero variance"), std::string::npos) << flat.err;
  const Finished word = run("stats --a 1,two --b 2,3");
  EXPECT_NE(word.exit_code, 0);
  EXPECT_NE(word.err.find("--a"), std::string::npos) << word.err;
  const Finished nan = run("stats --a 1,nan --b 2,3");
  EXPECT_NE(nan.exit_code, 0);
}

TEST(SaiCommand, AKnownTrajectoryWithExactlyTheContractsKeys) {
  const std::string traj = kDir + "imasim_sai_traj.csv", line = kDir + "imasim_sai_line.csv",
                    heart = kDir + "imasim_sai_heart.obj";
  // The IMA along z; the heart's near face at x = -20 mm; the tool 4 mm away from it for three
  // samples and 2 mm toward it for one: SAI = (3 * 2 - 1) / 4.
  write(traj,
        "t,x,y,z\n0,0.004,0,0.01\n0.0167,0.004,0,0.02\n0.0333,0.004,0,0.03\n0.05,-0.002,0,0.04\n");
  write(line, "x,y,z\n0,0,0\n0,0,0.1\n");
  write(heart,
        "v -0.02 -0.5 -0.5\nv -0.02 0.5 -0.5\nv -0.02 0.5 0.5\nv -0.02 -0.5 0.5\n"
        "f 1 2 3\nf 1 3 4\n");
  const std::string files = "--trajectory " + traj + " --centerline " + line + " --heart " + heart;
  const Finished r = run("sai " + files + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(keys_of(j),
            (std::vector<std::string>{"sai", "samples", "mean_distance_m", "heart_side_fraction"}));
  EXPECT_NEAR(j["sai"].get<double>(), 1.25, 1e-12);
  EXPECT_EQ(j["samples"], 4);
  EXPECT_NEAR(j["mean_distance_m"].get<double>(), 0.0035, 1e-15);
  EXPECT_NEAR(j["heart_side_fraction"].get<double>(), 0.25, 1e-15);
  // R = 1 mm doubles it; the recorder's columns by tool name give the same.
  const Finished r1 = run("sai " + files + " --radius 0.001 --json");
  EXPECT_NEAR(nlohmann::json::parse(r1.out)["sai"].get<double>(), 2.5, 1e-12);
  const std::string recorded = kDir + "imasim_sai_recorded.csv";
  write(recorded,
        "t_s,forceps_x,forceps_y,forceps_z,hook_x,hook_y,hook_z\n"
        "0,9,9,9,0.004,0,0.01\n0.0167,9,9,9,0.004,0,0.02\n0.0333,9,9,9,0.004,0,0.03\n"
        "0.05,9,9,9,-0.002,0,0.04\n");
  const Finished hook = run("sai --trajectory " + recorded + " --centerline " + line + " --heart " +
                            heart + " --tool hook --json");
  ASSERT_EQ(hook.exit_code, 0) << hook.err;
  EXPECT_NEAR(nlohmann::json::parse(hook.out)["sai"].get<double>(), 1.25, 1e-12);
}

TEST(SaiCommand, BadFilesAreNamedWithTheirLine) {
  const std::string traj = kDir + "imasim_sai_bad.csv", line = kDir + "imasim_sai_line2.csv",
                    heart = kDir + "imasim_sai_heart2.obj";
  write(traj, "t,x,y,z\n0,0,0,0\n0.1,0,zero,0\n");
  write(line, "x,y,z\n0,0,0\n0,0,0.1\n");
  write(heart, "v -0.02 -0.5 -0.5\nv -0.02 0.5 -0.5\nv -0.02 0.5 0.5\nf 1 2 3\n");
  const std::string rest = " --centerline " + line + " --heart " + heart;
  const Finished bad = run("sai --trajectory " + traj + rest);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find(traj + ":3: column 'y': expected a finite number, got 'zero'"),
            std::string::npos)
      << bad.err;
  const Finished tool = run("sai --trajectory " + traj + rest + " --tool hook");
  EXPECT_EQ(tool.exit_code, 2);
  EXPECT_NE(tool.err.find(traj + ":1: the header has no column 'hook_x'"), std::string::npos)
      << tool.err;
  const std::string good = kDir + "imasim_sai_good.csv";
  write(good, "t,x,y,z\n0,0.001,0,0.01\n");
  const Finished missing = run("sai --trajectory " + good + " --centerline " + line + " --heart " +
                               kDir + "no_such_heart.obj");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no_such_heart.obj"), std::string::npos) << missing.err;
  const Finished radius = run("sai --trajectory " + traj + rest + " --radius 0");
  EXPECT_NE(radius.exit_code, 0);
  EXPECT_NE(radius.err.find("--radius"), std::string::npos) << radius.err;
}

// Each of these scored and exited 0: a header-only trajectory as 0.0, coordinates of 1e308 as
// null, a heart of collinear points with a sign. Now each is an error that says why.
TEST(SaiCommand, NonsenseIsRefusedNotScored) {
  const std::string line = kDir + "imasim_sai_line3.csv", heart = kDir + "imasim_sai_heart3.obj",
                    good = kDir + "imasim_sai_good3.csv";
  write(line, "x,y,z\n0,0,0\n0,0,0.1\n");
  write(heart, "v -0.02 -0.5 -0.5\nv -0.02 0.5 -0.5\nv -0.02 0.5 0.5\nf 1 2 3\n");
  write(good, "t,x,y,z\n0,0.001,0,0.01\n");
  auto refused = [&](const std::string& trajectory, const std::string& heart_file,
                     const std::string& expected) {
    const Finished f =
        run("sai --trajectory " + trajectory + " --centerline " + line + " --heart " + heart_file);
    EXPECT_EQ(f.exit_code, 2) << f.out;
    EXPECT_NE(f.err.find(expected), std::string::npos) << f.err;
    EXPECT_EQ(f.out, "");
  };
  const std::string empty = kDir + "imasim_sai_empty.csv", huge = kDir + "imasim_sai_huge.csv";
  write(empty, "t,x,y,z\n");
  refused(empty, heart, empty + ": the trajectory has no samples (a header only)");
  write(huge, "t,x,y,z\n0,1e308,1e308,1e308\n0.1,-1e308,1e308,1e308\n");
  refused(huge, heart, "trajectory sample 1 is inf m from the centerline, more than 10 m");
  const std::string flat = kDir + "imasim_sai_flat.obj", millimetres = kDir + "imasim_sai_mm.obj";
  write(flat, "v -0.02 0 0\nv -0.03 0 0\nv -0.04 0 0\nf 1 2 3\n");
  refused(good, flat, "the heart surface is degenerate: none of its 1 triangles has an area");
  write(millimetres, "v -20 -500 -500\nv -20 500 -500\nv -20 500 500\nf 1 2 3\n");
  refused(good, millimetres, "the heart surface's area is 5e+05 m^2, not a heart's");
}

}  // namespace
