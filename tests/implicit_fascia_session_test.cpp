// The example session (examples/open_fascia.script: the flap lifted by the forceps, the hook
// cutting under the pedal) with the fascia solved implicitly (`fascia.solver = "implicit"`), as
// `imasim run` plays it: the tools and the fascia meet in one solver each step, so neither leaves
// fascia inside a tool or off the jaws' holds for the other to find. Measured: 3 particles put
// out of a tool after a step in 2060 (the XPBD fascia's 1; 2069 before the fascia stopped the
// tools in the XPBD step and the wall's stops joined the implicit step), 3 steps unsolved
// (3.2e-6 N at most; 14 and 0.012 N before the contacts' friction and 40 Newton iterations a
// step at most, 43 and 0.22 N before the stops). Release only, label `physics`.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_process.hpp"

namespace {

using imasim::test::Finished;
using imasim::test::run_imasim;
using imasim::test::test_err_file;

TEST(ImplicitFasciaSession, TheExampleSessionCutsWithTheToolsAndTheFasciaInOneSolve) {
  const std::string dir = ::testing::TempDir();
  const std::string scene = dir + "/imasim_implicit_session.toml";
  std::ofstream(scene) << "[fascia]\nsolver = \"implicit\"\n";
  const Finished f = run_imasim("run --headless --threads 1 --json --script " IMASIM_SOURCE_DIR
                                "/examples/open_fascia.script --scene " +
                                    scene,
                                test_err_file(dir, "imasim_implicit_session"));
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const nlohmann::json out = nlohmann::json::parse(f.out);
  EXPECT_EQ(out["status"], "ok");
  EXPECT_EQ(out["fascia_solver"], "implicit");
  const double steps = out["steps"].get<double>();
  // The cuts go through (the XPBD fascia: 1215 edges, 31 strands).
  EXPECT_GT(out["fascia_edges_cut"].get<int>(), 700);
  EXPECT_GT(out["strands_cut"].get<int>(), 25);
  // A handful of particles put out of a tool over the run, not one a step.
  EXPECT_LE(out["warnings"]["missed_tool_contacts"].get<double>(), 0.005 * steps);
  // Under 1 % of the steps end unsolved, and none far from balance.
  EXPECT_LT(out["fascia_unsolved_steps"].get<double>(), 0.01 * steps);
  EXPECT_LT(out["fascia_largest_residual_n"].get<double>(), 0.05);
  EXPECT_GT(out["fascia_newton_iterations_per_step"].get<double>(), 1);
  EXPECT_GT(out["fascia_factorizations_per_step"].get<double>(), 0.5);  // measured 6.0
  // Measured: 2.0 of the 6.0 for the active set (the rest the kept matrix too slow), 2.87 of the
  // 9.44 Newton steps a step cut short by the line search.
  EXPECT_GT(out["fascia_active_set_factorizations_per_step"].get<double>(), 0.5);
  EXPECT_LT(out["fascia_active_set_factorizations_per_step"].get<double>(),
            out["fascia_factorizations_per_step"].get<double>());
  EXPECT_GT(out["fascia_shortened_iterations_per_step"].get<double>(), 0.5);
  EXPECT_LT(out["fascia_shortened_iterations_per_step"].get<double>(),
            out["fascia_newton_iterations_per_step"].get<double>());
  EXPECT_GT(out["fascia_refits"].get<int>(), 0);  // every cut rebuilds the implicit step
}

}  // namespace
