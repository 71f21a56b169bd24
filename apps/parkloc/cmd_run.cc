// `parkloc run`: localize the vehicle along one sequence folder.
#include <fmt/format.h>

#include <iostream>
#include <cstdint>
#include <memory>

#include "apps/parkloc/command.h"
#include "apps/parkloc/config_args.h"
#include "apps/parkloc/progress_line.h"
#include "io/sequence.h"
#include "run/sequence_runner.h"

namespace {

struct RunArgs {
  std::string sequence;
  std::string out;
  std::string calib, map, odometry;
  std::string video;
  std::string level;
  bool oracle = false, paper = false;
  bool no_afm = false, no_mcrp = false, no_mcap = false, no_odometry = false;
  size_t max_frames = 0;
  double map_noise = 0.0;
  uint64_t map_noise_seed = 0;
  bool quiet = false;
  bool realtime = false, background_search = false, background_reads = false;
  std::vector<std::string> inject;
  parkloc::app::ConfigArgs config;
};

void run(const RunArgs& a) {
  using namespace parkloc;
  const config::Config config = a.config.load();  // a bad file fails before any work
  const io::Sequence sequence(a.sequence, a.calib, a.map, a.odometry);
  for (const auto& w : sequence.warnings()) std::cerr << "parkloc: warning: " << w << "\n";

  run::RunOptions options;
  options.pipeline = config.pipeline;
  if (a.paper) options.pipeline = localize::PipelineOptions::paper(options.pipeline);
  if (a.no_afm) options.pipeline.paper_modules.afm = false;
  if (a.no_mcrp) options.pipeline.paper_modules.mcrp = false;
  if (a.no_mcap) options.pipeline.paper_modules.mcap = false;
  if (a.no_odometry) options.pipeline.motion.use_odometry = false;
  // Without a hint (--level, or the configuration's) the pipeline estimates the level.
  if (!a.level.empty()) options.pipeline.level = a.level;
  options.oracle = a.oracle;
  options.max_frames = a.max_frames;
  options.map_noise = {a.map_noise, a.map_noise_seed};
  options.out_dir = a.out;
  options.video_path = a.video;
  options.realtime = a.realtime;
  if (a.background_search) options.pipeline.realtime.background_search = true;
  if (a.background_reads) options.pipeline.realtime.background_reads = true;
  if (!a.inject.empty()) {
    options.faults = run::parseFaults(a.inject);
    std::cerr << "parkloc: injecting faults:\n" << run::describeFaults(options.faults) << "\n";
  }
  if (!a.paper && !a.no_odometry && sequence.odometry().empty())
    std::cerr << "parkloc: warning: no odometry: the filter predicts a random walk\n";

  std::unique_ptr<ocr::TextSpotter> spotter;
  app::WorkerSpotterSet workers;
  if (!a.oracle) spotter = app::makeSpotter(config);
  if (!a.oracle) {
    config::Config worker_config = config;
    worker_config.pipeline = options.pipeline;
    workers = app::makeWorkerSpotters(worker_config);
  }
  app::ProgressLine progress(a.quiet);
  options.progress = [&](size_t done, size_t total) {
    progress({"run " + sequence.dir(), done, total});
  };
  const auto s = run::runSequence(sequence, spotter.get(), options, workers.pointers());
  progress.finish();

  std::cout << fmt::format("frames {}  with pose {}  first fix {}\n", s.frames, s.frames_with_pose,
                           s.first_fix_time ? fmt::format("{:.3f} s", *s.first_fix_time) : "none");
  std::cout << fmt::format("pose after the first fix on {} of {} frames\n", s.poses_after_first_fix,
                           s.frames_after_first_fix);
  std::string statuses;
  for (const auto& [name, n] : s.status_counts) statuses += fmt::format("  {} {}", name, n);
  std::cout << "status" << statuses << "\n";
  if (s.has_truth)
    std::cout << fmt::format(
        "position error mean {:.4f} m  p95 {:.4f} m  max {:.4f} m  frames over 0.5 m {}\n"
        "yaw error mean {:.3f} deg\n",
        s.mean_position_error_m, s.p95_position_error_m, s.max_position_error_m,
        s.frames_over_half_metre, s.mean_yaw_error_deg);
  std::cout << fmt::format("latency per frame set median {:.2f} ms  p99 {:.2f} ms\n",
                           s.latency_median_ms, s.latency_p99_ms);
  if (a.realtime)
    std::cout << fmt::format(
        "real time: {} frame sets dropped of {}; pose age median {:.1f} ms  p95 {:.1f} ms  "
        "p99 {:.1f} ms  max {:.1f} ms; first pose at frame set {}\n",
        s.frames_dropped, s.frames + s.frames_dropped, s.pose_age_median_ms, s.pose_age_p95_ms,
        s.pose_age_p99_ms, s.pose_age_max_ms,
        s.first_pose_frame ? fmt::format("{} (out {:.0f} ms after the first frame set)",
                                         *s.first_pose_frame, s.first_pose_output_ms)
                           : "none");
  if (s.frames_skipped_by_faults)
    std::cout << fmt::format("{} frame sets skipped by fault injection\n",
                             s.frames_skipped_by_faults);
  if (s.frames_with_warnings)
    std::cout << fmt::format("{} frames with warnings (see frames.jsonl)\n",
                             s.frames_with_warnings);
  std::cout << "wrote " << a.out << "/trajectory.tum, " << a.out << "/frames.jsonl"
            << (a.video.empty() ? "" : ", " + a.video) << "\n";
}

const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = parent.add_subcommand("run", "Localize the vehicle along a sequence folder");
  cmd->add_option("sequence", args->sequence, "Sequence folder (parkloc simulate layout)")
      ->required();
  cmd->add_option("--out", args->out, "Output folder (trajectory.tum, frames.jsonl)")->required();
  cmd->add_option("--calib", args->calib, "Rig calibration (default SEQUENCE/calib.yaml)");
  cmd->add_option("--map", args->map, "HD map (default SEQUENCE/map.geojson)");
  cmd->add_option("--odometry", args->odometry,
                  "Wheel odometry CSV (default SEQUENCE/odometry.csv)");
  cmd->add_option("--video", args->video, "Write an annotated mp4 here");
  cmd->add_option("--level", args->level,
                  "A hint: the garage level the drive starts on (default: estimated)");
  cmd->add_flag("--oracle", args->oracle, "Text from the ground-truth labels (oracle OCR)");
  cmd->add_flag("--paper", args->paper,
                "The paper's pipeline: text centre + homography, AFM, MCRP, MCAP, no odometry");
  cmd->add_flag("--no-afm", args->no_afm, "Turn the box-plot anomaly filter off");
  cmd->add_flag("--no-mcrp", args->no_mcrp, "One camera per landmark");
  cmd->add_flag("--no-mcap", args->no_mcap, "Only the nearest landmark");
  cmd->add_flag("--no-odometry", args->no_odometry, "Ignore wheel odometry");
  cmd->add_option("--max-frames", args->max_frames, "Process at most N frame sets (0: all)");
  cmd->add_option("--map-noise", args->map_noise,
                  "Localize on the map perturbed by this survey error (metres, 1 sigma per axis; "
                  "see map/map_noise.h); the error is measured against the truth")
      ->check(CLI::Range(0.0, parkloc::map::kMaxPositionSigmaM));
  cmd->add_option("--map-noise-seed", args->map_noise_seed, "Seed of the map perturbation")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--quiet", args->quiet, "No progress line");
  cmd->add_flag("--realtime", args->realtime,
                "Feed the frame sets at their recorded rate; a frame set that comes while the "
                "previous one runs is dropped; report dropped frame sets and pose ages");
  cmd->add_flag("--background-search", args->background_search,
                "Full-frame spotting on a worker thread (pipeline.realtime.background_search)");
  cmd->add_flag("--background-reads", args->background_reads,
                "Reads at predicted places on a worker thread (pipeline.realtime.background_reads)");
  cmd->add_option("--inject", args->inject,
                  "Inject faults, e.g. dark:front:3-8,drop:0.1 (see run/fault_injection.h)")
      ->allow_extra_args(false);
  args->config.addTo(cmd);
  cmd->callback([args] { run(*args); });
});

}  // namespace
