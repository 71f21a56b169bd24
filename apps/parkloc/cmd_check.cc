// `parkloc check consistency RUN_DIR --truth poses.tum`: is the covariance a run reported
// honest (NEES against the chi-square bound), and did the integrity flag come in time?
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "apps/parkloc/command.h"
#include "common/error.h"
#include "eval/consistency.h"
#include "io/tum.h"

namespace {

struct ConsistencyArgs {
  std::string run_dir;
  std::string truth;
  std::string per_frame_csv;
  std::string json_out;
  parkloc::eval::ConsistencyOptions options;
};

void runConsistency(const ConsistencyArgs& a) {
  using namespace parkloc;
  namespace fs = std::filesystem;
  std::string frames_path = a.run_dir;
  if (fs::is_directory(frames_path)) frames_path = (fs::path(a.run_dir) / "frames.jsonl").string();
  const auto frames = eval::loadReportedFrames(frames_path);
  const auto truth = io::loadTum(a.truth);
  const auto r = eval::evaluateConsistency(frames, truth, a.options);
  if (r.frames.empty())
    throw InputError(fmt::format("check consistency: no frame of {} has a pose within {}",
                                 frames_path, a.truth));
  const double n = static_cast<double>(r.frames.size());
  std::cout << fmt::format(
      "frames {}  with pose and truth {}  without pose {}  unanswered after the first pose {}\n",
      r.frames_total, r.frames.size(), r.frames_without_pose, r.frames_unanswered);
  std::cout << fmt::format("position error mean {:.3f} m  max {:.3f} m\n", r.mean_position_error_m,
                           r.max_position_error_m);
  std::cout << fmt::format(
      "NEES (x, y, yaw) inside the bound {:.3f}: {} of {} frames ({:.1f} %)  mean {:.2f}  "
      "median {:.2f} (3 when consistent)\n",
      a.options.nees_bound, r.inside_bound, r.frames.size(), 100.0 * r.fraction_inside, r.mean_nees,
      r.median_nees);
  std::cout << fmt::format(
      "integrity: protection level {:.2f} x sigma_max (mean {:.3f} m), alert limit {:.2f} m\n"
      "  alerts {} ({:.1f} %)  frames over the alert limit {}  missed detections {}  "
      "false alerts {}\n  episodes over the limit {}  flagged late or never {}\n",
      a.options.protection_k, r.mean_protection_level_m, a.options.alert_limit_m, r.alerts,
      100.0 * static_cast<double>(r.alerts) / n, r.over_alert_limit, r.missed_detections,
      r.false_alerts, r.episodes, r.late_episodes);
  std::cout << fmt::format("verdict: covariance {} (>= 90 % inside), integrity {}\n",
                           r.fraction_inside >= 0.9 ? "honest" : "NOT honest",
                           r.missed_detections == 0 ? "no missed detection" : "MISSED DETECTIONS");
  if (!a.per_frame_csv.empty()) {
    std::ofstream out(a.per_frame_csv);
    if (!out) throw IoError(fmt::format("check consistency: cannot write {}", a.per_frame_csv));
    out << "timestamp,dx,dy,dyaw,position_error_m,nees,protection_level_m,alert,missed\n";
    for (const auto& f : r.frames)
      out << fmt::format("{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.4f},{:.6f},{},{}\n", f.timestamp,
                         f.error.x(), f.error.y(), f.error.z(), f.position_error_m, f.nees,
                         f.protection_level_m, int(f.alert), int(f.missed));
  }
  if (!a.json_out.empty()) {
    nlohmann::json j = {{"frames", r.frames_total},
                        {"frames_with_pose_and_truth", r.frames.size()},
                        {"frames_without_pose", r.frames_without_pose},
                        {"frames_unanswered", r.frames_unanswered},
                        {"mean_position_error_m", r.mean_position_error_m},
                        {"max_position_error_m", r.max_position_error_m},
                        {"nees_bound", a.options.nees_bound},
                        {"inside_bound", r.inside_bound},
                        {"fraction_inside", r.fraction_inside},
                        {"mean_nees", r.mean_nees},
                        {"median_nees", r.median_nees},
                        {"protection_k", a.options.protection_k},
                        {"alert_limit_m", a.options.alert_limit_m},
                        {"alerts", r.alerts},
                        {"over_alert_limit", r.over_alert_limit},
                        {"missed_detections", r.missed_detections},
                        {"false_alerts", r.false_alerts},
                        {"episodes", r.episodes},
                        {"late_episodes", r.late_episodes}};
    std::ofstream out(a.json_out);
    if (!out) throw IoError(fmt::format("check consistency: cannot write {}", a.json_out));
    out << j.dump(2) << "\n";
  }
}

const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto* cmd = parent.add_subcommand("check", "Reliability checks of a run");
  cmd->require_subcommand(1);
  auto args = std::make_shared<ConsistencyArgs>();
  auto* c = cmd->add_subcommand(
      "consistency",
      "NEES of the reported covariance against ground truth, and the integrity flag");
  c->add_option("run", args->run_dir, "Run folder of `parkloc run` (or its frames.jsonl)")
      ->required();
  c->add_option("--truth", args->truth, "Ground-truth poses (TUM), e.g. SEQUENCE/poses.tum")
      ->required();
  c->add_option("--bound", args->options.nees_bound, "NEES bound (chi-square 3 dof)")
      ->capture_default_str();
  c->add_option("--k", args->options.protection_k,
                "Protection level = k * sqrt(largest position eigenvalue)")
      ->capture_default_str();
  c->add_option("--alert-limit", args->options.alert_limit_m, "Alert limit, metres")
      ->capture_default_str();
  c->add_option("--per-frame", args->per_frame_csv, "Write per-frame values to this CSV");
  c->add_option("--json", args->json_out, "Write the summary as JSON here");
  c->callback([args] { runConsistency(*args); });
});

}  // namespace
