#include "sim/contact_sheet.h"

#include <algorithm>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "io/labels.h"
#include "io/sequence.h"

namespace parkloc::sim {

cv::Mat makeContactSheet(const std::vector<ContactSheetRow>& rows,
                         const std::vector<std::string>& cameras, int tile_width,
                         bool draw_labels) {
  namespace fs = std::filesystem;
  const int tile_height = tile_width * 10 / 16;
  const int caption_h = 22;
  cv::Mat sheet(static_cast<int>(rows.size()) * (tile_height + caption_h),
                static_cast<int>(cameras.size()) * tile_width, CV_8UC3, cv::Scalar::all(30));
  for (size_t r = 0; r < rows.size(); ++r) {
    const int y0 = static_cast<int>(r) * (tile_height + caption_h);
    cv::putText(sheet, rows[r].caption, {6, y0 + 16}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                cv::Scalar::all(235), 1, cv::LINE_AA);
    const std::string stem = io::timestampStem(rows[r].timestamp);
    for (size_t c = 0; c < cameras.size(); ++c) {
      const fs::path dir(rows[r].sequence_dir);
      cv::Mat img = cv::imread((dir / "images" / cameras[c] / (stem + ".jpg")).string());
      if (img.empty()) img = cv::Mat(tile_height, tile_width, CV_8UC3, cv::Scalar::all(90));
      if (draw_labels) {
        const fs::path lp = dir / "labels" / cameras[c] / (stem + ".json");
        if (fs::exists(lp)) {
          for (const auto& inst : io::loadLabels(lp.string()).instances) {
            std::vector<cv::Point> pts;
            for (const auto& p : inst.polygon) pts.emplace_back(cvRound(p.x()), cvRound(p.y()));
            const cv::Scalar colour =
                inst.occluded_fraction >= 0.5 ? cv::Scalar(0, 0, 255) : cv::Scalar(0, 255, 0);
            cv::polylines(img, pts, true, colour, 2, cv::LINE_AA);
            cv::putText(img, inst.text, pts[0] + cv::Point(0, -4), cv::FONT_HERSHEY_SIMPLEX, 0.6,
                        colour, 2);
          }
        }
      }
      // Scaled to fit the tile with its aspect kept: rigs differ in image shape.
      cv::Mat tile(tile_height, tile_width, CV_8UC3, cv::Scalar::all(30));
      const double scale = std::min(static_cast<double>(tile_width) / img.cols,
                                    static_cast<double>(tile_height) / img.rows);
      const cv::Size fit(std::max(1, static_cast<int>(img.cols * scale)),
                         std::max(1, static_cast<int>(img.rows * scale)));
      cv::resize(img, tile(cv::Rect((tile_width - fit.width) / 2, (tile_height - fit.height) / 2,
                                    fit.width, fit.height)),
                 fit, 0, 0, cv::INTER_AREA);
      cv::putText(tile, cameras[c], {6, tile_height - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                  cv::Scalar(0, 255, 255), 1, cv::LINE_AA);
      tile.copyTo(sheet(
          cv::Rect(static_cast<int>(c) * tile_width, y0 + caption_h, tile_width, tile_height)));
    }
  }
  return sheet;
}

}  // namespace parkloc::sim
