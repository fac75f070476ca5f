#include "commands.hpp"

namespace imasim::cli {

Commands add_commands(CLI::App& app) {
  app.require_subcommand(1);
  Commands c;
  c.cloth = add_cloth_command(app);
  c.run = add_run_command(app);
  c.scene = add_scene_command(app);
  c.haptics_bench = add_haptics_bench_command(app);
  c.device_emulator = add_device_emulator_command(app);
  c.devices = add_devices_command(app);
  c.stats = add_stats_command(app);
  c.sai = add_sai_command(app);
  c.heatmap = add_heatmap_command(app);
  c.history = add_history_command(app);
  c.press = add_press_command(app);
  c.experiment = add_experiment_command(app);
  c.demo = add_demo_command(app);
  c.render = add_render_command(app);
  c.window = add_window_command(app);
  return c;
}

int run_chosen_command(const CLI::App& app, const Commands& c) {
  if (app.got_subcommand("cloth")) return run_cloth_command(*c.cloth);
  if (app.got_subcommand("run")) return run_run_command(*c.run);
  if (app.got_subcommand("scene")) return run_scene_command(*c.scene);
  if (app.got_subcommand("haptics-bench")) return run_haptics_bench_command(*c.haptics_bench);
  if (app.got_subcommand("device-emulator")) return run_device_emulator_command(*c.device_emulator);
  if (app.got_subcommand("devices")) return run_devices_command(*c.devices);
  if (app.got_subcommand("stats")) return run_stats_command(*c.stats);
  if (app.got_subcommand("sai")) return run_sai_command(*c.sai);
  if (app.got_subcommand("heatmap")) return run_heatmap_command(*c.heatmap);
  if (app.got_subcommand("history")) return run_history_command(*c.history);
  if (app.got_subcommand("press")) return run_press_command(*c.press);
  if (app.got_subcommand("experiment")) return run_experiment_command(*c.experiment);
  if (app.got_subcommand("demo")) return run_demo_command(*c.demo);
  if (app.got_subcommand("render")) return run_render_command(*c.render);
  if (app.got_subcommand("window")) return run_window_command(*c.window);
  return 0;
}

}  // namespace imasim::cli
