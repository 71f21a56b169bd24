#include "eval/tables.h"

#include <fmt/format.h>

#include <algorithm>

#include "eval/conditions.h"

namespace parkloc::eval {
namespace {

const std::vector<std::string> kClasses = {"parking_number", "pillar", "other"};

TableCell cm(const Summary& s, double Summary::*field) {
  if (s.count == 0) return TableCell("-");
  return TableCell::number(s.*field * 100.0, 1);
}

TableCell ms(const Summary& s, double Summary::*field) {
  if (s.count == 0) return TableCell("-");
  return TableCell::number(s.*field, 1);
}

std::string check(bool on) { return on ? "yes" : "-"; }

}  // namespace

Table table3(const OcrEvaluation& ocr, const std::optional<AnomalyFilterCounts>& afm) {
  Table t;
  t.key = "table3";
  t.title = "Table 3: text spotting (detection, recognition, classification) and anomaly filter";
  t.caption =
      "ICDAR-2015 matching at IoU >= 0.5; instances at least half occluded are don't care. "
      "TP and FN rates per labelled instance, FP rate per detection; recognition and "
      "classification over the matched instances (exact string).";
  t.header = {"Metric", "All"};
  std::vector<const OcrCounts*> columns = {&ocr.overall};
  for (const std::string& cls : kClasses) {
    const auto it = ocr.by_class.find(cls);
    if (it == ocr.by_class.end()) continue;
    t.header.push_back(cls);
    columns.push_back(&it->second);
  }
  auto row = [&](const std::string& name, auto metric) {
    std::vector<TableCell> r = {name};
    for (const OcrCounts* c : columns) r.push_back(metric(*c));
    t.rows.push_back(std::move(r));
  };
  auto count = [](size_t n) { return TableCell::number(static_cast<double>(n), 0); };
  row("Instances (cared for)", [&](const OcrCounts& c) { return count(c.truths); });
  row("Detection TP", [](const OcrCounts& c) { return TableCell::percent(c.tpRate()); });
  row("Detection FP", [](const OcrCounts& c) { return TableCell::percent(c.fpRate()); });
  row("Detection FN", [](const OcrCounts& c) { return TableCell::percent(c.fnRate()); });
  row("Detection IoU (mean)", [](const OcrCounts& c) { return TableCell::percent(c.meanIoU()); });
  row("Detection F-measure", [](const OcrCounts& c) { return TableCell::percent(c.fMeasure()); });
  row("Recognition (raw)",
      [](const OcrCounts& c) { return TableCell::percent(c.recognitionRawAccuracy()); });
  row("Recognition (lexicon)",
      [](const OcrCounts& c) { return TableCell::percent(c.recognitionAccuracy()); });
  row("Classification",
      [](const OcrCounts& c) { return TableCell::percent(c.classificationAccuracy()); });
  row("End to end (found and read)",
      [](const OcrCounts& c) { return TableCell::percent(c.endToEndAccuracy()); });
  if (afm) {
    std::vector<TableCell> filter = {"AFM filter accuracy",
                                     TableCell::percent(afm->filterAccuracy())};
    std::vector<TableCell> overall = {"Overall recognition accuracy after AFM",
                                      TableCell::percent(afm->overallRecognitionAccuracy())};
    filter.resize(t.header.size(), TableCell(""));
    overall.resize(t.header.size(), TableCell(""));
    t.rows.push_back(filter);
    t.rows.push_back(overall);
  }
  std::vector<TableCell> speed = {"Images per second", TableCell::number(ocr.imagesPerSecond(), 2)};
  speed.resize(t.header.size(), TableCell(""));
  t.rows.push_back(speed);
  return t;
}

namespace {

// One subset's row of the per-subset tables: name, instances, detection and reading rates.
std::vector<TableCell> subsetRow(const std::string& name, const OcrCounts* c, size_t columns) {
  if (c == nullptr) {
    std::vector<TableCell> r = {name, "0"};
    r.resize(columns, TableCell("-"));
    return r;
  }
  return {name,
          TableCell::number(static_cast<double>(c->truths), 0),
          TableCell::percent(c->tpRate()),
          TableCell::percent(c->fpRate()),
          TableCell::percent(c->fMeasure()),
          TableCell::percent(c->meanIoU()),
          TableCell::percent(c->recognitionRawAccuracy()),
          TableCell::percent(c->recognitionAccuracy()),
          TableCell::percent(c->classificationAccuracy())};
}

const std::vector<std::string> kSubsetHeader = {
    "Subset",   "Instances",         "Detection TP",          "Detection FP",  "F-measure",
    "Mean IoU", "Recognition (raw)", "Recognition (lexicon)", "Classification"};

std::string asIs(const std::string& name) { return name; }

// A table of Table 3's columns with one row per subset: `names` in order, each titled by
// `title`, the first column headed `first_column`.
template <typename Title = std::string (*)(const std::string&)>
Table subsetTable(const std::string& key, const std::string& heading, const std::string& caption,
                  const std::string& first_column, const std::vector<std::string>& names,
                  const std::map<std::string, OcrCounts>& counts, const Title& title = asIs) {
  Table t;
  t.key = key;
  t.title = heading;
  t.caption = caption;
  t.header = kSubsetHeader;
  t.header[0] = first_column;
  for (const std::string& name : names) {
    const auto it = counts.find(name);
    t.rows.push_back(
        subsetRow(title(name), it == counts.end() ? nullptr : &it->second, t.header.size()));
  }
  return t;
}

}  // namespace

Table table3Conditions(const OcrEvaluation& ocr) {
  return subsetTable(
      "table3_conditions", "Table 3 by condition: text spotting per subset",
      "Light and blur per sequence; rotation per instance (|reading direction| in the image "
      "within 30-60, 60-120 or 150-180 degrees).",
      "Subset", conditionNames(), ocr.by_condition, conditionTitle);
}

Table table3Appearance(const OcrEvaluation& ocr) {
  // The looks present: the clean render first, the factors alone, every factor on last (the
  // bird's-eye orientations, "avm_*", have their own table).
  std::vector<std::string> names;
  const auto& fixed = conditionNames();
  for (const auto& [name, counts] : ocr.parking_numbers_by_condition)
    if (std::find(fixed.begin(), fixed.end(), name) == fixed.end() && name != "clean" &&
        name != "realistic" && name.rfind("avm_", 0) != 0)
      names.push_back(name);
  if (ocr.parking_numbers_by_condition.count("clean")) names.insert(names.begin(), "clean");
  if (ocr.parking_numbers_by_condition.count("realistic")) names.push_back("realistic");
  return subsetTable(
      "table3_appearance", "Table 3 by appearance: parking numbers per rendered look",
      "Clean: the plain render; a factor's name: that factor alone on (sim/appearance.h); "
      "realistic: every factor on.",
      "Look", names, ocr.parking_numbers_by_condition);
}

Table table3BirdsEye(const OcrEvaluation& ocr) {
  return subsetTable("table3_birdseye",
                     "Table 3 on bird's-eye images: parking numbers per orientation",
                     "Stitched top-down (AVM) renders, as rendered (forward up) and turned "
                     "clockwise by 90, 180 and 270 degrees.",
                     "Orientation", {"avm_rot0", "avm_rot90", "avm_rot180", "avm_rot270"},
                     ocr.parking_numbers_by_condition);
}

Table table3Heights(const OcrEvaluation& ocr) {
  return subsetTable(
      "table3_heights", "Table 3 by size: parking numbers per apparent height",
      "Apparent height = polygon area over reading length, in image pixels (the truth's for "
      "instances and misses, the detection's own for false detections). Only instances "
      "labelled legible are counted (8 px tall at least, 2 cycles per character after blur).",
      "Height", heightBins(), ocr.parking_numbers_by_height);
}

Table table3Paint(const OcrEvaluation& ocr) {
  return subsetTable(
      "table3_paint", "Table 3 by paint: parking numbers with intact and worn paint",
      "Worn: the simulator erased part of the number's paint (the labels' paint_wear > 0). A "
      "false detection has no paint and counts in neither row, so their detection FP is 0 and "
      "their F-measure counts no false detection: compare the TP, recognition and "
      "classification columns.",
      "Paint", paintBins(), ocr.parking_numbers_by_paint);
}

Table table3Sight(const OcrEvaluation& ocr) {
  return subsetTable(
      "table3_sight", "Table 3 by sight: parking numbers in full sight and partly hidden",
      "Partly hidden: a car, a pillar or the vehicle's body hides part of the number (the "
      "labels' occluded_fraction > 0, under half for a number that counts), or the image's edge "
      "cuts it. A raw reading of such a number can be exact only where every character still "
      "shows. False detections count in neither row (their FP is 0).",
      "Sight", sightBins(), ocr.parking_numbers_by_sight);
}

Table table3Ink(const OcrEvaluation& ocr) {
  return subsetTable(
      "table3_ink", "Table 3 by ink contrast: parking numbers by their ink's signal to noise",
      "Ink SNR: the labels' ink_snr, one reading feature's contrast against the floor summed "
      "over its pixels, over the sensor noise (the simulator's light, exposure, paint and "
      "wear); below 5 a number is not legible. Labels without it count in no row, nor do "
      "false detections (their FP is 0).",
      "Ink", inkBins(), ocr.parking_numbers_by_ink);
}

Table table3HeightRule(const OcrEvaluation& ocr) {
  return subsetTable(
      "table3_height_rule",
      "Table 3 under the height-only rule: every text 8 px or taller cared for",
      "A height-only legibility rule: text at least 8 px tall (apparent height) and less than "
      "half occluded is cared for, however squeezed along its reading direction or smeared by "
      "blur. The tables above follow the labels' legible flag, which weighs both.",
      "Class", kClasses, ocr.height_rule_by_class);
}

namespace {

// One row: the pairs of a group of images and a parking number, found and read by some image.
Table recallTable(const std::string& key, const std::string& heading, const std::string& caption,
                  const std::string& by, const NumberRecall& r) {
  Table t;
  t.key = key;
  t.title = heading;
  t.caption = caption;
  t.header = {"Pairs", "Found by some " + by, "Found and read right by some " + by};
  t.rows.push_back({TableCell::number(static_cast<double>(r.numbers), 0),
                    TableCell::percent(r.foundShare()), TableCell::percent(r.readShare())});
  return t;
}

}  // namespace

Table table3FrameSets(const OcrEvaluation& ocr) {
  return recallTable(
      "table3_frame_sets", "Table 3 per frame set: parking numbers found by some camera",
      "Each (frame set, parking number) pair cared for in some camera's image counts once: "
      "found when some camera's image found it, read when some camera found it and read it "
      "right. The localization works on the frame set.",
      "camera", ocr.parking_numbers_per_frame_set);
}

Table table3Drives(const OcrEvaluation& ocr) {
  return recallTable(
      "table3_drives", "Table 3 per drive: parking numbers found in some image of the drive",
      "Each (drive, parking number) pair cared for in some image of the drive counts once: "
      "found when some image found it, read when some image found it and read it right. The "
      "per-image rates weigh a number by the images that show it; this table, once.",
      "image", ocr.parking_numbers_per_drive);
}

std::vector<Table> table3All(const OcrEvaluation& ocr,
                             const std::optional<AnomalyFilterCounts>& afm) {
  std::vector<Table> out = {table3(ocr, afm), table3Conditions(ocr), table3Heights(ocr),
                            table3Paint(ocr), table3Sight(ocr)};
  if (!ocr.parking_numbers_by_ink.empty()) out.push_back(table3Ink(ocr));
  const Table looks = table3Appearance(ocr);
  if (!looks.rows.empty()) out.push_back(looks);
  out.push_back(table3HeightRule(ocr));
  if (ocr.parking_numbers_per_frame_set.numbers > 0) out.push_back(table3FrameSets(ocr));
  if (ocr.parking_numbers_per_drive.numbers > 0) out.push_back(table3Drives(ocr));
  return out;
}

Table table10(const std::vector<AblationRow>& paper_rows, const std::vector<VariantResult>& extra) {
  Table t;
  t.key = "table10";
  t.title = "Table 10: ablation of the anomaly filter (AFM) and multi-camera fusion (MCRP, MCAP)";
  t.caption =
      "Position error against ground truth, cm (evo APE, no alignment). Paper rows "
      "use full-frame OCR on all four cameras every frame, the text centre through "
      "the ground homography and no odometry.";
  t.header = {"System",    "AFM",         "MCRP",     "MCAP",
              "Mean (cm)", "Median (cm)", "p95 (cm)", "Frames with pose"};
  auto pose_share = [](const VariantResult& v) {
    return TableCell::percent(
        v.frames ? static_cast<double>(v.frames_with_pose) / static_cast<double>(v.frames) : 0.0);
  };
  for (const AblationRow& r : paper_rows) {
    const Summary& e = r.result.error.position_m;
    t.rows.push_back({"OCR-RTPS (paper)", check(r.afm), check(r.mcrp), check(r.mcap),
                      cm(e, &Summary::mean), cm(e, &Summary::median), cm(e, &Summary::p95),
                      pose_share(r.result)});
  }
  for (const VariantResult& v : extra) {
    const Summary& e = v.error.position_m;
    t.rows.push_back({v.title, "", "", "", cm(e, &Summary::mean), cm(e, &Summary::median),
                      cm(e, &Summary::p95), pose_share(v)});
  }
  return t;
}

Table table8(const std::vector<std::pair<std::string, std::map<std::string, TrajectoryError>>>&
                 per_variant) {
  Table t;
  t.key = "table8";
  t.title = "Table 8: position error per condition (mean / p95, cm)";
  t.caption =
      "Bright light, weak light and blur are whole drives; a rotation subset is every "
      "frame in which a labelled, less than half occluded parking number is seen at "
      "about that rotation by some camera.";
  t.header = {"System"};
  for (const std::string& name : conditionNames()) t.header.push_back(conditionTitle(name));
  for (const auto& [title, errors] : per_variant) {
    std::vector<TableCell> r = {title};
    for (const std::string& name : conditionNames()) {
      const auto it = errors.find(name);
      if (it == errors.end() || it->second.position_m.count == 0) {
        r.push_back(TableCell("-"));
        continue;
      }
      const Summary& s = it->second.position_m;
      TableCell cell(fmt::format("{:.1f} / {:.1f} (n={})", s.mean * 100.0, s.p95 * 100.0, s.count));
      cell.value = s.mean * 100.0;
      r.push_back(cell);
    }
    t.rows.push_back(r);
  }
  return t;
}

Table table5(const std::vector<VariantResult>& variants) {
  Table t;
  t.key = "table5";
  t.title = "Table 5: accuracy and latency";
  t.caption =
      "Errors over frames with a pose; latency per four-camera frame set on this "
      "machine, including OCR. Odometry-only dead reckoning starts from the true "
      "first pose and stands in for a GNSS-denied system without OCR.";
  t.header = {"Method",           "Mean error (cm)",      "p95 error (cm)",
              "Max error (cm)",   "Mean yaw error (deg)", "Latency median (ms)",
              "Latency p99 (ms)", "Frames with pose"};
  for (const VariantResult& v : variants) {
    const Summary& e = v.error.position_m;
    t.rows.push_back({v.title, cm(e, &Summary::mean), cm(e, &Summary::p95), cm(e, &Summary::max),
                      v.error.abs_yaw_deg.count ? TableCell::number(v.error.abs_yaw_deg.mean, 2)
                                                : TableCell("-"),
                      ms(v.latency.total_ms, &Summary::median),
                      ms(v.latency.total_ms, &Summary::p99),
                      TableCell(fmt::format("{} / {}", v.frames_with_pose, v.frames))});
  }
  return t;
}

Table mapNoiseTable(const std::vector<MapNoiseRow>& rows) {
  Table t;
  t.key = "map_noise";
  t.title = "Map noise: survey error in the map";
  t.caption =
      "The pipeline localizes on the map perturbed (positions N(0, s) per axis, headings "
      "N(0, 1 deg x s / 10 cm), sizes x (1 + N(0, 5 %))); errors against the truth over frames "
      "with a pose. NEES: share of those frames inside the 95 % chi-square bound (3 dof). "
      "Smoothed: the same drives smoothed offline from the fixes the filter fused and the "
      "odometry, each landmark's map error one unknown (a non-causal yardstick). Seed: the "
      "map draw; all N: the frames of N draws pooled.";
  t.header = {"Map noise (cm)",
              "Seed",
              "Mean error (cm)",
              "p95 error (cm)",
              "Max error (cm)",
              "Mean yaw error (deg)",
              "NEES inside 95 %",
              "Frames with pose",
              "Smoothed mean / p95 / max (cm)",
              "Smoothed yaw (deg)"};
  for (const MapNoiseRow& r : rows) {
    const VariantResult& v = r.result;
    const Summary& e = v.error.position_m;
    t.rows.push_back(
        {TableCell::number(r.noise_m * 100.0, 1), TableCell(r.seed), cm(e, &Summary::mean),
         cm(e, &Summary::p95), cm(e, &Summary::max),
         v.error.abs_yaw_deg.count ? TableCell::number(v.error.abs_yaw_deg.mean, 2)
                                   : TableCell("-"),
         r.nees_frames ? TableCell::percent(static_cast<double>(r.nees_inside) /
                                            static_cast<double>(r.nees_frames))
                       : TableCell("-"),
         TableCell(fmt::format("{} / {}", v.frames_with_pose, v.frames)),
         r.smoothed && r.smoothed->position_m.count
             ? TableCell(fmt::format(
                   "{:.1f} / {:.1f} / {:.1f}", 100.0 * r.smoothed->position_m.mean,
                   100.0 * r.smoothed->position_m.p95, 100.0 * r.smoothed->position_m.max))
             : TableCell("-"),
         r.smoothed && r.smoothed->abs_yaw_deg.count
             ? TableCell::number(r.smoothed->abs_yaw_deg.mean, 2)
             : TableCell("-")});
  }
  return t;
}

Table latencyTable(const std::vector<VariantResult>& variants) {
  Table t;
  t.key = "latency";
  t.title = "Latency per four-camera frame set and per stage (ms)";
  t.caption = "Wall-clock time on this machine; a stage that did not run in a frame counts 0.";
  t.header = {"Method", "Stage", "Median", "p95", "p99", "Max", "Mean"};
  for (const VariantResult& v : variants) {
    auto row = [&](const std::string& stage, const Summary& s) {
      t.rows.push_back({v.title, stage, ms(s, &Summary::median), ms(s, &Summary::p95),
                        ms(s, &Summary::p99), ms(s, &Summary::max), ms(s, &Summary::mean)});
    };
    for (const auto& [stage, s] : v.latency.stage_ms) row(stage, s);
    row("total", v.latency.total_ms);
    // Not part of the total: the frame sets do not wait for it.
    if (!v.latency.worker_samples_ms.empty())
      row("workers, off the critical path (per frame set fusing their texts)", v.latency.worker_ms);
  }
  return t;
}

Table levelTable(const std::vector<VariantResult>& variants) {
  Table t;
  t.key = "level";
  t.title = "Level estimate (no level given)";
  t.caption =
      "Decided: the level's probability reached levels.decided_probability. Time to decide: "
      "from the first frame set with a legible level sign or level-unique text in view (the "
      "labels) to the first decided on the right level; median / max over the drives "
      "(first level) and over the level changes; never: such a text was in view and the "
      "stretch ended undecided.";
  t.header = {"Method",
              "Frame sets",
              "With a pose",
              "Decided",
              "Right where decided",
              "Time to decide (s)",
              "Time to follow a change (s)",
              "Never decided"};
  const auto delays = [](const std::vector<double>& d) -> TableCell {
    if (d.empty()) return TableCell("-");
    const Summary s = summarize(d);
    return TableCell(fmt::format("{:.1f} / {:.1f} (n={})", s.median, s.max, s.count));
  };
  for (const VariantResult& v : variants) {
    const LevelScore& l = v.levels;
    if (l.frames == 0) continue;
    const double n = static_cast<double>(l.frames);
    t.rows.push_back({v.title, TableCell::number(n, 0),
                      TableCell::percent(static_cast<double>(l.with_pose) / n),
                      TableCell::percent(static_cast<double>(l.decided) / n),
                      TableCell::percent(l.rightWhereDecided()), delays(l.decision_delays_s),
                      delays(l.change_delays_s),
                      TableCell::number(static_cast<double>(l.stretches_never_decided), 0)});
  }
  return t;
}

}  // namespace parkloc::eval
