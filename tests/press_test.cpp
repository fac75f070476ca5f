// `imasim press`: the hook pressed into a tissue of the built-in scene and held at each
// depth, the force the device receives beside eq. 17's k_d d. On the rigid surfaces (the chest
// wall, the heart held at its static phase) the tool's proxy stops at the surface and the hand
// feels eq. 17 at the surface's k_d and the device's depth past the plane where it stops the
// proxy (docs/haptics.md): within 2 % for the wall (k_d 1000 N/m) and the heart (400 N/m), whose
// curved surface lets the tool slide a little within its friction cone. On the fascia the
// membrane pushes back, more the deeper it is pressed. Release only, label `physics`.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_process.hpp"

namespace {

using imasim::test::Finished;
using imasim::test::run_imasim;
using imasim::test::test_err_file;

const std::string kDir = ::testing::TempDir();

nlohmann::json press(const std::string& args) {
  const Finished f = run_imasim("press --json " + args, test_err_file(kDir, "imasim_press"));
  EXPECT_EQ(f.exit_code, 0) << f.err;
  return nlohmann::json::parse(f.out);
}

void expect_the_table(const nlohmann::json& out, double k_d) {
  EXPECT_EQ(out["k_d_n_per_m"].get<double>(), k_d);
  ASSERT_EQ(out["depths"].size(), 5u);
  double depth_mm = 0;
  for (const nlohmann::json& row : out["depths"]) {
    depth_mm += 1;
    EXPECT_NEAR(row["depth_mm"].get<double>(), depth_mm, 1e-3);
    EXPECT_NEAR(row["law_n"].get<double>(), std::min(5.0, k_d * depth_mm * 1e-3), 1e-6);
    EXPECT_NEAR(row["force_n"].get<double>(), row["law_n"].get<double>(),
                0.02 * row["law_n"].get<double>())
        << "at " << depth_mm << " mm";
  }
}

TEST(Press, TheChestWallStopsTheToolAndTheHandFeelsTheTablesForce) {
  const nlohmann::json out = press("--tissue wall");
  EXPECT_EQ(out["tissue"], "wall");
  expect_the_table(out, 1000);
  for (const nlohmann::json& row : out["depths"])
    EXPECT_NEAR(row["tool_depth_mm"].get<double>(), 0, 0.05);  // the tool stays on the surface
}

TEST(Press, TheHeldHeartStopsTheToolAndTheHandFeelsTheTablesForce) {
  const nlohmann::json out = press("--tissue heart");
  EXPECT_EQ(out["tissue"], "heart");
  expect_the_table(out, 400);
}

// The membrane gives way and pushes back: the tool goes in with the device, and the force grows
// with every millimetre (measured 0.0040, 0.0063, 0.0093, 0.0142, 0.0224 N at 1-5 mm). It is
// within 30 % of the table's k_d d: the fascia's k_d is the stiffness the hook's tip
// meets, 4.3 N/m (measured 94, 73, 72, 83, 104 %; with the old 300 N/m, 1.3-1.5 %).
TEST(Press, TheFasciaPushesBackMoreTheDeeperItIsPressedAndAsTheTableSays) {
  const nlohmann::json out = press("--tissue fascia --depth-mm 1,2,3,4,5");
  ASSERT_EQ(out["depths"].size(), 5u);
  double previous = 0;
  for (const nlohmann::json& row : out["depths"]) {
    EXPECT_GT(row["force_n"].get<double>(), previous) << row.dump();
    previous = row["force_n"].get<double>();
    EXPECT_GT(row["tool_depth_mm"].get<double>(), 0.5 * row["depth_mm"].get<double>());
    EXPECT_NEAR(row["force_n"].get<double>(), row["law_n"].get<double>(),
                0.3 * row["law_n"].get<double>())
        << row.dump();
  }
}

std::string scene_file(const std::string& name, const std::string& text) {
  const std::string path = kDir + "/imasim_press_" + name + ".toml";
  std::ofstream(path) << text;
  return path;
}

// The fascia solved implicitly (`fascia.solver = "implicit"`), the hook's proxy a body of its
// Newton solve (scene/implicit_mesh_scene.hpp): at the toe's modulus throughout
// (linear_modulus_pa = youngs_modulus_pa) it presses as the XPBD fascia does with the same
// frictionless hook (the surfaces under it with their friction in both), within 5 % (measured
// 1.7, 2.6, 4.1 % at 1, 3, 5 mm; 0.2-2.1 % with the implicit fascia's surfaces frictionless; with
// eq. 18's mu = 0.2 on the hook too, 4.0, 4.3, 6.3 %: docs/physics.md); with the fascia's law
// (2.65 MPa past 5 % strain) it is no softer, and stiffer where the press stretches it past its
// toe (measured 2.1 times at 5 mm).
TEST(Press, TheImplicitFasciaPressesAsTheXpbdFasciaAtTheToesModulus) {
  const std::string depths = "--tissue fascia --depth-mm 1,3,5 --scene ";
  const nlohmann::json xpbd =
      press(depths + scene_file("frictionless", "[force_fascia]\nfriction = 0.0\n"));
  const nlohmann::json toe =
      press(depths + scene_file("toe",
                                "[fascia]\nsolver = \"implicit\"\nlinear_modulus_pa = 1e5\n"
                                "[force_fascia]\nfriction = 0.0\n"));
  const nlohmann::json law = press(depths + scene_file("law", "[fascia]\nsolver = \"implicit\"\n"));
  ASSERT_EQ(toe["depths"].size(), 3u);
  ASSERT_EQ(law["depths"].size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const double reference = xpbd["depths"][k]["force_n"].get<double>();
    const double at_toe = toe["depths"][k]["force_n"].get<double>();
    EXPECT_NEAR(at_toe, reference, 0.05 * reference) << toe["depths"][k].dump();
    EXPECT_GE(law["depths"][k]["force_n"].get<double>(), 0.99 * at_toe) << law["depths"][k].dump();
  }
  EXPECT_GT(law["depths"][2]["force_n"].get<double>(),
            1.5 * toe["depths"][2]["force_n"].get<double>());
}

// The fat's columns (fascia_fat.resists_compression, off by default; docs/physics.md): the
// layer under the fascia pushes back, so the hook meets far more than the membrane alone at every
// depth (measured 0.0316, 0.1072, 0.2332 N against 0.0040, 0.0093, 0.0224 N at 1, 3, 5 mm: 7-10
// times) and more the deeper it goes, the tool still going in with the device.
TEST(Press, TheFatsColumnsPushTheFasciaBack) {
  const std::string depths = "--tissue fascia --depth-mm 1,3,5";
  const nlohmann::json plain = press(depths);
  const nlohmann::json held = press(
      depths + " --scene " + scene_file("columns", "[fascia_fat]\nresists_compression = true\n"));
  ASSERT_EQ(plain["depths"].size(), 3u);
  ASSERT_EQ(held["depths"].size(), 3u);
  double previous = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    const nlohmann::json& row = held["depths"][k];
    EXPECT_GT(row["force_n"].get<double>(), 3 * plain["depths"][k]["force_n"].get<double>())
        << row.dump();
    EXPECT_GT(row["force_n"].get<double>(), previous) << row.dump();
    previous = row["force_n"].get<double>();
    EXPECT_GT(row["tool_depth_mm"].get<double>(), 0.5 * row["depth_mm"].get<double>());
  }
}

// The vessel on its fat's columns (tissue/fat_support.hpp) is held across them as well as along
// them, so it does not roll away from the hook's tip: it pushes back more at each depth to 1.5
// mm, along the press (measured 0.0262, 0.0344, 0.0429 N). Held along its columns only, the XPBD
// vessel of 40 rings rolled aside at 1.5 mm (0.0023 N there against 0.0091 N at 1 mm).
TEST(Press, TheVesselOnItsColumnsIsHeldAcrossThemAndPushesBackDeeper) {
  const nlohmann::json held = press("--tissue ima --depth-mm 0.5,1,1.5");
  ASSERT_EQ(held["depths"].size(), 3u);
  double previous = 0;
  for (const nlohmann::json& row : held["depths"]) {
    const double force = row["force_n"].get<double>();
    EXPECT_GT(force, 1.2 * previous) << row.dump();
    EXPECT_GT(row["force_along_press_n"].get<double>(), 0.9 * force) << row.dump();
    EXPECT_GT(row["tool_depth_mm"].get<double>(), 0.9 * row["depth_mm"].get<double>());
    previous = force;
  }
}

// The vessel, solved by the implicit step of its rows (the default, scene/implicit_mesh_scene.hpp)
// on its fat's columns, pushes back within 30 % of the table's k_d d at 1 and 1.5 mm: its k_d is
// the stiffness of a beam on its fat in series with its tensed wall (34 N/m, docs/haptics.md),
// the model the columns discretise. Measured 1.01 and 0.84 times. Without its columns it gives a
// tenth (0.12 times at 1 mm).
TEST(Press, TheVesselPushesBackAsTheTableSays) {
  const nlohmann::json out = press("--tissue ima --depth-mm 1,1.5");
  EXPECT_EQ(out["k_d_n_per_m"].get<double>(), 34.0);
  ASSERT_EQ(out["depths"].size(), 2u);
  for (const nlohmann::json& row : out["depths"]) {
    EXPECT_NEAR(row["force_n"].get<double>(), row["law_n"].get<double>(),
                0.3 * row["law_n"].get<double>())
        << row.dump();
    EXPECT_GT(row["force_along_press_n"].get<double>(), 0.9 * row["force_n"].get<double>());
  }
}

double press_at(const std::string& depths, const std::string& scene, std::size_t k) {
  return press("--tissue ima --depth-mm " + depths +
               (scene.empty() ? "" : " --scene " + scene))["depths"][k]["force_n"]
      .get<double>();
}

// The press is the vessel's, not its mesh's nor its solver's: with twice the rings (and the fat's
// strands, one a face) it is within 5 % (measured 3.8 and 3.0 % more; 40 rings gave 12 and 17 %
// less), and the XPBD vessel solved finely (128 substeps, the vessel in every one) meets the
// implicit step's press within 10 % (measured 6.5 and 4.6 % less; at 256 substeps 5 % more).
TEST(Press, TheVesselsPressIsConvergedInItsMeshAndAsFinelySolvedXpbdPresses) {
  const std::string finer =
      scene_file("vessel_160_rings", "[vessel]\ncoarse_rings = 160\nfine_rings = 320\n");
  const std::string xpbd =
      scene_file("vessel_xpbd_fine",
                 "[vessel]\nsolver = \"xpbd\"\n[solver]\nsubsteps = 128\ncoarse_stride = 1\n"
                 "coarse_sweeps = 1\n");
  for (std::size_t k = 0; k < 2; ++k) {
    const double implicit = press_at("1,1.5", "", k);
    EXPECT_NEAR(press_at("1,1.5", finer, k), implicit, 0.05 * implicit) << "depth " << k;
    EXPECT_NEAR(press_at("1,1.5", xpbd, k), implicit, 0.1 * implicit) << "depth " << k;
  }
}

// Why the XPBD vessel (`vessel.solver = "xpbd"`) gives a fifth of its k_d: not a press cut short,
// the solve. Held five times longer (--hold-s 2) the force is the same (measured 0.0064366 N
// both); with the vessel stepped in every substep (`vessel.coarse = false`) instead of the coarse
// band's eight, the same press pushes back 3.0 times as hard (0.0196 N): the coarse substep's
// inertia, m / h^2, softens the wall's stiff rows (docs/physics.md).
TEST(Press, TheXpbdVesselsShortfallIsItsSolvesNotTheHolds) {
  const std::string coarse = scene_file("vessel_xpbd", "[vessel]\nsolver = \"xpbd\"\n");
  const double base = press_at("1", coarse, 0);
  const double held =
      press("--hold-s 2 --tissue ima --depth-mm 1 --scene " + coarse)["depths"][0]["force_n"]
          .get<double>();
  EXPECT_NEAR(held, base, 0.02 * base);
  const double every_substep = press_at(
      "1", scene_file("vessel_every_substep", "[vessel]\nsolver = \"xpbd\"\ncoarse = false\n"), 0);
  EXPECT_GT(every_substep, 2 * base);
  EXPECT_LT(base, 0.5 * press_at("1", "", 0));
}

TEST(Press, RefusesAnUnknownTissueAndADepthPastTheProxysBound) {
  const Finished bone = run_imasim("press --tissue bone", test_err_file(kDir, "imasim_press"));
  EXPECT_EQ(bone.exit_code, 105);  // CLI11's validation error
  EXPECT_NE(bone.err.find("--tissue"), std::string::npos) << bone.err;
  const Finished deep =
      run_imasim("press --tissue fascia --depth-mm 20", test_err_file(kDir, "imasim_press"));
  EXPECT_NE(deep.exit_code, 0);
  EXPECT_NE(deep.err.find("--depth-mm"), std::string::npos) << deep.err;
  const Finished brief =
      run_imasim("press --tissue fascia --hold-s 0.1", test_err_file(kDir, "imasim_press"));
  EXPECT_EQ(brief.exit_code, 105);
  EXPECT_NE(brief.err.find("--hold-s"), std::string::npos) << brief.err;
}

}  // namespace
