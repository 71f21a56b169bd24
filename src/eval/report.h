#pragma once
// The evaluation report: results.json (stable keys other tools read), results.md (the
// tables) and report.html (self-contained: tables and inline SVG plots, no scripts, no
// network). The plots are the paper's: estimated vs true trajectory over the map, error
// along x and y over time and as histograms (Figure 7), latency per stage.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "eval/latency.h"
#include "eval/level_metrics.h"
#include "eval/ocr_metrics.h"
#include "eval/trajectory_metrics.h"

namespace parkloc::eval {

// A table cell: the text shown, and the number behind it for results.json when it has one.
struct TableCell {
  std::string text;
  std::optional<double> value;
  TableCell(std::string t = "") : text(std::move(t)) {}  // NOLINT: plain text cells
  TableCell(const char* t) : text(t) {}                  // NOLINT
  static TableCell number(double v, int decimals, const std::string& unit = "");
  static TableCell percent(double fraction);  // 0.8594 -> "85.94 %", value 85.94
};

struct Table {
  std::string key;    // "table3", ... (the key under "tables" in results.json)
  std::string title;  // "Table 3: text spotting"
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<TableCell>> rows;
};

// One pipeline configuration run over the evaluated frames.
struct VariantResult {
  std::string key;    // "parkloc", "paper", "odometry_only", "oracle", ...
  std::string title;  // shown in tables
  TrajectoryError error;
  LatencyReport latency;
  size_t frames = 0;            // frame sets processed
  size_t frames_with_pose = 0;  // frame sets that produced a pose
  size_t frames_after_first_fix = 0;
  size_t frames_with_pose_after_first_fix = 0;
  LevelScore levels;  // the level estimate against the true level (pipelines only)
};

// One drive drawn over its map: landmarks, true and estimated path.
struct TrajectoryView {
  std::string name;
  std::vector<double> truth_x, truth_y, estimate_x, estimate_y;
  std::vector<double> landmark_x, landmark_y;
  std::vector<std::string> landmark_text;
};

struct EvaluationReport {
  std::string title = "parkloc evaluation";
  std::string dataset;                  // what was evaluated (folder, split)
  std::string command;                  // the command line that produced it
  VariantResult main;                   // the headline figures (the full parkloc pipeline)
  std::vector<VariantResult> variants;  // every configuration that ran
  std::optional<OcrEvaluation> ocr;
  std::vector<TrajectoryView> trajectories;
  std::vector<Table> tables;
  std::vector<std::string> notes;  // shown under the tables (definitions, caveats)
};

// Every OCR count and rate, overall, per class and per condition.
nlohmann::json ocrEvaluationJson(const OcrEvaluation& ocr);
nlohmann::json resultsJson(const EvaluationReport& report);
std::string resultsMarkdown(const EvaluationReport& report);
std::string reportHtml(const EvaluationReport& report);
std::string tableMarkdown(const Table& table);

// Writes results.json, results.md and report.html into `dir` (created when missing).
// Throws IoError when a file cannot be written.
void writeReport(const EvaluationReport& report, const std::string& dir);

}  // namespace parkloc::eval
