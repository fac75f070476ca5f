// `imasim cloth` as a user runs it: the JSON contract, and clear errors for bad arguments.
#include <gtest/gtest.h>

#include <fstream>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

namespace {

struct Outcome {
  int exit_code;
  std::string output;  // stdout and stderr
};

Outcome run_imasim(const std::string& args) {
  const std::string command = std::string(IMASIM_EXE) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return {-1, ""};
  std::string out;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr)
    out += buffer.data();
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

TEST(ClothCommand, PrintsTheJsonContract) {
  const Outcome r = run_imasim("cloth --n 16 --steps 50 --threads 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["particles"], 256);
  EXPECT_EQ(j["distance_constraints"], 3 * 15 * 15 + 2 * 15);
  EXPECT_EQ(j["dihedral_constraints"], 3 * 15 * 15 + 2 * 15 - 4 * 15);
  EXPECT_GT(j["colours"].get<int>(), 0);
  EXPECT_GT(j["center_sag_m"].get<double>(), 0.0);
  EXPECT_GE(j["max_displacement_m"].get<double>(), j["center_sag_m"].get<double>());
  EXPECT_GE(j["ms_per_step_median"].get<double>(), 0.0);
  EXPECT_EQ(j["state_hash"].get<std::string>().size(), 16u);
  EXPECT_EQ(j["finite"], true);
}

TEST(ClothCommand, SameHashForAnyThreadCount) {
  const auto one =
      nlohmann::json::parse(run_imasim("cloth --n 20 --steps 30 --threads 1 --json").output);
  const auto two =
      nlohmann::json::parse(run_imasim("cloth --n 20 --steps 30 --threads 2 --json").output);
  EXPECT_EQ(one["state_hash"], two["state_hash"]);
}

TEST(ClothCommand, AcceptsXpbdCompliances) {
  const Outcome r = run_imasim("cloth --n 10 --steps 20 --compliance 1e-4,2 --substeps 4 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(nlohmann::json::parse(r.output)["finite"], true);
}

TEST(ClothCommand, ReportsARefusedStepWithExitCodeThree) {
  // The sagging cloth moves faster than 1 mm/s within a few steps: the guard refuses the step.
  const Outcome r = run_imasim("cloth --n 8 --steps 50 --max-speed 0.001 --json");
  ASSERT_EQ(r.exit_code, 3) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["status"], "speed_limit");
  EXPECT_EQ(j["finite"], true);
  EXPECT_LT(j["failed_step"].get<int>(), 50);
  EXPECT_EQ(j["steps"], j["failed_step"]);
  EXPECT_LT(j["failed_particle"].get<int>(), 64);
}

TEST(RunCommand, RunsTheThoraxSceneHeadless) {
  const Outcome r = run_imasim("run --headless --seconds 0.5 --threads 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["heart"], "beating");
  EXPECT_EQ(j["steps"], 100);
  EXPECT_GT(j["particles"].get<int>(), 1000);
  EXPECT_EQ(j["ports"], 4);
  EXPECT_GT(j["ima_motion_max_m"].get<double>(), 1e-4);
  // Bone does not beat: the chest wall stays put while the heart moves the vessel (the wall
  // used to take the heart's drive, 6.4 mm over a beat).
  EXPECT_LT(j["chest_wall_motion_max_m"].get<double>(), 1e-4);
  EXPECT_NEAR(j["heart_phase"].get<double>(), 0.7 + 0.5 * 75 / 60.0 - 1, 1e-9);
  EXPECT_EQ(j["status"], "ok");
  const auto two =
      nlohmann::json::parse(run_imasim("run --headless --seconds 0.5 --threads 2 --json").output);
  EXPECT_EQ(two["state_hash"], j["state_hash"]);
}

TEST(RunCommand, StaticHeartAndClearErrors) {
  const auto j =
      nlohmann::json::parse(run_imasim("run --headless --seconds 0.3 --static --json").output);
  EXPECT_EQ(j["heart"], "static");
  EXPECT_LT(j["ima_motion_max_m"].get<double>(), 1e-15);
  const Outcome window = run_imasim("run");
  EXPECT_EQ(window.exit_code, 2);
  EXPECT_NE(window.output.find("--headless"), std::string::npos);
  const Outcome bad = run_imasim("run --headless --heart-rate 5");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("--heart-rate"), std::string::npos);
}

// --substeps and --iterations override the scene's solver, and the report says where the tissue
// rests: the unconverged 1 x 5 solve sags the fascia far more than the default.
TEST(RunCommand, SolverOverridesAndRestingDisplacements) {
  const auto fine = nlohmann::json::parse(
      run_imasim("run --headless --static --seconds 0.5 --threads 1 --json").output);
  EXPECT_EQ(fine["substeps"], 32);
  EXPECT_EQ(fine["iterations"], 1);
  const auto coarse = nlohmann::json::parse(
      run_imasim("run --headless --static --seconds 0.5 --substeps 1 --iterations 5 --threads 1 "
                 "--json")
          .output);
  EXPECT_EQ(coarse["substeps"], 1);
  EXPECT_EQ(coarse["iterations"], 5);
  EXPECT_GT(fine["fascia_max_displacement_m"].get<double>(), 1e-4);
  EXPECT_GT(coarse["fascia_max_displacement_m"].get<double>(),
            1.5 * fine["fascia_max_displacement_m"].get<double>());
  EXPECT_LT(fine["vessel_max_displacement_m"].get<double>(), 1e-9);  // unloaded, static heart
  EXPECT_GE(fine["kinetic_energy_j"].get<double>(), 0);
  EXPECT_EQ(fine["missed_heart_contacts"], 0);
  // Where the time went: per-stage means that add up to the total; a scene without instruments
  // spends none on them, and 32 substeps spend more in the solve than 1 x 5 does.
  const auto& profile = fine["profile_ms_per_step"];
  double sum = 0;
  for (const char* stage : {"instruments", "cutting", "heart", "contacts", "predict", "solve",
                            "velocities", "coupling", "surfaces"})
    sum += profile[stage].get<double>();
  EXPECT_NEAR(profile["total"].get<double>(), sum, 1e-9);
  EXPECT_EQ(profile["instruments"].get<double>(), 0.0);
  EXPECT_GT(profile["solve"].get<double>(), coarse["profile_ms_per_step"]["solve"].get<double>());
  const Outcome bad = run_imasim("run --headless --substeps 0");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("--substeps"), std::string::npos);
}

TEST(RunCommand, PatientSeedGivesAnotherReproduciblePatient) {
  const std::string args = "run --headless --seconds 0.1 --threads 1 --json";
  const auto typical = nlohmann::json::parse(run_imasim(args).output);
  const auto seven = nlohmann::json::parse(run_imasim(args + " --patient-seed 7").output);
  const auto again = nlohmann::json::parse(run_imasim(args + " --patient-seed 7").output);
  EXPECT_EQ(typical["patient_seed"], 0);
  EXPECT_EQ(seven["patient_seed"], 7);
  EXPECT_EQ(seven["status"], "ok");
  EXPECT_EQ(seven["state_hash"], again["state_hash"]);
  EXPECT_NE(seven["state_hash"], typical["state_hash"]);
  EXPECT_NE(seven["ima_depth_m"], typical["ima_depth_m"]);
  EXPECT_EQ(typical["skeleton_meshes"].get<int>() % 2, 1);  // sternum + cartilage/rib pairs
}

TEST(RunCommand, AScriptDrivesTheInstrumentsAndWritesTheEvents) {
  const std::string events = ::testing::TempDir() + "imasim_cli_events.csv";
  const Outcome r = run_imasim("run --headless --script " IMASIM_SOURCE_DIR
                               "/examples/open_fascia.script --seconds 2 --threads 1 --events " +
                               events + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["steps"], 400);
  EXPECT_GT(j["events"]["fascia_cut"].get<int>(), 0);
  EXPECT_EQ(j["events"]["cautery_on"], 1);
  EXPECT_GT(j["fascia_edges_cut"].get<int>(), 0);
  EXPECT_EQ(j["finite"], true);
  std::FILE* f = std::fopen(events.c_str(), "r");
  ASSERT_NE(f, nullptr);
  std::array<char, 256> line;
  ASSERT_NE(std::fgets(line.data(), line.size(), f), nullptr);
  EXPECT_STREQ(line.data(), "time_s,kind,instrument,tissue,count,value\n");
  int cuts = 0;
  while (std::fgets(line.data(), line.size(), f) != nullptr)
    cuts += std::string(line.data()).find(",fascia_cut,right,fascia,") != std::string::npos;
  std::fclose(f);
  EXPECT_EQ(cuts, j["events"]["fascia_cut"].get<int>());
  // Same inputs, same result, whatever the threads.
  const auto two = nlohmann::json::parse(
      run_imasim("run --headless --script " IMASIM_SOURCE_DIR
                 "/examples/open_fascia.script --seconds 2 --threads 2 --json")
          .output);
  EXPECT_EQ(two["state_hash"], j["state_hash"]);
}

TEST(RunCommand, ABadScriptIsReportedWithItsLine) {
  const std::string path = ::testing::TempDir() + "imasim_bad.script";
  std::FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs("0.0 left jaw open\n0.5 right pedal burn\n", f);
  std::fclose(f);
  const Outcome r = run_imasim("run --headless --script " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(path + ":2:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("pedal"), std::string::npos) << r.output;
  const Outcome missing = run_imasim("run --headless --script /nonexistent/x.script");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("/nonexistent/x.script"), std::string::npos);
}

TEST(SceneCommand, PrintDefaultChecksAndRunsLikeTheBuiltInScene) {
  const std::string path = testing::TempDir() + "imasim_default_scene.toml";
  const Outcome printed = run_imasim("scene print-default > " + path);
  ASSERT_EQ(printed.exit_code, 0) << printed.output;
  const Outcome checked = run_imasim("scene check " + path);
  EXPECT_EQ(checked.exit_code, 0) << checked.output;
  EXPECT_NE(checked.output.find(": ok"), std::string::npos);
  const auto from_file = nlohmann::json::parse(
      run_imasim("run --headless --seconds 0.1 --threads 1 --json --scene " + path).output);
  const auto built_in =
      nlohmann::json::parse(run_imasim("run --headless --seconds 0.1 --threads 1 --json").output);
  EXPECT_EQ(from_file["state_hash"], built_in["state_hash"]);
}

TEST(SceneCommand, CheckListsProblemsWithFileLineAndKey) {
  const std::string path = testing::TempDir() + "imasim_bad_scene.toml";
  ASSERT_EQ(run_imasim("scene print-default > /dev/null").exit_code, 0);
  {
    FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs(
        "[heart]\nheart_rate_bpm = 500\nphase_files = [\"no_such_phase.obj\", \"p1.obj\"]\n"
        "[fascia]\nnxx = 4\n",
        f);
    std::fclose(f);
  }
  const Outcome r = run_imasim("scene check " + path);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find(path + ":2: key 'heart.heart_rate_bpm'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(path + ":5: key 'fascia.nxx': unknown key; did you mean 'fascia.nx'?"),
            std::string::npos)
      << r.output;
  // Once the keys are sound, the files they name are checked too.
  {
    FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("[heart]\nphase_files = [\"no_such_phase.obj\", \"p1.obj\"]\n", f);
    std::fclose(f);
  }
  const Outcome mesh = run_imasim("scene check " + path);
  EXPECT_EQ(mesh.exit_code, 1);
  EXPECT_NE(mesh.output.find(path + ":2: key 'heart.phase_files': "), std::string::npos)
      << mesh.output;
  EXPECT_NE(mesh.output.find("no_such_phase.obj: no such file"), std::string::npos) << mesh.output;
  const Outcome run = run_imasim("run --headless --scene " + path);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("heart.phase_files"), std::string::npos) << run.output;
}

TEST(ClothCommand, RejectsBadArgumentsWithAClearMessage) {
  struct Case {
    const char* args;
    const char* message;
  };
  for (const Case& c :
       {Case{"cloth --n 1", "--n"}, Case{"cloth --n abc", "--n"},
        Case{"cloth --pbd 2,0.1", "--pbd"}, Case{"cloth --pbd 1", "--pbd"},
        Case{"cloth --compliance -1,0", "--compliance"},
        Case{"cloth --pbd 1,0.1 --compliance 0,0", "excludes"}, Case{"cloth --dt 0", "--dt"},
        Case{"cloth --max-speed 0", "--max-speed"}, Case{"cloth --bogus", "bogus"}}) {
    const Outcome r = run_imasim(c.args);
    EXPECT_NE(r.exit_code, 0) << c.args;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << " -> " << r.output;
  }
}

// The red team's hostile command lines and files: each refused at once with a message naming what
// is wrong (and, for a scene file, its line and key), never a crash, a hang or a silent run.
void write_file(const std::string& path, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs(text.c_str(), f);
  std::fclose(f);
}

TEST(HostileInput, BadArgumentsAreRefusedNamingTheOption) {
  const std::string dir = ::testing::TempDir();
  struct Case {
    std::string args;
    int exit_code;
    std::string message;
  };
  const Case cases[] = {
      {"run --headless --seconds nan", 105,
       "--seconds: expected a finite number in [0, 3600], got 'nan'"},
      {"run --headless --seconds inf", 105, "--seconds: expected a finite number"},
      {"run --headless --heart-rate nan", 105,
       "--heart-rate: expected a finite number in [20, 250], got 'nan'"},
      {"run --headless --patient-seed -1", 105,
       "--patient-seed: expected a whole number in [0, 9000000000000000000], got '-1'"},
      {"run --headless --scene ''", 105, "--scene: expected a file name, got an empty one"},
      {"run --headless --script ''", 105, "--script: expected a file name, got an empty one"},
      {"scene check ''", 105, "FILE: expected a file name, got an empty one"},
      {"run --headless --scene " + dir, 2, "cannot open the scene file: is a directory"},
      {"scene check " + dir, 1, "cannot open the scene file: is a directory"},
      {"scene check /dev/zero", 1, "/dev/zero: cannot open the scene file: not a regular file"},
      {"run --headless --script /dev/zero", 2,
       "/dev/zero: cannot open the input script: not a regular file"},
      {"run --headless --substeps 1000", 105, "--substeps: Value 1000 not in range 1 to 512"},
      {"run --headless --substeps 512 --iterations 512", 2,
       "imasim run: substeps x iterations = 512 x 512 = 262144 sweeps per step, above the "
       "limit of 512"},
      {"cloth --iterations 10000", 105, "--iterations: Value 10000 not in range 1 to 64"},
      {"cloth --n 4096", 2, "cloth: the scene would have up to 16777216 particles"},
  };
  for (const Case& c : cases) {
    const Outcome r = run_imasim(c.args);
    EXPECT_EQ(r.exit_code, c.exit_code) << c.args << " -> " << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << " -> " << r.output;
  }
}

TEST(HostileInput, ScriptTimesInMillisecondsAreRefused) {
  const std::string path = ::testing::TempDir() + "imasim_ms.script";
  write_file(path, "0 right pedal off\n5000 right pedal cut\n");
  const Outcome r = run_imasim("run --headless --script " + path);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(path + ":2: time 5000 s is after the limit of 3600 s"), std::string::npos)
      << r.output;
  write_file(path, "1e308 left jaw open\n");
  const Outcome huge = run_imasim("run --headless --script " + path);
  EXPECT_EQ(huge.exit_code, 2) << huge.output;
  EXPECT_NE(huge.output.find(path + ":1: time 1e308 s is after the limit"), std::string::npos)
      << huge.output;
}

// `scene check` refuses what `run` refuses, at the key: a sternum at 1e200 m passed the check
// and then failed in the run's set-up with a message naming no key.
TEST(HostileInput, SceneCheckRefusesWhatRunRefusesAtTheKey) {
  const std::string path = ::testing::TempDir() + "imasim_far.toml";
  for (const std::string& text :
       {std::string("[anatomy]\nsternum_position_m = [1e200, 0, 0]\n"),
        std::string("[anatomy]\nheart_offset_m = [1000, 0, 0]\n"),
        std::string("[anatomy]\nheart_offset_m = [1e300, -1e300, 1e300]\n")}) {
    write_file(path, text);
    const std::string key = text.substr(10, text.find(' ', 10) - 10);
    const Outcome check = run_imasim("scene check " + path);
    EXPECT_EQ(check.exit_code, 1) << check.output;
    EXPECT_NE(check.output.find(path + ":2: key 'anatomy." + key + "'"), std::string::npos)
        << check.output;
    const Outcome run = run_imasim("run --headless --seconds 0.01 --scene " + path);
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(path + ":2: key 'anatomy." + key + "'"), std::string::npos)
        << run.output;
  }
}

}  // namespace

namespace {

TEST(HapticsBenchCommand, PrintsExactlyTheContractsKeys) {
  // The whole loop for 2 s: physics in real time, the 1 kHz loop, two emulated devices over
  // OpenIGTLink on loopback. The figures are measured by `make bench`'s run, not asserted here;
  // this checks the contract and that the loop ran and rendered forces.
  const Outcome r = run_imasim("haptics-bench --seconds 2 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  std::vector<std::string> keys;
  for (const auto& [key, value] : j.items())
    keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"contacts", "floor_missed_deadlines",
                                            "floor_p99_error_us", "floor_seconds", "force_max_n",
                                            "latency_p99_us", "missed_deadlines", "period_max_us",
                                            "period_p50_us", "period_p99_error_us", "rate_hz"}));
  // The machine's floor, measured beside the loop: a bare sleeper half a second before and after.
  EXPECT_GT(j["floor_p99_error_us"].get<double>(), 0);
  EXPECT_GE(j["floor_missed_deadlines"].get<int>(), 0);
  EXPECT_NEAR(j["floor_seconds"].get<double>(), 1.0, 0.1);
  EXPECT_GT(j["rate_hz"].get<double>(), 0);
  EXPECT_GT(j["period_p50_us"].get<double>(), 0);
  EXPECT_GE(j["force_max_n"].get<double>(), 0);
  EXPECT_LE(j["force_max_n"].get<double>(), 3.3 + 1e-9);  // the device's limit
  EXPECT_GE(j["missed_deadlines"].get<int>(), 0);
}

TEST(HapticsBenchCommand, RefusesABadDuration) {
  for (const char* bad : {"nan", "-1", "0", "1e9"}) {
    const Outcome r = run_imasim(std::string("haptics-bench --seconds ") + bad);
    EXPECT_NE(r.exit_code, 0) << bad;
    EXPECT_NE(r.output.find("--seconds"), std::string::npos) << r.output;
  }
}

TEST(DevicesCommand, ListsEveryKindWithItsMapping) {
  const Outcome r = run_imasim("devices --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  std::vector<std::string> kinds;
  for (const auto& d : j["devices"]) {
    kinds.push_back(d["kind"]);
    EXPECT_FALSE(d["mapping"].get<std::string>().empty());
    EXPECT_FALSE(d["use"].get<std::string>().empty());
  }
  EXPECT_EQ(kinds, (std::vector<std::string>{"openigtlink", "gamepad", "spacemouse", "pedal",
                                             "emulator", "script"}));
  EXPECT_EQ(j["devices"][0]["max_force_n"], 3.3);
}

// The mappings listed are the scene file's; a broken scene file is named with its line.
TEST(DevicesCommand, ShowsTheSceneFilesMappings) {
  const std::string path = ::testing::TempDir() + "imasim_devices_scene.toml";
  {
    std::ofstream f(path);
    f << "[devices]\ngamepad_cut_button = \"right_shoulder\"\npedal_coag_button = 5\n"
         "igtl_port = 0\n";
  }
  const Outcome r = run_imasim("devices --json --scene " + path);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_NE(j["devices"][1]["mapping"].get<std::string>().find("right_shoulder -> pedal cut"),
            std::string::npos)
      << j["devices"][1]["mapping"];
  EXPECT_NE(j["devices"][3]["mapping"].get<std::string>().find("button 5 -> pedal coag"),
            std::string::npos)
      << j["devices"][3]["mapping"];
  {
    std::ofstream f(path);
    f << "[devices]\n\npedal_cut_button = -1\n";
  }
  const Outcome bad = run_imasim("devices --scene " + path);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find(":3: key 'devices.pedal_cut_button'"), std::string::npos) << bad.output;
}

}  // namespace
