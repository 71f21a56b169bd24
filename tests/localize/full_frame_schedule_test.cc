#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "localize/read_planning.h"

namespace parkloc::localize {
namespace {

constexpr size_t kCameras = 4;

int countTrue(const std::vector<bool>& v) {
  int n = 0;
  for (bool b : v) n += b;
  return n;
}

TEST(FullFrameScheduleTest, WhileTrackingTheRoundRobinSweepsOneCameraAtATimeEachOncePerInterval) {
  ReadingOptions options;
  options.full_frame_interval = 8;
  FullFrameSchedule schedule(options, /*guided=*/true);
  std::vector<int> sweeps(kCameras, 0);
  int sweeping_frames = 0;
  for (int k = 0; k < 16; ++k) {
    const FullFrameChoice choice = schedule.next(kCameras, /*tracking=*/true, true);
    EXPECT_FALSE(choice.all);
    EXPECT_FALSE(choice.searching);
    ASSERT_LE(countTrue(choice.full_frame), 1) << "frame set " << k;
    EXPECT_EQ(choice.sweeping, countTrue(choice.full_frame) == 1);
    sweeping_frames += choice.sweeping;
    for (size_t c = 0; c < kCameras; ++c) sweeps[c] += choice.full_frame[c];
  }
  EXPECT_EQ(sweeping_frames, 8);  // 4 camera images per 8 frame sets, in turn
  for (size_t c = 0; c < kCameras; ++c) EXPECT_EQ(sweeps[c], 2) << "camera " << c;
}

TEST(FullFrameScheduleTest, WithoutTheRoundRobinEveryCameraGoesFullFrameEveryInterval) {
  ReadingOptions options;
  options.full_frame_interval = 5;
  options.full_frame_round_robin = false;
  FullFrameSchedule schedule(options, true);
  std::vector<int> all_frames;
  for (int k = 0; k < 15; ++k) {
    const FullFrameChoice choice = schedule.next(kCameras, true, true);
    EXPECT_EQ(countTrue(choice.full_frame), choice.all ? 4 : 0);
    if (choice.all) all_frames.push_back(k);
  }
  EXPECT_EQ(all_frames, (std::vector<int>{4, 9, 14}));
}

TEST(FullFrameScheduleTest, BeforeTheFirstFixOneCameraPerFrameSetIsSearchedInTurn) {
  ReadingOptions options;
  options.search_cameras_per_frame = 1;
  FullFrameSchedule schedule(options, true);
  for (int k = 0; k < 8; ++k) {
    const FullFrameChoice choice = schedule.next(kCameras, false, /*initialised=*/false);
    EXPECT_TRUE(choice.searching);
    ASSERT_EQ(countTrue(choice.full_frame), 1);
    EXPECT_TRUE(choice.full_frame[static_cast<size_t>(k) % kCameras]) << "frame set " << k;
  }
}

TEST(FullFrameScheduleTest, OnWorkersTheSearchTakesACameraPerFreeWorkerAndWaitsForOne) {
  // The search's turn goes on where it stopped: a busy worker makes the camera due wait, it
  // does not skip it; two free workers search two cameras.
  ReadingOptions options;
  options.search_cameras_per_frame = 1;
  FullFrameSchedule schedule(options, true);
  const auto cameras = [](const FullFrameChoice& choice) {
    std::vector<size_t> out;
    for (size_t c = 0; c < choice.full_frame.size(); ++c)
      if (choice.full_frame[c]) out.push_back(c);
    return out;
  };
  EXPECT_EQ(cameras(schedule.next(kCameras, false, false, false, 1)), std::vector<size_t>{0});
  const FullFrameChoice busy = schedule.next(kCameras, false, false, false, 0);
  EXPECT_TRUE(busy.searching);
  EXPECT_TRUE(cameras(busy).empty());
  EXPECT_EQ(cameras(schedule.next(kCameras, false, false, false, 1)), std::vector<size_t>{1});
  EXPECT_EQ(cameras(schedule.next(kCameras, false, false, false, 2)), (std::vector<size_t>{2, 3}));
  EXPECT_EQ(cameras(schedule.next(kCameras, false, false, false, 2)), (std::vector<size_t>{0, 1}));
}

TEST(FullFrameScheduleTest, ASweepDueWhileTheWorkerIsBusyGoesToItWhenItIsFree) {
  ReadingOptions options;
  options.full_frame_interval = 8;
  FullFrameSchedule inline_schedule(options, true), worker(options, true);
  std::vector<size_t> inline_sweeps, worker_sweeps;
  for (int k = 0; k < 16; ++k) {
    const FullFrameChoice a = inline_schedule.next(kCameras, true, true);
    // The worker is busy on frame sets 1 and 9, when sweeps come due (1, 3, 5, ...).
    const bool free = k % 8 != 1;
    const FullFrameChoice b = worker.next(kCameras, true, true, false, free ? 1 : 0);
    ASSERT_LE(countTrue(b.full_frame), 1);
    EXPECT_TRUE(free || !b.sweeping) << k;
    for (size_t c = 0; c < kCameras; ++c) {
      if (a.full_frame[c]) inline_sweeps.push_back(c);
      if (b.full_frame[c]) worker_sweeps.push_back(c);
    }
  }
  // The same cameras in the same order: none skipped, the held ones a frame set late.
  EXPECT_EQ(worker_sweeps, inline_sweeps);
  EXPECT_EQ(worker_sweeps.size(), 8u);
}

TEST(FullFrameScheduleTest, ALostTrackAndThePapersPipelineSpotEveryCameraEveryFrameSet) {
  ReadingOptions options;
  FullFrameSchedule lost(options, true), paper(options, /*guided=*/false);
  for (int k = 0; k < 5; ++k) {
    const FullFrameChoice l = lost.next(kCameras, /*tracking=*/false, /*initialised=*/true);
    EXPECT_TRUE(l.all);
    EXPECT_FALSE(l.searching);
    EXPECT_EQ(countTrue(l.full_frame), 4);
    const FullFrameChoice p = paper.next(kCameras, false, false);
    EXPECT_TRUE(p.all);
    EXPECT_FALSE(p.searching);
    EXPECT_EQ(countTrue(p.full_frame), 4);
  }
}

TEST(FullFrameScheduleTest, TheRoundRobinStartsAfreshWhenTheTrackBegins) {
  ReadingOptions options;
  options.full_frame_interval = 8;
  FullFrameSchedule schedule(options, true);
  // 4 slots in 8 tracked frame sets: the 2nd, 4th, 6th and 8th; counted again after a loss.
  EXPECT_FALSE(schedule.next(kCameras, true, true).sweeping);
  EXPECT_TRUE(schedule.next(kCameras, true, true).sweeping);
  EXPECT_FALSE(schedule.next(kCameras, true, true).sweeping);
  EXPECT_TRUE(schedule.next(kCameras, false, true).all);
  EXPECT_FALSE(schedule.next(kCameras, true, true).sweeping);
  EXPECT_TRUE(schedule.next(kCameras, true, true).sweeping);
}


TEST(FullFrameSchedule, ATentativeTrackSweepsOneCameraEveryFrameSet) {
  ReadingOptions options;
  options.full_frame_interval = 30;
  options.tentative_full_frame_interval = 4;
  FullFrameSchedule tentative(options, true), tracking(options, true);
  int tentative_sweeps = 0, tracking_sweeps = 0;
  for (int k = 0; k < 8; ++k) {
    const FullFrameChoice t = tentative.next(4, true, true, true);
    tentative_sweeps += static_cast<int>(std::count(t.full_frame.begin(), t.full_frame.end(), true));
    EXPECT_TRUE(t.sweeping) << k;
    const FullFrameChoice c = tracking.next(4, true, true, false);
    tracking_sweeps += static_cast<int>(std::count(c.full_frame.begin(), c.full_frame.end(), true));
  }
  EXPECT_EQ(tentative_sweeps, 8);  // each of the four cameras twice, one a frame set
  EXPECT_LE(tracking_sweeps, 2);
}

}  // namespace
}  // namespace parkloc::localize
