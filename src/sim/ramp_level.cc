#include "sim/ramp_level.h"

#include <opencv2/imgproc.hpp>

#include "sim/garage_builder.h"

namespace parkloc::sim {

GarageLevel rampLevel(const Garage& garage, int from_level) {
  const GarageLevel& from = garage.levels.at(from_level);
  GarageLevel ramp;
  ramp.name = "ramp";
  ramp.lamps = from.lamps;
  // Pillars keep their concrete and their yellow-and-black foot; their painted band and label
  // are decals, left out with every other decal.
  cv::Mat occupancy(static_cast<int>(garage.size.y() * 10), static_cast<int>(garage.size.x() * 10),
                    CV_32F, cv::Scalar(0));
  for (const Box& box : from.boxes) {
    if (box.material != Material::kPillar) continue;
    Box bare = box;
    bare.first_decal = 0;
    bare.decal_count = 0;
    ramp.boxes.push_back(bare);
    cv::rectangle(occupancy, cv::Point(int(box.lo.x() * 10), int(box.lo.y() * 10)),
                  cv::Point(int(box.hi.x() * 10), int(box.hi.y() * 10)), cv::Scalar(1.0), -1);
  }
  const cv::Mat no_paint(
      static_cast<int>(std::ceil(garage.size.y() * garage.paint_texels_per_metre)),
      static_cast<int>(std::ceil(garage.size.x() * garage.paint_texels_per_metre)), CV_8UC1,
      cv::Scalar(0));
  ramp.paint_white = MipTexture(no_paint);
  ramp.paint_yellow = MipTexture(no_paint);
  // Concrete mottling and tyre marks along the lanes, no oil stains (no parking slots); its
  // own stream, so the floors' shades are untouched.
  detail::Rng rng(garage.seed ^ 0x7a3b9c1dULL ^ static_cast<uint64_t>(from_level));
  ramp.floor_shade = detail::floorShade(garage, rng, {}, occupancy);
  return ramp;
}

}  // namespace parkloc::sim
