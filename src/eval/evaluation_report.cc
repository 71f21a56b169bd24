#include <fmt/format.h>

#include "eval/evaluation_variants.h"

namespace parkloc::eval::detail {

EvaluationReport assembleReport(const EvaluationOptions& options, const EvaluationTotals& totals) {
  const std::vector<VariantTally>& tallies = totals.tallies;
  const std::string& main_key = totals.main_key;
  const bool shared_ocr = totals.shared_ocr;
  const bool shared_second_opinions = totals.shared_second_opinions;
  const OcrEvaluator& ocr_evaluator = totals.shared_ocr_evaluator;
  const OcrEvaluator& own_ocr_evaluator = totals.own_ocr_evaluator;
  const AnomalyFilterCounts& afm_counts = totals.afm_counts;
  EvaluationReport report;
  report.title = options.title;
  report.dataset = options.dataset;
  report.command = options.command;
  report.trajectories = totals.views;
  std::map<std::string, const VariantTally*> by_key;
  for (const VariantTally& t : tallies) by_key[t.spec.key] = &t;
  auto result = [&](const std::string& key) -> std::optional<VariantResult> {
    const auto it = by_key.find(key);
    if (it == by_key.end()) return std::nullopt;
    return toResult(*it->second);
  };
  if (auto main = result(main_key)) report.main = *main;
  const std::string paper_key = "paper_afm1_mcrp1_mcap1";
  if (!shared_ocr && own_ocr_evaluator.result().images > 0) {
    report.ocr = own_ocr_evaluator.result();
    for (Table& t : table3All(own_ocr_evaluator.result(), std::nullopt))
      report.tables.push_back(std::move(t));
    report.notes.push_back(fmt::format(
        "OCR figures from the {} camera images the parkloc pipeline spotted on the full frame "
        "(map-guided frames left out).",
        own_ocr_evaluator.result().images));
  }
  if (shared_ocr) {
    report.ocr = ocr_evaluator.result();
    for (Table& t : table3All(ocr_evaluator.result(), afm_counts))
      report.tables.push_back(std::move(t));
    if (!shared_second_opinions)
      report.notes.push_back(
          "OCR figures from the full-frame spotting that fed the paper's pipeline, without "
          "second opinions (`parkloc eval ocr` asks for them by default).");
  }
  {
    std::vector<AblationRow> rows;
    std::vector<VariantResult> extra;
    for (const VariantTally& t : tallies) {
      if (t.spec.ablation) rows.push_back({t.spec.afm, t.spec.mcrp, t.spec.mcap, toResult(t)});
    }
    for (const char* key : {"parkloc", "oracle"}) {
      if (auto r = result(key)) extra.push_back(*r);
    }
    report.tables.push_back(table10(rows, extra));
  }
  {
    std::vector<std::pair<std::string, std::map<std::string, TrajectoryError>>> per_variant;
    for (const std::string& key : {std::string("parkloc"), paper_key, std::string("paper_spotting"),
                                   std::string("oracle")}) {
      const auto it = by_key.find(key);
      if (it != by_key.end())
        per_variant.emplace_back(it->second->spec.title, conditionErrors(*it->second));
    }
    report.tables.push_back(table8(per_variant));
  }
  {
    std::vector<VariantResult> rows;
    for (const std::string& key : {std::string("parkloc"), paper_key, std::string("paper_spotting"),
                                   std::string("odometry_only"), std::string("oracle")}) {
      if (auto r = result(key)) rows.push_back(*r);
    }
    report.tables.push_back(table5(rows));
  }
  {
    std::vector<VariantResult> rows;
    for (const std::string& key : {std::string("parkloc"), paper_key, std::string("paper_spotting"),
                                   std::string("oracle")}) {
      if (auto r = result(key)) rows.push_back(*r);
    }
    report.tables.push_back(latencyTable(rows));
  }
  {
    std::vector<VariantResult> rows;
    for (const std::string& key : {std::string("parkloc"), std::string("oracle")})
      if (auto r = result(key)) rows.push_back(*r);
    report.tables.push_back(levelTable(rows));
  }
  {
    // The main configuration at each map-noise level and seed, when any is perturbed; a
    // level drawn with several seeds gets a row of their frames pooled as well.
    // (variantSpecs lists a level's draws one after another.)
    std::vector<MapNoiseRow> rows;
    bool perturbed = false;
    std::vector<const VariantTally*> draws;  // of the perturbed level being listed
    const auto row = [](const VariantTally& t, const std::string& seed) {
      MapNoiseRow r{t.spec.map_noise_m, seed, toResult(t), t.nees_frames, t.nees_inside, {}};
      if (!t.smoothed_frames.empty()) r.smoothed = errorFromFrames(t.smoothed_frames);
      return r;
    };
    const auto pool = [&] {
      if (draws.size() > 1)
        rows.push_back(row(pooledTally(draws), fmt::format("all {}", draws.size())));
      draws.clear();
    };
    for (const VariantTally& t : tallies) {
      if (t.spec.key != totals.main_key && t.spec.key.rfind(totals.main_key + "_map_noise_", 0))
        continue;
      const bool noisy = t.spec.map_noise_m > 0.0;
      perturbed = perturbed || noisy;
      if (!draws.empty() && draws.front()->spec.map_noise_m != t.spec.map_noise_m) pool();
      rows.push_back(row(t, noisy ? std::to_string(t.spec.map_noise_seed) : "-"));
      if (noisy) draws.push_back(&t);
    }
    pool();
    if (perturbed) report.tables.push_back(mapNoiseTable(rows));
  }
  for (const VariantTally& t : tallies) report.variants.push_back(toResult(t));
  report.notes.push_back(fmt::format(
      "{} sequences, {} frame sets. Position error: evo-style APE (translation, no alignment, "
      "association by timestamp within 10 ms) over frames with a pose.",
      totals.sequences, report.main.frames));
  if (shared_ocr) {
    report.notes.push_back(
        "Paper-pipeline variants share one full-frame OCR pass per image; its time is "
        "counted in each variant's latency.");
  }
  if (!totals.have_spotter) {
    report.notes.push_back("No text spotter: only the oracle and odometry-only variants ran.");
  }
  return report;
}

}  // namespace parkloc::eval::detail
