// parkloc bench SEQUENCE_DIR: latency per four-camera frame set of the full pipeline and, in
// the same run, of the paper's pipeline (full-frame OCR on all four cameras every frame); then
// the drive replayed at its recorded rate (`parkloc run --realtime`), the heavy work inside
// the frame set and on the workers: dropped frame sets and pose ages, also as
// ratios to the paper pipeline's median latency (the machine's speed cancels out).
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <iterator>

#include "apps/parkloc/command.h"
#include "apps/parkloc/config_args.h"
#include "apps/parkloc/progress_line.h"
#include "eval/evaluation.h"
#include "eval/report.h"
#include "eval/tables.h"
#include "io/sequence.h"
#include "run/replay_summary.h"
#include "run/sequence_runner.h"

namespace {

using namespace parkloc;

struct BenchArgs {
  std::string sequence;
  int max_frames = 0;
  std::string out;
  bool no_paper = false;
  bool no_replay = false;
  int replays = 1;
  bool quiet = false;
  app::ConfigArgs config;
};

// Where the heavy work of a replay runs: inside the frame set; full frames on the search worker;
// full frames and the reads at predicted places on workers (localize/search_worker.h).
struct ReplayMode {
  const char* name;
  const char* folder;
  bool search, reads;
};
constexpr ReplayMode kReplayModes[] = {{"in the frame set", "replay_synchronous", false, false},
                                       {"search worker", "replay_worker", true, false},
                                       {"search and read workers", "replay_workers", true, true}};

std::string ratioTo(double paper_median_ms, double ms) {
  return paper_median_ms > 0.0 ? fmt::format("{:.3f}", ms / paper_median_ms) : std::string("-");
}

// One table row: one replay, or the replays of one mode together (run/replay_summary.h).
void printReplayRow(const std::string& label, const std::vector<run::RunSummary>& runs,
                    double paper_median_ms) {
  const run::ReplaySummary r = run::summarizeReplays(runs);
  const auto range = [](double lo, double hi) {
    return lo == hi ? fmt::format("{:.0f}", lo) : fmt::format("{:.0f}-{:.0f}", lo, hi);
  };
  std::string first = "none";
  if (r.posed > 0)
    first = fmt::format("frame set {}, out at {} ms",
                        range(static_cast<double>(r.first_pose_frame_min),
                              static_cast<double>(r.first_pose_frame_max)),
                        range(r.first_pose_ms_min, r.first_pose_ms_max));
  if (r.posed > 0 && r.posed < r.replays)
    first += fmt::format(" ({} of {} replays posed)", r.posed, r.replays);
  std::cout << fmt::format(
      "| {} | {} of {} | {:.1f} ms | {:.1f} ms | {:.1f} ms | {:.1f} ms | {} | {} | {} | "
      "{:.2f} cm | {:.2f} cm |\n",
      label, r.dropped, r.frames, r.age_median_ms, r.age_p95_ms, r.age_p99_ms, r.age_max_ms,
      ratioTo(paper_median_ms, r.age_median_ms), ratioTo(paper_median_ms, r.age_p99_ms), first,
      r.mean_error_m * 100.0, r.p95_error_m * 100.0);
}

// The drive at its recorded rate, `replays` times in each mode. When the workers' texts arrive
// decides which frame set fuses them, so one replay is one draw: with several, the modes take
// turns (machine state drifts alike for all) and a row per mode gives the replays together
// (ages pooled, errors averaged, the first pose's range).
void replay(const BenchArgs& a, const config::Config& config, ocr::TextSpotter& spotter,
            const eval::EvaluationReport& report) {
  double paper_median = 0.0;
  for (const eval::VariantResult& v : report.variants)
    if (v.key == "paper_spotting") paper_median = v.latency.total_ms.median;
  const io::Sequence sequence(a.sequence);
  const std::filesystem::path out =
      a.out.empty() ? std::filesystem::temp_directory_path() / "parkloc-bench-replay"
                    : std::filesystem::path(a.out);
  std::cout << "\nreal-time replay at the recorded rate (pose age: output time less capture "
               "time; ratios to the paper pipeline's median)\n\n"
               "| heavy work | dropped | age median | p95 | p99 | max | median / paper | "
               "p99 / paper | first pose | error mean | error p95 |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::vector<std::vector<run::RunSummary>> runs(std::size(kReplayModes));
  for (int r = 0; r < a.replays; ++r)
    for (size_t m = 0; m < std::size(kReplayModes); ++m) {
      const ReplayMode& mode = kReplayModes[m];
      run::RunOptions options;
      options.pipeline = config.pipeline;
      options.pipeline.realtime.background_search = mode.search;
      options.pipeline.realtime.background_reads = mode.reads;
      options.realtime = true;
      options.max_frames = static_cast<size_t>(a.max_frames);
      options.out_dir =
          (out / (a.replays > 1 ? fmt::format("{}_{}", mode.folder, r + 1) : mode.folder)).string();
      config::Config worker_config = config;
      worker_config.pipeline = options.pipeline;
      const app::WorkerSpotterSet workers = app::makeWorkerSpotters(worker_config);
      runs[m].push_back(run::runSequence(sequence, &spotter, options, workers.pointers()));
      printReplayRow(a.replays > 1 ? fmt::format("{} (replay {})", mode.name, r + 1) : mode.name,
                     {runs[m].back()}, paper_median);
    }
  if (a.replays > 1)
    for (size_t m = 0; m < std::size(kReplayModes); ++m)
      printReplayRow(fmt::format("**{}, {} replays**", kReplayModes[m].name, a.replays), runs[m],
                     paper_median);
  if (paper_median > 0.0)
    std::cout << fmt::format("paper pipeline median {:.1f} ms per frame set\n", paper_median);
}

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
  const auto workers = app::makeWorkerSpotters(config);
  const eval::EvaluationReport report =
      eval::evaluateSequences({a.sequence}, spotter.get(), options, workers.pointers());
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
  if (!a.no_replay) replay(a, config, *spotter, report);
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
  cmd->add_flag("--no-replay", args->no_replay,
                "Skip the real-time replays (the drive at its recorded rate, in three modes)");
  cmd->add_option("--replays", args->replays,
                  "Replays per mode, taking turns; with more than one, a row per mode gives "
                  "them together")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr");
  args->config.addTo(cmd);
  cmd->callback([args] { runBench(*args); });
});

}  // namespace
