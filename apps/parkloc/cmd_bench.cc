// parkloc bench SEQUENCE_DIR: latency per four-camera frame set of the full pipeline and, in
// the same run, of the paper's pipeline (full-frame OCR on all four cameras every frame).
#include <fmt/format.h>

#include <iostream>

#include "apps/parkloc/command.h"
#include "apps/parkloc/config_args.h"
#include "apps/parkloc/progress_line.h"
#include "eval/evaluation.h"
#include "eval/report.h"
#include "eval/tables.h"

namespace {

using namespace parkloc;

struct BenchArgs {
  std::string sequence;
  int max_frames = 0;
  std::string out;
  bool no_paper = false;
  bool quiet = false;
  app::ConfigArgs config;
};

void runBench(const BenchArgs& a) {
  const config::Config config = a.config.load();
  auto spotter = app::makeSpotter(config);
  app::ProgressLine progress(a.quiet);
  eval::EvaluationOptions options;
  options.parkloc_options = config.pipeline;
  options.paper_ablation = false;
  options.paper_own_spotting = !a.no_paper;
  options.oracle = false;
  options.odometry_only = false;
  options.max_frames_per_sequence = static_cast<size_t>(a.max_frames);
  options.progress = [&](const eval::Progress& p) { progress(p); };
  options.title = "parkloc bench";
  options.dataset = a.sequence;
  options.command = "parkloc bench " + a.sequence;
  const eval::EvaluationReport report =
      eval::evaluateSequences({a.sequence}, spotter.get(), options);
  progress.finish();
  std::cout << fmt::format("{} frame sets of {}, {} cameras each, engine {}\n", report.main.frames,
                           a.sequence, 4, spotter->name());
  std::cout << eval::tableMarkdown(eval::latencyTable(report.variants));
  for (const eval::VariantResult& v : report.variants) {
    std::cout << fmt::format(
        "{}: median {:.1f} ms, p95 {:.1f} ms, p99 {:.1f} ms per frame set; position error mean "
        "{:.1f} cm ({} / {} frames with a pose)\n",
        v.title, v.latency.total_ms.median, v.latency.total_ms.p95, v.latency.total_ms.p99,
        v.error.position_m.mean * 100.0, v.frames_with_pose, v.frames);
  }
  if (!a.out.empty()) {
    eval::writeReport(report, a.out);
    std::cout << "wrote " << a.out << "/report.html, results.json, results.md\n";
  }
}

const bool registered = app::registerCommand([](CLI::App& parent) {
  auto args = std::make_shared<BenchArgs>();
  auto* cmd = parent.add_subcommand(
      "bench", "Latency per frame set: full pipeline and the paper's pipeline, per stage");
  cmd->add_option("sequence", args->sequence, "Sequence folder (as parkloc simulate writes)")
      ->required();
  cmd->add_option("--max-frames", args->max_frames, "At most N frame sets (0: all)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--out", args->out, "Also write a report folder");
  cmd->add_flag("--no-paper", args->no_paper, "Only the full pipeline");
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr");
  args->config.addTo(cmd);
  cmd->callback([args] { runBench(*args); });
});

}  // namespace
