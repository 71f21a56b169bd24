#include "eval/report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "eval/tables.h"
#include "geometry/pose.h"

namespace parkloc::eval {
namespace {

io::StampedPose pose(double t, double x, double y, double yaw) {
  return {t, geometry::Pose2(x, y, yaw).toRigid3()};
}

// A drive around a rectangle with Gaussian position noise on the estimate.
EvaluationReport syntheticReport() {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.03);
  std::vector<io::StampedPose> truth, estimate;
  std::vector<FrameTiming> timings;
  for (int i = 0; i < 300; ++i) {
    const double t = i * 0.1, a = t / 30.0 * 2.0 * M_PI;
    truth.push_back(pose(t, 20.0 * std::cos(a), 8.0 * std::sin(a), a + M_PI / 2));
    estimate.push_back(pose(t, truth.back().pose.translation().x() + noise(rng),
                            truth.back().pose.translation().y() + noise(rng), a + M_PI / 2));
    timings.push_back(
        {20.0 + 5.0 * std::fabs(noise(rng)) * 30, {{"spotting", 15.0}, {"filter", 0.2}}});
  }
  EvaluationReport r;
  r.title = "synthetic";
  r.dataset = "none";
  r.main.key = "parkloc";
  r.main.title = "parkloc";
  r.main.error = trajectoryError(estimate, truth);
  r.main.latency = latencyReport(timings);
  r.main.frames = r.main.frames_with_pose = 300;
  TrajectoryView view;
  view.name = "loop";
  for (const auto& p : truth) {
    view.truth_x.push_back(p.pose.translation().x());
    view.truth_y.push_back(p.pose.translation().y());
  }
  for (const auto& p : estimate) {
    view.estimate_x.push_back(p.pose.translation().x());
    view.estimate_y.push_back(p.pose.translation().y());
  }
  view.landmark_x = {0.0, 10.0};
  view.landmark_y = {0.0, 2.0};
  view.landmark_text = {"B1-001", "B1-<2>"};
  r.trajectories.push_back(view);
  OcrEvaluation ocr;
  ocr.overall.truths = 10;
  ocr.overall.detections = 10;
  ocr.overall.tp = 9;
  ocr.overall.fp = 1;
  ocr.overall.fn = 1;
  ocr.overall.recognized = 9;
  r.ocr = ocr;
  r.tables.push_back(table3(ocr, std::nullopt));
  r.tables.push_back(table5({r.main}));
  return r;
}

TEST(Report, ResultsJsonCarriesTheDocumentedKeys) {
  const EvaluationReport r = syntheticReport();
  const nlohmann::json j = resultsJson(r);
  for (const char* key : {"/position_error_cm/mean", "/position_error_cm/p95",
                          "/yaw_error_deg/mean", "/ocr/detection_f", "/ocr/recognition_accuracy",
                          "/ocr/classification_accuracy", "/latency_ms/median", "/latency_ms/p99",
                          "/frames", "/frames_with_pose", "/tables/table3", "/tables/table5"}) {
    EXPECT_TRUE(j.contains(nlohmann::json::json_pointer(key))) << key;
  }
  EXPECT_NEAR(j["position_error_cm"]["mean"].get<double>(), r.main.error.position_m.mean * 100.0,
              1e-9);
  EXPECT_NEAR(j["ocr"]["detection_f"].get<double>(), 0.9, 1e-9);
  EXPECT_EQ(j["frames"].get<int>(), 300);
  // Table cells with a number carry it as a number.
  EXPECT_TRUE(j["tables"]["table3"]["rows"][1][1].is_number());
}

TEST(Report, HtmlIsSelfContainedAndEscapesText) {
  const std::string html = reportHtml(syntheticReport());
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("http://www.w3.org/2000/svg"), html.find("http"));  // only the namespace
  EXPECT_NE(html.find("B1-&lt;2&gt;"), std::string::npos);
  EXPECT_EQ(html.find("B1-<2>"), std::string::npos);
}

TEST(Report, WritesThreeFiles) {
  const std::string dir = testing::TempDir() + "/parkloc_report_test";
  writeReport(syntheticReport(), dir);
  for (const char* name : {"results.json", "results.md", "report.html"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + name)) << name;
  }
  std::ifstream md(dir + "/results.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find("| Metric | All |"), std::string::npos);
}

TEST(Report, MarkdownTableHasOneRowPerEntry) {
  Table t;
  t.title = "T";
  t.header = {"a", "b"};
  t.rows = {{"x", TableCell::number(1.25, 1)}, {"y", TableCell::percent(0.5)}};
  EXPECT_EQ(tableMarkdown(t),
            "### T\n\n| a | b |\n| --- | ---: |\n| x | 1.2 |\n| y | 50.00 % |\n\n");
}

}  // namespace
}  // namespace parkloc::eval
