#include "sim/number_styles.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "sim/text_raster.h"

namespace parkloc::sim {
namespace {

double uniform(std::mt19937_64& rng, double a, double b) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}

constexpr uint8_t kInk = 128;  // coverage at which a texel counts as ink

// The typical stroke width of the ink in columns [x0, x1): the median length of the
// horizontal ink runs (most rows of a digit cross vertical strokes).
double strokeWidth(const cv::Mat& coverage, int x0, int x1) {
  std::vector<int> runs;
  for (int y = 0; y < coverage.rows; ++y) {
    const uint8_t* row = coverage.ptr<uint8_t>(y);
    int run = 0;
    for (int x = x0; x <= x1; ++x) {
      if (x < x1 && row[x] >= kInk) {
        ++run;
      } else if (run > 0) {
        runs.push_back(run);
        run = 0;
      }
    }
  }
  if (runs.empty()) return 1.0;
  std::nth_element(runs.begin(), runs.begin() + runs.size() / 2, runs.end());
  return runs[runs.size() / 2];
}

// A coverage texture of a rectangle `w` x `h` metres at `tpm` texels per metre: filled, or
// only its frame `line_m` wide.
cv::Mat rectangleInk(double w, double h, double tpm, double line_m) {
  const int cols = std::max(2, static_cast<int>(std::lround(w * tpm)));
  const int rows = std::max(2, static_cast<int>(std::lround(h * tpm)));
  cv::Mat ink(rows, cols, CV_8UC1, cv::Scalar(255));
  if (line_m > 0.0) {
    const int line = std::max(1, static_cast<int>(std::lround(line_m * tpm)));
    ink(cv::Rect(line, line, std::max(0, cols - 2 * line), std::max(0, rows - 2 * line))).setTo(0);
  }
  return ink;
}

// A decal of `ink` around text decal `text`, `margin_u`, `margin_v` metres out from its box.
Decal surroundingDecal(Garage& g, const Decal& text, const cv::Mat& ink, double margin_u,
                       double margin_v, const Eigen::Vector3f& color) {
  constexpr int kPad = 3;
  g.textures.emplace_back(padInk(ink, kPad));
  Decal d;
  d.origin = text.origin - static_cast<float>(margin_u) * text.axis_u -
             static_cast<float>(margin_v) * text.axis_v;
  d.axis_u = text.axis_u;
  d.axis_v = text.axis_v;
  d.size_u = text.size_u + 2.0f * static_cast<float>(margin_u);
  d.size_v = text.size_v + 2.0f * static_cast<float>(margin_v);
  // The texture spans the size exactly (rectangleInk rounds, so take its own scale).
  d.texels_per_metre = static_cast<float>(ink.cols / d.size_u);
  d.pad = kPad;
  d.texture = static_cast<int>(g.textures.size()) - 1;
  d.color = color;
  d.opacity = text.opacity;
  return d;
}

}  // namespace

void cutStencilBridges(cv::Mat& coverage) {
  CV_Assert(coverage.type() == CV_8UC1);
  // Glyphs: runs of columns holding ink.
  std::vector<std::pair<int, int>> glyphs;
  int start = -1;
  for (int x = 0; x <= coverage.cols; ++x) {
    const bool ink = x < coverage.cols && cv::countNonZero(coverage.col(x) >= kInk) > 0;
    if (ink && start < 0) start = x;
    if (!ink && start >= 0) {
      glyphs.emplace_back(start, x);
      start = -1;
    }
  }
  int tallest = 0;
  std::vector<std::pair<int, int>> rows(glyphs.size(), {coverage.rows, -1});
  for (size_t i = 0; i < glyphs.size(); ++i) {
    const cv::Mat band = coverage.colRange(glyphs[i].first, glyphs[i].second) >= kInk;
    for (int y = 0; y < band.rows; ++y)
      if (cv::countNonZero(band.row(y)) > 0) {
        rows[i].first = std::min(rows[i].first, y);
        rows[i].second = std::max(rows[i].second, y);
      }
    tallest = std::max(tallest, rows[i].second - rows[i].first + 1);
  }
  for (size_t i = 0; i < glyphs.size(); ++i) {
    const auto [x0, x1] = glyphs[i];
    const int height = rows[i].second - rows[i].first + 1;
    if (height < tallest / 2) continue;  // a dash or a dot: nothing to hold together
    const double stroke = strokeWidth(coverage, x0, x1);
    const int bridge = std::max(1, static_cast<int>(std::lround(0.1 * height)));
    const int cx = (x0 + x1) / 2;
    for (int y = rows[i].first; y <= rows[i].second; ++y) {
      uint8_t* row = coverage.ptr<uint8_t>(y);
      if (row[cx] < kInk) continue;
      int a = cx, b = cx;
      while (a > x0 && row[a - 1] >= kInk) --a;
      while (b + 1 < x1 && row[b + 1] >= kInk) ++b;
      if (b - a + 1 < 1.8 * stroke) continue;  // a vertical stroke: no bridge across it
      for (int x = cx - bridge / 2; x < cx - bridge / 2 + bridge; ++x)
        if (x >= x0 && x < x1) row[x] = 0;
    }
  }
}

void hollowOutGlyphs(cv::Mat& coverage) {
  CV_Assert(coverage.type() == CV_8UC1);
  cv::Mat dist;
  cv::distanceTransform(coverage >= kInk, dist, cv::DIST_L2, 3);
  double max_half_stroke = 0.0;
  cv::minMaxLoc(dist, nullptr, &max_half_stroke);
  const int r = std::max(1, static_cast<int>(std::lround(0.5 * max_half_stroke)));
  cv::Mat eroded;
  cv::erode(coverage, eroded, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1}));
  coverage = coverage - eroded;
}

void styleNumbers(Garage& g, const AppearanceOptions& a, std::mt19937_64& rng) {
  const Eigen::Vector3f kBlack(0.06f, 0.06f, 0.06f), kWhite(0.88f, 0.88f, 0.85f),
      kYellow(0.90f, 0.72f, 0.12f);
  // Patches under numbers: the blue and green of reserved bays, yellow, dark grey; each with
  // the ink that stands out on it.
  const std::vector<std::pair<Eigen::Vector3f, Eigen::Vector3f>> patches = {
      {{0.12f, 0.26f, 0.60f}, kWhite},
      {{0.16f, 0.45f, 0.26f}, kWhite},
      {{0.90f, 0.72f, 0.12f}, kBlack},
      {{0.20f, 0.20f, 0.21f}, kYellow}};
  for (GarageLevel& level : g.levels) {
    // Decals to put before each text decal (patches and frames lie under the number).
    std::vector<std::vector<Decal>> before(level.floor_decals.size());
    for (const TextItem& item : level.texts) {
      if (item.floor_decal < 0 || item.landmark.cls != map::TextClass::kParkingNumber) continue;
      Decal& d = level.floor_decals[static_cast<size_t>(item.floor_decal)];
      if (d.texture < 0) continue;
      // Fixed draws per number, whatever the shares: one factor's share does not move another's
      // numbers.
      const double u_stencil = uniform(rng, 0, 1), u_outline = uniform(rng, 0, 1),
                   u_box = uniform(rng, 0, 1), u_fade = uniform(rng, 0, 1),
                   u_kind = uniform(rng, 0, 1), u_colour = uniform(rng, 0, 1),
                   fade_severity = uniform(rng, 0.3, 0.95), fade_opacity = uniform(rng, 0.55, 0.9);
      const uint64_t wear_seed = rng();
      const bool stencil = u_stencil < a.stencil;
      const bool outlined = !stencil && u_outline < a.outlined;
      const bool faded = u_fade < a.faded;
      if (stencil || outlined || faded) {
        cv::Mat texels = g.textures[static_cast<size_t>(d.texture)].levelTexels(0).clone();
        const double before_sum = cv::sum(texels)[0];
        if (stencil) cutStencilBridges(texels);
        if (outlined) hollowOutGlyphs(texels);
        if (faded) {
          std::mt19937_64 wear_rng(wear_seed);
          wearInk(texels, fade_severity, wear_rng);
          d.wear = std::max(d.wear, static_cast<float>(fade_severity));
          d.opacity *= static_cast<float>(fade_opacity);
        }
        const double after_sum = cv::sum(texels)[0];
        if (before_sum > 0.0) d.ink_kept *= static_cast<float>(after_sum / before_sum);
        g.textures[static_cast<size_t>(d.texture)] = MipTexture(texels);
      }
      if (u_box < a.boxed) {
        // Margins that keep a frame clear of the slot's side lines.
        const double h = d.size_v;
        const double side_room = 0.5 * (g.spec.slot_width - d.size_u) - 0.12;
        if (u_kind < 0.5) {
          const double line = 0.1 * h;
          const double mu = std::clamp(side_room - line, 0.02, 0.3 * h);
          const double mv = 0.25 * h;
          before[static_cast<size_t>(item.floor_decal)].push_back(surroundingDecal(
              g, d, rectangleInk(d.size_u + 2 * mu, d.size_v + 2 * mv, 100.0, line), mu, mv,
              d.color));
        } else {
          const auto& [patch, ink] =
              patches[std::min(patches.size() - 1, static_cast<size_t>(u_colour * patches.size()))];
          const double mu = std::clamp(side_room, 0.03, 0.3 * h), mv = 0.3 * h;
          Decal p = surroundingDecal(
              g, d, rectangleInk(d.size_u + 2 * mu, d.size_v + 2 * mv, 100.0, 0.0), mu, mv, patch);
          p.opacity = 0.95f;
          p.backing = -2;  // marks the patch for the re-pointing below
          before[static_cast<size_t>(item.floor_decal)].push_back(p);
          d.color = ink;
        }
      }
    }
    // The new list: each decal after what lies under it; text items and backings re-pointed.
    std::vector<Decal> decals;
    std::vector<int> moved(level.floor_decals.size());
    for (size_t i = 0; i < level.floor_decals.size(); ++i) {
      int patch_index = -1;
      for (Decal under : before[i]) {
        if (under.backing == -2) {
          under.backing = -1;
          patch_index = static_cast<int>(decals.size());
        }
        decals.push_back(under);
      }
      Decal d = level.floor_decals[i];
      d.backing = patch_index;
      moved[i] = static_cast<int>(decals.size());
      decals.push_back(d);
    }
    level.floor_decals = std::move(decals);
    for (TextItem& item : level.texts)
      if (item.floor_decal >= 0) item.floor_decal = moved[static_cast<size_t>(item.floor_decal)];
  }
}

}  // namespace parkloc::sim
