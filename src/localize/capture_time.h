#pragma once
// Cameras that are not triggered together: each image of a frame set was captured at its own
// time (CameraInput::capture_time), when the vehicle stood a little elsewhere than at the frame
// set's time: at 2 m/s a camera 30 ms late sees the garage from 6 cm further on. Every stage
// works at the frame set's time, so each such camera's mounting is moved by the vehicle's
// motion over its offset (the odometry's speed and yaw rate, held over the few milliseconds):
// its observations then say where the vehicle was at the frame set's time.
#include <optional>

#include "common/odometry_sample.h"
#include "geometry/rig.h"
#include "localize/frame_types.h"

namespace parkloc::localize {

// The vehicle at time t + dt in the vehicle frame at t, moving at `motion`'s speed and yaw
// rate (an arc).
geometry::Rigid3 vehicleMotionOver(const OdometrySample& motion, double dt);

// `nominal` with the mounting of each camera whose input carries a capture time other than
// the frame set's moved as above. Without `motion` (no odometry) the rig stays as it is.
geometry::Rig rigAtFrameTime(const geometry::Rig& nominal, const FrameInput& frame,
                             const std::optional<OdometrySample>& motion);

}  // namespace parkloc::localize
