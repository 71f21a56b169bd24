#include "eval/evaluation_variants.h"

#include <fmt/format.h>

#include <filesystem>

#include "eval/conditions.h"

namespace parkloc::eval::detail {

namespace {
// The main configuration once per map-noise level: the first level is the configuration
// itself, each further one a copy on a perturbed map, once per seed.
void addWithMapNoise(const VariantSpec& main, const EvaluationOptions& o,
                     std::vector<VariantSpec>& specs) {
  const std::vector<double> levels =
      o.map_noise_levels.empty() ? std::vector<double>{0.0} : o.map_noise_levels;
  const std::vector<uint64_t> seeds =
      o.map_noise_seeds.empty() ? std::vector<uint64_t>{0} : o.map_noise_seeds;
  const bool several = seeds.size() > 1;
  for (size_t i = 0; i < levels.size(); ++i) {
    VariantSpec s = main;
    s.map_noise_m = levels[i];
    s.map_noise_seed = seeds.front();
    if (i == 0) {
      if (levels[i] > 0.0)
        s.title = fmt::format("{}, map noise {:g} cm", main.title, levels[i] * 100.0);
      specs.push_back(s);
      continue;
    }
    for (const uint64_t seed : seeds) {
      s.map_noise_seed = seed;
      s.key = fmt::format("{}_map_noise_{:g}cm{}", main.key, levels[i] * 100.0,
                          several ? fmt::format("_seed{}", seed) : "");
      s.title = fmt::format("{}, map noise {:g} cm{}", main.title, levels[i] * 100.0,
                            several ? fmt::format(", seed {}", seed) : "");
      specs.push_back(s);
    }
  }
}
}  // namespace

std::vector<VariantSpec> variantSpecs(const EvaluationOptions& o, bool have_spotter) {
  std::vector<VariantSpec> specs;
  const bool parkloc_main = o.parkloc && have_spotter;
  if (parkloc_main) {
    addWithMapNoise({"parkloc", "parkloc (full pipeline)", Source::kSpotter, o.parkloc_options}, o,
                    specs);
  }
  if (o.paper_ablation && have_spotter) {
    // The paper's Table 10 row order.
    const bool rows[8][3] = {{false, false, false}, {true, false, false}, {true, true, false},
                             {true, false, true},   {false, true, false}, {false, false, true},
                             {false, true, true},   {true, true, true}};
    for (const auto& r : rows) {
      VariantSpec s;
      s.afm = r[0], s.mcrp = r[1], s.mcap = r[2];
      s.ablation = true;
      s.key = fmt::format("paper_afm{}_mcrp{}_mcap{}", int(s.afm), int(s.mcrp), int(s.mcap));
      s.title = s.afm && s.mcrp && s.mcap
                    ? "OCR-RTPS (paper pipeline)"
                    : fmt::format("OCR-RTPS AFM {} MCRP {} MCAP {}", s.afm ? "on" : "off",
                                  s.mcrp ? "on" : "off", s.mcap ? "on" : "off");
      s.source = Source::kSharedFullFrame;
      s.options = localize::PipelineOptions::paper(o.parkloc_options);
      s.options.paper_modules.afm = s.afm, s.options.paper_modules.mcrp = s.mcrp, s.options.paper_modules.mcap = s.mcap;
      specs.push_back(s);
    }
  }
  if (o.paper_own_spotting && have_spotter) {
    VariantSpec s;
    s.key = "paper_spotting";
    s.title = "OCR-RTPS (paper pipeline, spotting itself)";
    s.source = Source::kSpotter;
    s.options = localize::PipelineOptions::paper(o.parkloc_options);
    s.afm = s.mcrp = s.mcap = true;
    specs.push_back(s);
  }
  if (o.oracle) {
    const VariantSpec oracle{"oracle", "parkloc on ground-truth text (oracle OCR)", Source::kOracle,
                             o.parkloc_options};
    if (parkloc_main)
      specs.push_back(oracle);
    else
      addWithMapNoise(oracle, o, specs);
  }
  if (o.odometry_only) {
    specs.push_back({"odometry_only", "odometry-only dead reckoning", Source::kOdometry, {}});
  }
  return specs;
}

VariantTally pooledTally(const std::vector<const VariantTally*>& tallies) {
  VariantTally pooled;
  if (tallies.empty()) return pooled;
  pooled.spec = tallies.front()->spec;
  const auto append = [](auto& to, const auto& from) {
    to.insert(to.end(), from.begin(), from.end());
  };
  for (const VariantTally* t : tallies) {
    append(pooled.frames, t->frames);
    append(pooled.frame_tags, t->frame_tags);
    append(pooled.timings, t->timings);
    append(pooled.smoothed_frames, t->smoothed_frames);
    pooled.frames_total += t->frames_total;
    pooled.frames_with_pose += t->frames_with_pose;
    pooled.after_fix += t->after_fix;
    pooled.with_pose_after_fix += t->with_pose_after_fix;
    pooled.nees_frames += t->nees_frames;
    pooled.nees_inside += t->nees_inside;
  }
  return pooled;
}

VariantResult toResult(const VariantTally& t) {
  VariantResult r;
  r.key = t.spec.key;
  r.title = t.spec.title;
  r.error = errorFromFrames(t.frames);
  r.latency = latencyReport(t.timings);
  r.frames = t.frames_total;
  r.frames_with_pose = t.frames_with_pose;
  r.frames_after_first_fix = t.after_fix;
  r.frames_with_pose_after_first_fix = t.with_pose_after_fix;
  r.levels = t.levels;
  return r;
}

std::map<std::string, TrajectoryError> conditionErrors(const VariantTally& t) {
  std::map<std::string, TrajectoryError> out;
  for (const std::string& name : conditionNames()) {
    std::vector<FrameError> frames;
    for (size_t i = 0; i < t.frames.size(); ++i) {
      if (t.frame_tags[i].count(name)) frames.push_back(t.frames[i]);
    }
    if (!frames.empty()) out[name] = errorFromFrames(frames);
  }
  return out;
}

TrajectoryView makeView(const io::Sequence& seq, const VariantRun& run, double t0, double t1) {
  TrajectoryView v;
  v.name =
      std::filesystem::path(seq.dir()).filename().string() + " (" + run.tally->spec.title + ")";
  for (const auto& p : seq.groundTruth()) {
    if (p.timestamp < t0 - 1e-6 || p.timestamp > t1 + 1e-6) continue;
    v.truth_x.push_back(p.pose.translation().x());
    v.truth_y.push_back(p.pose.translation().y());
  }
  for (const auto& p : run.estimate) {
    v.estimate_x.push_back(p.pose.translation().x());
    v.estimate_y.push_back(p.pose.translation().y());
  }
  for (const map::Landmark& l : seq.map().landmarks()) {
    if (!run.levels.empty() && !run.levels.count(l.level)) continue;
    v.landmark_x.push_back(l.position.x());
    v.landmark_y.push_back(l.position.y());
    v.landmark_text.push_back(l.cls == map::TextClass::kParkingNumber ? l.text : "");
  }
  return v;
}

}  // namespace parkloc::eval::detail
