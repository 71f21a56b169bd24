// parkloc demo: a small built-in garage, a ~30 s drive, the full pipeline, a summary and a
// report folder. Needs nothing but the set-up (models ship with it).
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "apps/parkloc/command.h"
#include "apps/parkloc/config_args.h"
#include "apps/parkloc/progress_line.h"
#include "eval/dataset.h"
#include "eval/evaluation.h"
#include "eval/report.h"
#include "eval/tables.h"
#include "sim/dataset_writer.h"
#include "sim/scenario.h"

namespace {

using namespace parkloc;

struct DemoArgs {
  std::string out = "parkloc-demo";
  int max_frames = -1;
  bool paper = false;
  bool quiet = false;
  app::ConfigArgs config;
};

void runDemo(const DemoArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  const std::string data_dir = (std::filesystem::path(a.out) / "data").string();
  app::ProgressLine progress(a.quiet);

  sim::DatasetOptions sim_options;
  sim_options.out_dir = data_dir;
  sim_options.max_frames = a.max_frames;
  sim_options.jobs = 1;
  const sim::DatasetStats stats =
      sim::writeDataset(sim::demoScenario(), sim_options, [&](size_t done, size_t total) {
        progress({"1/2 rendering the demo drive", done, total});
      });
  progress.finish();

  const config::Config config = a.config.load();
  auto spotter = app::makeSpotter(config);
  eval::EvaluationOptions options;
  options.parkloc_options = config.pipeline;
  options.paper_ablation = a.paper;
  options.trajectory_views = 1;
  options.progress = [&](const eval::Progress& p) {
    progress({"2/2 localizing (" + p.stage + ")", p.done, p.total});
  };
  options.title = "parkloc demo";
  options.dataset = data_dir + " (built-in demo garage)";
  options.command = "parkloc demo --out " + a.out + (a.paper ? " --paper" : "");
  const auto workers = app::makeWorkerSpotters(config);
  const eval::EvaluationReport report = eval::evaluateSequences(
      eval::splitSequences(data_dir, "test"), spotter.get(), options, workers.pointers());
  progress.finish();
  eval::writeReport(report, a.out);

  const eval::VariantResult& m = report.main;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << fmt::format(
      "parkloc demo: {} frame sets, {} camera images, {} parking-number "
      "instances labelled\n",
      m.frames, stats.images, stats.instances_per_class[1]);
  std::cout << fmt::format("  frames with a pose   {} / {}\n", m.frames_with_pose, m.frames);
  std::cout << fmt::format("  position error       mean {:.1f} cm, p95 {:.1f} cm, max {:.1f} cm\n",
                           m.error.position_m.mean * 100.0, m.error.position_m.p95 * 100.0,
                           m.error.position_m.max * 100.0);
  std::cout << fmt::format("  yaw error            mean {:.2f} deg, p95 {:.2f} deg\n",
                           m.error.abs_yaw_deg.mean, m.error.abs_yaw_deg.p95);
  std::cout << fmt::format(
      "  level                no level given: estimated, decided on {} / {} frame sets, right "
      "on {}\n",
      m.levels.decided, m.levels.frames, m.levels.decided_right);
  std::cout << fmt::format(
      "  latency per frame    median {:.1f} ms, p95 {:.1f} ms, p99 {:.1f} ms\n",
      m.latency.total_ms.median, m.latency.total_ms.p95, m.latency.total_ms.p99);
  for (const eval::VariantResult& v : report.variants) {
    if (v.key == m.key) continue;
    std::cout << fmt::format("  {:<44} mean {:.1f} cm, p95 {:.1f} cm\n", v.title,
                             v.error.position_m.mean * 100.0, v.error.position_m.p95 * 100.0);
  }
  std::cout << fmt::format("report: {}/report.html, results.json, results.md ({:.0f} s)\n", a.out,
                           seconds);
}

const bool registered = app::registerCommand([](CLI::App& parent) {
  auto args = std::make_shared<DemoArgs>();
  auto* cmd = parent.add_subcommand(
      "demo", "Simulate a small garage drive, localize it and write a report (no input needed)");
  cmd->add_option("--out", args->out, "Report folder (the drive is written to OUT/data)")
      ->capture_default_str();
  cmd->add_option("--max-frames", args->max_frames, "Cut the drive to N frame sets");
  cmd->add_flag("--paper", args->paper,
                "Also run the paper's pipeline and its ablation (full-frame OCR, slower)");
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr");
  args->config.addTo(cmd);
  cmd->callback([args] { runDemo(*args); });
});

}  // namespace
