// Scene files: the default scene survives print -> parse; broken files give file:line:key errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "math/edit_distance.hpp"
#include "physics/executor.hpp"
#include "scene/scene_file.hpp"
#include "scene/scene_key_renames.hpp"
#include "scene/scene_keys.hpp"
#include "session/surgical_session.hpp"

namespace imasim::scene {
namespace {

TEST(SceneFile, PrintThenParseGivesTheSameScene) {
  const std::string text = print_scene(default_thorax_scene_params());
  const ThoraxSceneParams parsed = parse_scene(text, "default.toml");
  EXPECT_EQ(print_scene(parsed), text);
  // And the same simulation, bit for bit.
  std::uint64_t hash[2];
  int k = 0;
  for (const ThoraxSceneParams& p : {default_thorax_scene_params(), parsed}) {
    ThoraxScene s = make_thorax_scene(p);
    physics::Executor exec(1);
    for (int n = 0; n < 20; ++n)
      ASSERT_TRUE(step_thorax_scene(s, exec).ok());
    hash[k++] = physics::position_hash(s.patch.world.state);
  }
  EXPECT_EQ(hash[0], hash[1]);
}

TEST(SceneFile, PrintedPathsAreEscapedTomlStrings) {
  ThoraxSceneParams p = default_thorax_scene_params();
  p.heart_series.phase_files = {"/data/a\"b\\c.obj", "/data/line\nbreak.obj"};
  const std::string text = print_scene(p);
  EXPECT_NE(text.find(R"(phase_files = ["/data/a\"b\\c.obj", "/data/line\u000abreak.obj"])"),
            std::string::npos)
      << text;
}

TEST(SceneFile, KeysNotGivenKeepTheirDefaults) {
  const ThoraxSceneParams p =
      parse_scene("[heart]\nheart_rate_bpm = 90\nbeating = false\n", "s.toml");
  EXPECT_EQ(p.playback.heart_rate_bpm, 90);
  EXPECT_FALSE(p.playback.beating);
  EXPECT_EQ(p.heart.phases, 11u);
  EXPECT_EQ(p.patch.fascia.nx, default_thorax_scene_params().patch.fascia.nx);
  const ThoraxSceneParams q = parse_scene(
      "[anatomy]\nsternum_position_m = [-0.03, 0.001, 0.002]\npatient_seed = 12\n"
      "[ima_fat]\nseed = 7\n[solver]\nbending_stride = 1\nstretch_sweeps = 3\n"
      "push_out_speed_m_per_s = 0.2\ncoarse_sweeps = 1\n",
      "s.toml");
  EXPECT_EQ(q.patch.solver.bending_stride, 1u);
  EXPECT_EQ(q.patch.solver.stretch_sweeps, 3u);
  EXPECT_EQ(q.patch.solver.coarse_sweeps, 1u);
  EXPECT_EQ(q.patch.solver.push_out_speed, 0.2);
  EXPECT_EQ(q.patch.solver.coarse_stride, default_thorax_scene_params().patch.solver.coarse_stride);
  EXPECT_EQ(q.anatomy.sternum_position, Vec3(-0.03, 0.001, 0.002));
  EXPECT_EQ(q.anatomy.patient_seed, 12u);
  EXPECT_EQ(q.anatomy.ima_depth, default_thorax_scene_params().anatomy.ima_depth);
  EXPECT_EQ(q.patch.ima_fat.generation.seed, 7u);
}

struct Broken {
  const char* text;
  const char* message;  // expected substring, file:line:key included
};

TEST(SceneFile, BrokenFilesNameFileLineAndKey) {
  const Broken cases[] = {
      {"[devices]\nleft_hand = \"Left Hand\"\n",
       "bad.toml:2: key 'devices.left_hand': expected a name of 1 to 20 letters, digits, '.', '_' "
       "or '-', got \"Left Hand\""},
      {"[devices]\n\npedal = \"\"\n", "bad.toml:3: key 'devices.pedal': expected a name of 1"},
      {"[devices]\ngamepad_cut_button = \"start\"\n",
       "bad.toml:2: key 'devices.gamepad_cut_button': expected \"a\" or \"b\" or \"x\" or \"y\" or "
       "\"left_shoulder\" or \"right_shoulder\", got \"start\""},
      {"[devices]\nspacemouse_hand = \"both\"\n",
       "bad.toml:2: key 'devices.spacemouse_hand': expected \"left\" or \"right\", got \"both\""},
      {"[devices]\npedal_coag_button = 33\n",
       "bad.toml:2: key 'devices.pedal_coag_button': expected an integer in [0, 32], got 33"},
      {"[devices]\nigtl_port = 70000\n",
       "bad.toml:2: key 'devices.igtl_port': expected an integer in [0, 65535], got 70000"},
      {"[force_ima]\nstiffness_n_per_m = -5\n",
       "bad.toml:2: key 'force_ima.stiffness_n_per_m': expected a number in [1, 100000], got -5"},
      // A zero coupling would silently make the tool rigid (docs/haptics.md): refused.
      {"[force_fascia]\nstiffness_n_per_m = 0\n",
       "bad.toml:2: key 'force_fascia.stiffness_n_per_m': expected a number in [1, 100000], got 0"},
      {"[force_fat]\ndamping_n_s_per_m = 0.0\n",
       "bad.toml:2: key 'force_fat.damping_n_s_per_m': expected a number in [0.01, 1000], got 0"},
      {"[haptics]\nproxy_damping_n_s_per_m = 0\n",
       "bad.toml:2: key 'haptics.proxy_damping_n_s_per_m': expected a number in [0.01, 1000], got "
       "0"},
      {"[heart]\nhart_rate_bpm = 80\n",
       "bad.toml:2: key 'heart.hart_rate_bpm': unknown key; did you mean 'heart.heart_rate_bpm'?"},
      {"[heart]\n\nejection_fraction = 1.5\n",
       "bad.toml:3: key 'heart.ejection_fraction': expected a number in [0.05, 0.95], got 1.5"},
      {"[anatomy]\nheart_offset_m = [1, 2]\n",
       "bad.toml:2: key 'anatomy.heart_offset_m': expected [x, y, z]"},
      {"[anatomy]\nima_lateral_offset_m = 0.2\n",
       "bad.toml:2: key 'anatomy.ima_lateral_offset_m': expected a number in [0.01, 0.05], got "
       "0.2"},
      {"[anatomy]\nima_course_length_m = 0.1\n",
       "bad.toml:2: key 'anatomy.ima_course_length_m': expected a number in [0.15, 0.3]"},
      {"[anatomy]\nima_depth_m = 0.002\n[vessel]\nradius_m = 0.002\n",
       "bad.toml:2: key 'anatomy.ima_depth_m': the IMA must lie at least 0.5 mm inside"},
      {"[heart]\nlong_axis = [1, 0, 0]\nlateral = [2, 0, 0]\n",
       "bad.toml:2: key 'heart.long_axis': the heart's long axis must be non-zero and not "
       "parallel"},
      {"[heart]\nphase_files = [\"/nonexistent/p0.obj\", \"/nonexistent/p1.obj\"]\n",
       "bad.toml:2: key 'heart.phase_files': /nonexistent/p0.obj: no such file"},
      {"[heart]\nphase_files = [\"/nonexistent/p0.obj\"]\n",
       "bad.toml:2: key 'heart.phase_files': heart phase series: at least two phase files"},
      {"[heart]\nphase_files = \"p0.obj\"\n",
       "bad.toml:2: key 'heart.phase_files': expected an array of file names"},
      {"[heart]\nphase_files = [\"p0.obj\", 3]\n",
       "bad.toml:2: key 'heart.phase_files': entry 1 is not a file name"},
      {"[heart]\nbeating = 1\n", "bad.toml:2: key 'heart.beating': expected true or false"},
      {"[solver]\niterations = 2.5\n", "bad.toml:2: key 'solver.iterations': expected an integer"},
      {"[solver]\niterations = 0\n",
       "bad.toml:2: key 'solver.iterations': expected an integer in [1, 512], got 0"},
      {"[solver]\ndt_s = \"fast\"\n", "bad.toml:2: key 'solver.dt_s': expected a number"},
      {"[solver]\nbending_stride = 0\n",
       "bad.toml:2: key 'solver.bending_stride': expected an integer in [1, 1000], got 0"},
      {"[solver]\nstretch_sweeps = 5\n",
       "bad.toml:2: key 'solver.stretch_sweeps': expected an integer in [1, 4], got 5"},
      {"[solver]\ncoarse_sweeps = 0\n",
       "bad.toml:2: key 'solver.coarse_sweeps': expected an integer in [1, 4], got 0"},
      {"[solver]\npush_out_speed_m_per_s = 0\n",
       "bad.toml:2: key 'solver.push_out_speed_m_per_s': expected a number in [0.0001, 100], got "
       "0"},
      {"[vessel]\ncenterline_m = [[0, 0, 0], [1, 1, 1]]\n",
       "bad.toml:2: key 'vessel.centerline_m' was retired; instead: the IMA's course is laid out "
       "from the anatomy"},
      // The law's keys change nothing with XPBD's fascia: refused, naming the solver key.
      {"[fascia]\n\nlinear_modulus_pa = 2.65e6\n",
       "bad.toml:3: key 'fascia.linear_modulus_pa': read by the implicit fascia only: set "
       "fascia.solver = \"implicit\""},
      {"[fascia]\ntoe_strain = 0.03\n",
       "bad.toml:2: key 'fascia.toe_strain': read by the implicit fascia only"},
      {"[fascia]\nsolver = \"implicit\"\nlinear_modulus_pa = 5e4\n",
       "bad.toml:3: key 'fascia.linear_modulus_pa': the linear region's modulus 50000.0 is below "
       "the toe's (youngs_modulus_pa 1e+05)"},
      {"[fascia]\nsolver = \"newton\"\n",
       "bad.toml:2: key 'fascia.solver': expected \"xpbd\" or \"implicit\", got \"newton\""},
      // The vessel's rate band is XPBD's: with the implicit vessel (the default) it changes
      // nothing.
      {"[vessel]\ncoarse = false\n",
       "bad.toml:2: key 'vessel.coarse': the implicit vessel has no rows in the step's rate bands"},
      {"[vessel]\nsolver = \"newton\"\n",
       "bad.toml:2: key 'vessel.solver': expected \"xpbd\" or \"implicit\", got \"newton\""},
      {"\n[fasica]\nnx = 3\n", "bad.toml:2: unknown table 'fasica'; did you mean 'fascia'?"},
      {"heart_rate_bpm = 70\n",
       "bad.toml:1: key 'heart_rate_bpm': not inside a table; did you mean "
       "'heart.heart_rate_bpm'?"},
      {"[heart\n", "bad.toml:1:"},
      {"[heart]\nphases = 3\nphases = 4\n", "bad.toml:3:"},
  };
  for (const Broken& c : cases) {
    try {
      parse_scene(c.text, "bad.toml");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const SceneFileError& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << "for\n"
                                                                          << c.text << "got\n"
                                                                          << e.what();
    }
  }
}

TEST(SceneFile, TheImplicitFasciaTakesItsLawFromTheFile) {
  const ThoraxSceneParams p = parse_scene(
      "[fascia]\nsolver = \"implicit\"\nlinear_modulus_pa = 1e6\ntoe_strain = 0.08\n", "s.toml");
  EXPECT_EQ(p.fascia_solver, "implicit");
  EXPECT_EQ(p.fascia_linear_modulus, Real(1e6));
  EXPECT_EQ(p.fascia_toe_strain, Real(0.08));
  EXPECT_EQ(default_thorax_scene_params().fascia_solver, "xpbd");
  // Printed and read again, the law is kept.
  const ThoraxSceneParams q = parse_scene(print_scene(p), "printed.toml");
  EXPECT_EQ(q.fascia_solver, "implicit");
  EXPECT_EQ(q.fascia_linear_modulus, Real(1e6));
}

TEST(SceneFile, TheVesselsSolverComesFromTheFile) {
  EXPECT_EQ(default_thorax_scene_params().vessel_solver, "implicit");
  const ThoraxSceneParams p =
      parse_scene("[vessel]\nsolver = \"xpbd\"\ncoarse = false\n", "s.toml");
  EXPECT_EQ(p.vessel_solver, "xpbd");
  EXPECT_FALSE(p.patch.vessel.object.coarse);
  // Printed and read again, both are kept; the default's print comments out the band it ignores.
  const ThoraxSceneParams q = parse_scene(print_scene(p), "printed.toml");
  EXPECT_EQ(q.vessel_solver, "xpbd");
  EXPECT_FALSE(q.patch.vessel.object.coarse);
  const std::string printed = print_scene(default_thorax_scene_params());
  EXPECT_EQ(printed.find("\ncoarse ="), std::string::npos);
  EXPECT_NE(printed.find("\n# coarse = true"), std::string::npos);
}

TEST(SceneFile, ReportsEveryErrorInFileOrder) {
  try {
    parse_scene("[solver]\niterations = 0\n[heart]\nzzz = 1\naaa = 2\n", "bad.toml");
    FAIL();
  } catch (const SceneFileError& e) {
    ASSERT_EQ(e.messages().size(), 3u);
    EXPECT_EQ(e.messages()[0].rfind("bad.toml:2:", 0), 0u);
    EXPECT_EQ(e.messages()[1].rfind("bad.toml:4:", 0), 0u);
    EXPECT_EQ(e.messages()[2].rfind("bad.toml:5:", 0), 0u);
  }
}

// The key fascia.linear_damping_kg_per_s vanished without a migration, and files that loaded
// before were refused. Renamed keys are read under their new names with a note, lengths converted
// to the multiples that replaced them.
TEST(SceneFile, AFileOfTheEarlierKeysLoadsWithNotesAndConvertedValues) {
  const std::string path = IMASIM_SOURCE_DIR "/tests/data/scene_before_materials.toml";
  const ThoraxSceneParams p = load_scene_file(path);
  EXPECT_EQ(p.patch.fascia.object.linear_damping, Real(0.05));
  EXPECT_EQ(p.patch.fascia.object.angular_damping, Real(0.02));
  EXPECT_EQ(p.anatomy.fascia_width, Real(0.045));
  EXPECT_EQ(p.anatomy.fascia_length, Real(0.14));
  EXPECT_EQ(p.patch.ima_fat.linear_damping, Real(0.04));
  EXPECT_EQ(p.patch.fascia_fat.linear_damping, Real(0.03));
  // 5.5 mm over the vessel-to-wall gap (4 mm deep, 1.25 mm radius), 12 mm over 10 mm of fat.
  EXPECT_NEAR(p.ima_fat_reach, 0.0055 / (0.004 - double(p.patch.vessel.radius)), 1e-12);
  EXPECT_NEAR(p.fascia_fat_reach, 1.2, 1e-12);
  ASSERT_EQ(p.file_notes.size(), 8u);
  EXPECT_EQ(p.file_notes[0].rfind(path + ":11: key 'fascia.linear_damping_kg_per_s' is now "
                                         "'fascia.linear_damping' (k_l of eq. 4",
                                  0),
            0u)
      << p.file_notes[0];
  EXPECT_NE(p.file_notes[4].find(":17: key 'ima_fat.max_length_m' is now 'ima_fat.reach' "),
            std::string::npos)
      << p.file_notes[4];
  EXPECT_NE(p.file_notes[4].find("0.0055 m read as 2"), std::string::npos) << p.file_notes[4];
  // The notes reach the user with the scene's (run and scene check print setup notes).
  EXPECT_EQ(make_thorax_scene(p).setup_notes.size(), 8u);
}

// A quantity that no longer exists is refused naming what replaced it; an old name beside its new
// one, and a length that converts outside the new key's range, are errors too.
TEST(SceneFile, RetiredKeysAreRefusedNamingWhatReplacedThem) {
  try {
    parse_scene(
        "[chest_wall]\nradius_m = 0.1\n[fascia]\nstretch_compliance_m_per_n = 1e-6\n"
        "linear_damping = 0.02\nlinear_damping_kg_per_s = 0.05\n[ima_fat]\n"
        "max_length_m = 0.5\n",
        "old.toml");
    FAIL();
  } catch (const SceneFileError& e) {
    ASSERT_EQ(e.messages().size(), 4u);
    EXPECT_EQ(e.messages()[0].rfind("old.toml:2: key 'chest_wall.radius_m' was retired; instead: "
                                    "the chest wall is laid out from the anatomy",
                                    0),
              0u)
        << e.messages()[0];
    EXPECT_EQ(e.messages()[1].rfind("old.toml:4: key 'fascia.stretch_compliance_m_per_n' was "
                                    "retired; instead: fascia.youngs_modulus_pa and "
                                    "fascia.thickness_m",
                                    0),
              0u)
        << e.messages()[1];
    EXPECT_EQ(e.messages()[2],
              "old.toml:6: key 'fascia.linear_damping_kg_per_s' is the old name of "
              "'fascia.linear_damping', which the file also gives: keep one");
    EXPECT_EQ(
        e.messages()[3].rfind("old.toml:8: key 'ima_fat.max_length_m' (now 'ima_fat.reach'", 0), 0u)
        << e.messages()[3];
    EXPECT_NE(e.messages()[3].find("outside [1, 10]"), std::string::npos) << e.messages()[3];
  }
  try {  // an old key's value out of the new key's range names the old key
    parse_scene("[fascia]\nlinear_damping_kg_per_s = 5\n", "old.toml");
    FAIL();
  } catch (const SceneFileError& e) {
    ASSERT_EQ(e.messages().size(), 1u);
    EXPECT_EQ(e.messages()[0].rfind("old.toml:2: key 'fascia.linear_damping_kg_per_s' (now "
                                    "'fascia.linear_damping'): expected a number in [0, 0.99]",
                                    0),
              0u)
        << e.messages()[0];
  }
}

// Every rename leads to a key that exists; no old name is a key of today.
TEST(SceneFile, EveryRenameLeadsToAKeyAndNoOldNameIsCurrent) {
  auto is_key = [](std::string_view path) {
    for (const SceneKey& k : scene_keys())
      if (k.path == path) return true;
    return false;
  };
  for (const RenamedSceneKey& r : renamed_scene_keys()) {
    EXPECT_TRUE(is_key(r.new_path)) << r.new_path;
    EXPECT_FALSE(is_key(r.old_path)) << r.old_path;
  }
  for (const RetiredSceneKey& r : retired_scene_keys())
    EXPECT_FALSE(is_key(r.old_path)) << r.old_path;
}

TEST(SceneFile, MissingFileIsAClearError) {
  try {
    load_scene_file("/nonexistent/scene.toml");
    FAIL();
  } catch (const SceneFileError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.toml: cannot open"),
              std::string::npos);
  }
}

TEST(SceneFile, SuggestsByEditDistance) {
  EXPECT_EQ(edit_distance("heart", "hart"), 1u);
  EXPECT_EQ(edit_distance("fasica", "fascia"), 2u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
}

TEST(SceneFile, ConsoleSettingsReachTheSession) {
  const ThoraxSceneParams p = parse_scene(
      "[force_fascia]\nstiffness_n_per_m = 450\nfriction = 0.35\n[haptics]\nmotion_scale = 0.2\n"
      "proxy_stiffness_n_per_m = 2500\nproxy_damping_n_s_per_m = 7\n[devices]\nigtl_address = "
      "\"127.0.0.2\"\nright_tool = \"HookTracker\"\n",
      "console.toml");
  EXPECT_EQ(p.console.force[0].stiffness, 450);
  EXPECT_EQ(p.console.igtl_address, "127.0.0.2");
  EXPECT_EQ(p.console.right_tool, "HookTracker");
  EXPECT_EQ(p.console.left_tool, "LeftTool");  // not given: the default
  const ThoraxSceneParams q = parse_scene(
      "[devices]\ngamepad_coag_button = \"left_shoulder\"\ngamepad_speed_m_per_s = 0.1\n"
      "spacemouse_hand = \"left\"\npedal_joystick = \"Footpedal\"\npedal_clutch_button = 32\n",
      "pads.toml");
  EXPECT_EQ(q.console.gamepad_coag_button, "left_shoulder");
  EXPECT_EQ(q.console.gamepad_speed, Real(0.1));
  EXPECT_EQ(q.console.spacemouse_hand, "left");
  EXPECT_EQ(q.console.pedal_joystick, "Footpedal");
  EXPECT_EQ(q.console.pedal_clutch_button, kUnmappedPedalButton);
  const session::SurgicalSession s = session::make_surgical_session(p, {});
  EXPECT_EQ(s.stations[0].arm.motion_scale, Real(0.2));
  EXPECT_EQ(s.params.proxy.stiffness[std::size_t(surgery::Tissue::fascia)], 450);
  // The proxy's coupling is its own, apart from every tissue's k_d.
  EXPECT_EQ(s.params.proxy.coupling_stiffness, 2500);
  EXPECT_EQ(s.params.proxy.coupling_damping, 7);
  EXPECT_EQ(session::make_surgical_session(default_thorax_scene_params(), {})
                .params.proxy.coupling_stiffness,
            surgery::ProxyParams{}.coupling_stiffness);
  // eq. 18's mu is also the friction of the instruments' contacts with that tissue.
  EXPECT_EQ(s.params.proxy.friction[std::size_t(surgery::Tissue::fascia)], Real(0.35));
}

}  // namespace
}  // namespace imasim::scene
