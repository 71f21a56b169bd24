#include "eval/report.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "common/error.h"
#include "eval/svg_plot.h"

namespace parkloc::eval {
namespace {

nlohmann::json summaryJson(const Summary& s, double scale) {
  return {{"count", s.count},       {"mean", s.mean * scale}, {"median", s.median * scale},
          {"rmse", s.rmse * scale}, {"std", s.std * scale},   {"min", s.min * scale},
          {"max", s.max * scale},   {"p95", s.p95 * scale},   {"p99", s.p99 * scale}};
}

nlohmann::json countsJson(const OcrCounts& c) {
  return {{"instances", c.truths},
          {"detections", c.detections},
          {"tp", c.tp},
          {"fp", c.fp},
          {"fn", c.fn},
          {"detection_tp_rate", c.tpRate()},
          {"detection_fp_rate", c.fpRate()},
          {"detection_fn_rate", c.fnRate()},
          {"precision", c.precision()},
          {"recall", c.recall()},
          {"detection_f", c.fMeasure()},
          {"mean_iou", c.meanIoU()},
          {"recognition_raw_accuracy", c.recognitionRawAccuracy()},
          {"recognition_accuracy", c.recognitionAccuracy()},
          {"classification_accuracy", c.classificationAccuracy()},
          {"end_to_end_accuracy", c.endToEndAccuracy()}};
}

nlohmann::json tableJson(const Table& t) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& row : t.rows) {
    nlohmann::json r = nlohmann::json::array();
    for (const TableCell& c : row) {
      if (c.value) {
        r.push_back(*c.value);
      } else {
        r.push_back(c.text);
      }
    }
    rows.push_back(r);
  }
  return {{"title", t.title}, {"caption", t.caption}, {"header", t.header}, {"rows", rows}};
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) throw IoError(path + ": cannot open for writing");
  out << text;
  if (!out) throw IoError(path + ": write failed");
}

std::string htmlTable(const Table& t) {
  std::string s = fmt::format("<h3>{}</h3>\n<table>\n<tr>", escapeXml(t.title));
  for (const std::string& h : t.header) s += "<th>" + escapeXml(h) + "</th>";
  s += "</tr>\n";
  for (const auto& row : t.rows) {
    s += "<tr>";
    for (const TableCell& c : row) {
      s += std::string(c.value ? "<td class=\"n\">" : "<td>") + escapeXml(c.text) + "</td>";
    }
    s += "</tr>\n";
  }
  s += "</table>\n";
  if (!t.caption.empty()) s += "<p class=\"caption\">" + escapeXml(t.caption) + "</p>\n";
  return s;
}

PlotSeries series(std::string label, std::string color, std::vector<double> x,
                  std::vector<double> y, bool line, double marker_radius, double line_width = 1.5) {
  PlotSeries p;
  p.label = std::move(label);
  p.color = std::move(color);
  p.x = std::move(x);
  p.y = std::move(y);
  p.line = line;
  p.marker_radius = marker_radius;
  p.line_width = line_width;
  return p;
}

std::string figure(const std::string& svg) { return "<div class=\"fig\">" + svg + "</div>\n"; }

std::string trajectoryPlot(const TrajectoryView& v) {
  PlotSeries landmarks = series("landmarks", "#999999", v.landmark_x, v.landmark_y, false, 2.0);
  if (v.landmark_text.size() <= 400) landmarks.point_labels = v.landmark_text;
  PlotSeries truth = series("ground truth", "#2ca02c", v.truth_x, v.truth_y, true, 0.0, 3.0);
  PlotSeries estimate = series("estimate", "#d62728", v.estimate_x, v.estimate_y, true, 0.0, 1.2);
  PlotOptions o;
  o.title = "Trajectory over the map: " + v.name;
  o.x_label = "x east (m)";
  o.y_label = "y north (m)";
  o.width = 1200;
  o.height = 640;
  o.equal_aspect = true;
  return linePlot({landmarks, truth, estimate}, o);
}

}  // namespace

TableCell TableCell::number(double v, int decimals, const std::string& unit) {
  TableCell c(fmt::format("{:.{}f}{}", v, decimals, unit));
  c.value = v;
  return c;
}

TableCell TableCell::percent(double fraction) {
  TableCell c(fmt::format("{:.2f} %", fraction * 100.0));
  c.value = fraction * 100.0;
  return c;
}

nlohmann::json ocrEvaluationJson(const OcrEvaluation& ocr) {
  nlohmann::json o = countsJson(ocr.overall);
  o["images"] = ocr.images;
  o["images_per_second"] = ocr.imagesPerSecond();
  o["by_class"] = nlohmann::json::object();
  o["by_condition"] = nlohmann::json::object();
  for (const auto& [cls, c] : ocr.by_class) o["by_class"][cls] = countsJson(c);
  for (const auto& [name, c] : ocr.by_condition) o["by_condition"][name] = countsJson(c);
  o["parking_numbers_by_height"] = nlohmann::json::object();
  for (const auto& [bin, c] : ocr.parking_numbers_by_height)
    o["parking_numbers_by_height"][bin] = countsJson(c);
  o["parking_numbers_by_condition"] = nlohmann::json::object();
  for (const auto& [name, c] : ocr.parking_numbers_by_condition)
    o["parking_numbers_by_condition"][name] = countsJson(c);
  o["parking_numbers_by_paint"] = nlohmann::json::object();
  for (const auto& [bin, c] : ocr.parking_numbers_by_paint)
    o["parking_numbers_by_paint"][bin] = countsJson(c);
  o["parking_numbers_by_sight"] = nlohmann::json::object();
  for (const auto& [bin, c] : ocr.parking_numbers_by_sight)
    o["parking_numbers_by_sight"][bin] = countsJson(c);
  o["parking_numbers_by_ink"] = nlohmann::json::object();
  for (const auto& [bin, c] : ocr.parking_numbers_by_ink)
    o["parking_numbers_by_ink"][bin] = countsJson(c);
  const auto recallJson = [](const NumberRecall& r) {
    return nlohmann::json{{"numbers", r.numbers}, {"found", r.found}, {"read", r.read}};
  };
  o["parking_numbers_per_frame_set"] = recallJson(ocr.parking_numbers_per_frame_set);
  o["parking_numbers_per_drive"] = recallJson(ocr.parking_numbers_per_drive);
  o["height_rule_by_class"] = nlohmann::json::object();
  for (const auto& [cls, c] : ocr.height_rule_by_class)
    o["height_rule_by_class"][cls] = countsJson(c);
  return o;
}

nlohmann::json resultsJson(const EvaluationReport& r) {
  const VariantResult& m = r.main;
  nlohmann::json j;
  j["title"] = r.title;
  j["dataset"] = r.dataset;
  j["command"] = r.command;
  j["system"] = m.key;
  j["frames"] = m.frames;
  j["frames_with_pose"] = m.frames_with_pose;
  j["frames_after_first_fix"] = m.frames_after_first_fix;
  j["frames_with_pose_after_first_fix"] = m.frames_with_pose_after_first_fix;
  j["position_error_cm"] = summaryJson(m.error.position_m, 100.0);
  j["error_x_cm"] = summaryJson(m.error.abs_x_m, 100.0);
  j["error_y_cm"] = summaryJson(m.error.abs_y_m, 100.0);
  j["yaw_error_deg"] = summaryJson(m.error.abs_yaw_deg, 1.0);
  nlohmann::json latency = summaryJson(m.latency.total_ms, 1.0);
  for (const auto& [stage, s] : m.latency.stage_ms) latency["stages"][stage] = summaryJson(s, 1.0);
  j["latency_ms"] = latency;
  const LevelScore& l = m.levels;
  j["level"] = {{"frames", l.frames},
                {"with_pose", l.with_pose},
                {"decided", l.decided},
                {"decided_right", l.decided_right},
                {"right_where_decided", l.rightWhereDecided()},
                {"decision_delays_s", l.decision_delays_s},
                {"change_delays_s", l.change_delays_s},
                {"changes", l.changes},
                {"stretches_never_decided", l.stretches_never_decided}};
  if (r.ocr) {
    j["ocr"] = ocrEvaluationJson(*r.ocr);
  } else {
    j["ocr"] = nlohmann::json::object();
  }
  j["tables"] = nlohmann::json::object();
  for (const Table& t : r.tables) j["tables"][t.key] = tableJson(t);
  j["notes"] = r.notes;
  return j;
}

std::string tableMarkdown(const Table& t) {
  std::string s = "### " + t.title + "\n\n|";
  for (const std::string& h : t.header) s += " " + h + " |";
  s += "\n|";
  for (size_t i = 0; i < t.header.size(); ++i) s += i == 0 ? " --- |" : " ---: |";
  s += "\n";
  for (const auto& row : t.rows) {
    s += "|";
    for (const TableCell& c : row) s += " " + c.text + " |";
    s += "\n";
  }
  if (!t.caption.empty()) s += "\n" + t.caption + "\n";
  return s + "\n";
}

std::string resultsMarkdown(const EvaluationReport& r) {
  const VariantResult& m = r.main;
  std::string s = "# " + r.title + "\n\n";
  if (!r.dataset.empty()) s += "Dataset: `" + r.dataset + "`\n\n";
  if (!r.command.empty()) s += "Command: `" + r.command + "`\n\n";
  s += fmt::format(
      "**{}**: {} frame sets, {} with a pose; position error mean {:.1f} cm, p95 {:.1f} cm, "
      "max {:.1f} cm; yaw error mean {:.2f} deg; latency median {:.1f} ms, p99 {:.1f} ms per "
      "frame set.\n\n",
      m.title, m.frames, m.frames_with_pose, m.error.position_m.mean * 100,
      m.error.position_m.p95 * 100, m.error.position_m.max * 100, m.error.abs_yaw_deg.mean,
      m.latency.total_ms.median, m.latency.total_ms.p99);
  if (m.levels.frames > 0)
    s += fmt::format(
        "No level given: the level decided on {} of {} frame sets, right on {} of those.\n\n",
        m.levels.decided, m.levels.frames, m.levels.decided_right);
  for (const Table& t : r.tables) s += tableMarkdown(t);
  for (const std::string& n : r.notes) s += "- " + n + "\n";
  return s;
}

std::string reportHtml(const EvaluationReport& r) {
  const VariantResult& m = r.main;
  std::string s =
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + escapeXml(r.title) +
      "</title>\n<style>\n"
      "body{font-family:sans-serif;margin:24px;color:#222;max-width:1240px}\n"
      "table{border-collapse:collapse;margin:8px 0}td,th{border:1px solid #ccc;padding:3px 8px;"
      "font-size:13px}th{background:#f0f0f0}td.n{text-align:right}\n"
      ".caption{font-size:12px;color:#555;margin-top:2px}.fig{display:inline-block;margin:4px}\n"
      ".kpi{display:inline-block;border:1px solid #ddd;border-radius:6px;padding:8px 14px;"
      "margin:4px;background:#fafafa}.kpi b{font-size:20px;display:block}\n"
      "</style></head><body>\n";
  s += "<h1>" + escapeXml(r.title) + "</h1>\n";
  if (!r.dataset.empty()) s += "<p>Dataset: <code>" + escapeXml(r.dataset) + "</code></p>\n";
  if (!r.command.empty()) s += "<p>Command: <code>" + escapeXml(r.command) + "</code></p>\n";
  auto kpi = [](const std::string& value, const std::string& name) {
    return "<div class=\"kpi\"><b>" + escapeXml(value) + "</b>" + escapeXml(name) + "</div>";
  };
  s += "<div>" + kpi(fmt::format("{} / {}", m.frames_with_pose, m.frames), "frames with pose") +
       kpi(fmt::format("{:.1f} cm", m.error.position_m.mean * 100), "mean position error") +
       kpi(fmt::format("{:.1f} cm", m.error.position_m.p95 * 100), "p95 position error") +
       kpi(fmt::format("{:.2f} deg", m.error.abs_yaw_deg.mean), "mean yaw error") +
       kpi(fmt::format("{:.1f} ms", m.latency.total_ms.median), "median latency") +
       kpi(fmt::format("{:.1f} ms", m.latency.total_ms.p99), "p99 latency");
  if (r.ocr) {
    s += kpi(fmt::format("{:.1f} %", r.ocr->overall.fMeasure() * 100), "detection F-measure") +
         kpi(fmt::format("{:.1f} %", r.ocr->overall.recognitionAccuracy() * 100),
             "recognition accuracy");
  }
  s += "</div>\n<h2>Trajectory (" + escapeXml(m.title) + ")</h2>\n";
  for (const TrajectoryView& v : r.trajectories) s += figure(trajectoryPlot(v));

  // Figure 7 of the paper: error along x and y, over time and as histograms.
  std::vector<double> t, dx, dy, position;
  for (const FrameError& f : m.error.frames) {
    t.push_back(f.timestamp);
    dx.push_back(f.dx * 100.0);
    dy.push_back(f.dy * 100.0);
    position.push_back(f.position * 100.0);
  }
  s += "<h2>Position error (paper Figure 7)</h2>\n";
  PlotOptions over_time;
  over_time.width = 1200;
  over_time.height = 300;
  over_time.title = "Error along x and y over time (estimate - truth, map frame)";
  over_time.x_label = "time (s)";
  over_time.y_label = "error (cm)";
  PlotSeries sx = series("x (east)", "#1f77b4", t, dx, false, 1.3);
  PlotSeries sy = series("y (north)", "#ff7f0e", t, dy, false, 1.3);
  PlotSeries sp = series("|error|", "#7f7f7f", t, position, false, 1.0);
  s += figure(linePlot({sp, sx, sy}, over_time));
  const double lim =
      std::max({std::fabs(percentile(dx, 0.5)), std::fabs(percentile(dx, 99.5)),
                std::fabs(percentile(dy, 0.5)), std::fabs(percentile(dy, 99.5)), 1.0});
  PlotOptions hist;
  hist.width = 390;
  hist.height = 280;
  hist.y_label = "frames";
  hist.x_marks = {0.0};
  hist.title = "Error along x";
  hist.x_label = "cm";
  s += figure(histogramPlot(dx, 40, "#1f77b4", hist, -lim, lim));
  hist.title = "Error along y";
  s += figure(histogramPlot(dy, 40, "#ff7f0e", hist, -lim, lim));
  hist.title = "Position error |e|";
  hist.x_marks = {};
  s += figure(
      histogramPlot(position, 40, "#7f7f7f", hist, 0.0, std::max(1.0, percentile(position, 99.5))));

  s += "<h2>Latency per stage (" + escapeXml(m.title) + ")</h2>\n";
  std::vector<RangeRow> rows;
  for (const auto& [stage, samples] : m.latency.samples_ms) {
    if (stage != "total") rows.push_back({stage, samples});
  }
  if (const auto it = m.latency.samples_ms.find("total"); it != m.latency.samples_ms.end()) {
    rows.push_back({"total (critical path)", it->second});
  }
  // The workers' full frames and reads run beside the frame sets, which do not wait for them.
  if (!m.latency.worker_samples_ms.empty())
    rows.push_back({"workers (per frame set fusing their texts)", m.latency.worker_samples_ms});
  PlotOptions lat;
  lat.width = 1200;
  lat.height = 70 + 34 * static_cast<int>(rows.size());
  lat.title =
      "Latency per frame set: the critical path's stages and total, and the workers' jobs "
      "beside it; bar 5th-95th percentile, tick median, dot 99th";
  lat.x_label = "ms";
  s += figure(rangePlot(rows, lat));

  s += "<h2>Tables</h2>\n";
  for (const Table& table : r.tables) s += htmlTable(table);
  if (!r.notes.empty()) {
    s += "<h2>Notes</h2><ul>\n";
    for (const std::string& n : r.notes) s += "<li>" + escapeXml(n) + "</li>\n";
    s += "</ul>\n";
  }
  return s + "</body></html>\n";
}

void writeReport(const EvaluationReport& report, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw IoError(dir + ": cannot create directory: " + ec.message());
  const std::filesystem::path d(dir);
  writeText((d / "results.json").string(), resultsJson(report).dump(2) + "\n");
  writeText((d / "results.md").string(), resultsMarkdown(report));
  writeText((d / "report.html").string(), reportHtml(report));
}

}  // namespace parkloc::eval
