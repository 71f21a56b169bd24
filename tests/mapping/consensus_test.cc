#include "mapping/consensus.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace parkloc::mapping {
namespace {

// Sightings at given floor places, one per frame set, with what they read.
struct Readings {
  std::vector<Sighting> sightings;
  std::vector<std::optional<CastSighting>> cast;

  void add(const std::string& text, const Eigen::Vector2d& place, size_t frame, double range = 3.0,
           bool second_opinion = false, bool off_numbering = false) {
    Sighting s;
    s.frame = frame;
    s.camera = 0;
    s.text = text;
    s.recognition_score = 0.9;
    s.second_opinion = second_opinion;
    s.off_numbering = off_numbering;
    sightings.push_back(s);
    CastSighting c;
    c.centre = place;
    c.range_m = range;
    cast.push_back(c);
  }
};

const TextTrack* find(const Consensus& c, const std::string& text) {
  for (const TextTrack& t : c.tracks)
    if (t.text == text) return &t;
  return nullptr;
}

TEST(Consensus, AMisreadIsOutvotedAndMakesNoLandmark) {
  Readings r;
  for (size_t f = 0; f < 8; ++f) r.add("B018", {5.0 + 0.05 * f, 2.0}, f);
  r.add("B016", {5.1, 2.05}, 8);  // a 6 for an 8, once
  const Consensus c = formConsensus(r.sightings, r.cast, {});
  ASSERT_EQ(c.tracks.size(), 1u);
  EXPECT_EQ(c.tracks[0].text, "B018");
  EXPECT_EQ(c.tracks[0].frame_sets, 8);
  EXPECT_EQ(c.tracks[0].misreads, 1);
  EXPECT_EQ(c.misreads, 1u);
  EXPECT_EQ(find(c, "B016"), nullptr);
}

TEST(Consensus, TooFewFrameSetsOrTooLittleAgreementMakeNoLandmark) {
  Readings r;
  r.add("A1", {0.0, 0.0}, 0);
  r.add("A1", {0.0, 0.1}, 1);  // two frame sets only
  for (size_t f = 0; f < 4; ++f) r.add("C7", {10.0, 0.0}, f);
  for (size_t f = 4; f < 7; ++f) r.add("C1", {10.0, 0.1}, f);  // 4 against 3: no agreement
  r.add("Z9", {20.0, 0.0}, 0, /*range=*/15.0);                 // cast from too far
  const Consensus c = formConsensus(r.sightings, r.cast, {});
  EXPECT_TRUE(c.tracks.empty());
  EXPECT_EQ(c.weak_places, 2u);
  EXPECT_EQ(c.unplaced, 1u);
  // The report names the place legible enough to be a landmark, with what it read.
  ASSERT_EQ(c.undecided.size(), 1u);
  EXPECT_EQ(c.undecided[0].why, "close runner-up");
  EXPECT_NEAR(c.undecided[0].place.x(), 10.0, 1e-9);
  ASSERT_EQ(c.undecided[0].readings.size(), 2u);
  EXPECT_EQ(c.undecided[0].readings[0], std::make_pair(std::string("C7"), 4));
  EXPECT_EQ(c.undecided[0].readings[1], std::make_pair(std::string("C1"), 3));
}

TEST(Consensus, TheSameTextNearByClosesALoopFarAwayIsADuplicate) {
  Readings r;
  for (size_t f = 0; f < 4; ++f) r.add("101", {0.0, 0.0}, f);
  // The same number at the end of a loop, the dead reckoning 1.5 m off by then.
  for (size_t f = 50; f < 54; ++f) r.add("101", {1.5, 0.0}, f);
  for (size_t f = 0; f < 4; ++f) r.add("102", {2.5 + 10.0, 0.0}, f);
  for (size_t f = 10; f < 14; ++f) r.add("102", {30.0, 5.0}, f);
  const Consensus c = formConsensus(r.sightings, r.cast, {});
  const TextTrack* loop = find(c, "101");
  ASSERT_NE(loop, nullptr);
  EXPECT_EQ(loop->frame_sets, 8);
  EXPECT_EQ(loop->sightings.size(), 8u);
  EXPECT_EQ(c.loops, 1u);
  EXPECT_EQ(find(c, "102"), nullptr);
  ASSERT_EQ(c.duplicates.size(), 1u);
  EXPECT_EQ(c.duplicates[0], "102");
}

TEST(Consensus, AFarPlaceReadInFarFewerFrameSetsIsAMisreadOfAnotherNumber) {
  Readings r;
  // 045 in full sight for 8 frame sets; a worn 046 far down the level read as 045 in 3.
  for (size_t f = 0; f < 8; ++f) r.add("045", {20.0, 0.0}, f);
  for (size_t f = 40; f < 43; ++f) r.add("045", {-18.0, -10.0}, f);
  const Consensus c = formConsensus(r.sightings, r.cast, {});
  const TextTrack* kept = find(c, "045");
  ASSERT_NE(kept, nullptr);
  EXPECT_EQ(kept->frame_sets, 8);
  EXPECT_NEAR(kept->place.x(), 20.0, 1e-9);
  EXPECT_TRUE(c.duplicates.empty());
  ASSERT_EQ(c.outweighed_duplicates.size(), 1u);
  EXPECT_EQ(c.outweighed_duplicates[0], "045");
  // Seen in 5 frame sets there instead (under twice as few as 8), neither place keeps it.
  for (size_t f = 43; f < 45; ++f) r.add("045", {-18.0, -10.0}, f);
  const Consensus close = formConsensus(r.sightings, r.cast, {});
  EXPECT_EQ(find(close, "045"), nullptr);
  ASSERT_EQ(close.duplicates.size(), 1u);
  EXPECT_TRUE(close.outweighed_duplicates.empty());
}

TEST(Consensus, UnconfirmedReadingsVoteButMakeNoLandmarkAlone) {
  Readings r;
  // A car's plate, read freely off the numbering the drive was read against.
  for (size_t f = 0; f < 5; ++f) r.add("04", {20.0, 1.0}, f, 3.0, false, /*off_numbering=*/true);
  // Another floor text (an EXIT) that only the fallback recognizer matched to a number.
  for (size_t f = 0; f < 6; ++f) r.add("113", {4.0, 1.0}, f, 3.0, /*second_opinion=*/true);
  // A number the first reader reads 4 times and misreads 5 times, the fallback reads 6 times.
  for (size_t f = 0; f < 4; ++f) r.add("132", {9.0, 1.0}, f);
  for (size_t f = 4; f < 9; ++f) r.add("152", {9.0, 1.0}, f);
  for (size_t f = 9; f < 15; ++f) r.add("132", {9.0, 1.0}, f, 3.0, /*second_opinion=*/true);
  Consensus c = formConsensus(r.sightings, r.cast, {});
  EXPECT_EQ(find(c, "113"), nullptr);
  EXPECT_EQ(find(c, "04"), nullptr);
  EXPECT_EQ(c.unconfirmed_places, 2u);
  ASSERT_EQ(c.undecided.size(), 2u);
  EXPECT_EQ(c.undecided[0].why, "unconfirmed");
  EXPECT_EQ(find(c, "152"), nullptr);
  const TextTrack* number = find(c, "132");
  ASSERT_NE(number, nullptr);
  EXPECT_EQ(number->frame_sets, 10);

  ConsensusOptions options;
  options.min_confirmed_frame_sets = 0;
  c = formConsensus(r.sightings, r.cast, options);
  EXPECT_NE(find(c, "113"), nullptr);
  EXPECT_NE(find(c, "04"), nullptr);
  EXPECT_EQ(c.unconfirmed_places, 0u);
}

TEST(Consensus, OfTwoNumbersSideBySideOutOfSequenceTheLessSeenIsLeftOut) {
  Readings r;
  for (size_t f = 0; f < 9; ++f) r.add("019", {0.0, 0.0}, f);
  for (size_t f = 0; f < 4; ++f) r.add("070", {2.5, 0.0}, f);   // 020 misread
  for (size_t f = 0; f < 4; ++f) r.add("C021", {5.0, 0.0}, f);  // another format: no sequence
  for (size_t f = 0; f < 5; ++f) r.add("040", {9.0, 0.0}, f);   // beyond the radius
  Consensus c = formConsensus(r.sightings, r.cast, {});
  EXPECT_NE(find(c, "019"), nullptr);
  EXPECT_EQ(find(c, "070"), nullptr);
  EXPECT_NE(find(c, "C021"), nullptr);
  EXPECT_NE(find(c, "040"), nullptr);
  ASSERT_EQ(c.out_of_sequence.size(), 1u);
  EXPECT_EQ(c.out_of_sequence[0], "070");

  ConsensusOptions options;
  options.sequence_radius_m = 0.0;
  c = formConsensus(r.sightings, r.cast, options);
  EXPECT_NE(find(c, "070"), nullptr);
  EXPECT_TRUE(c.out_of_sequence.empty());
}

TEST(Consensus, TheSequenceDecidesAContestedPlace) {
  Readings r;
  for (size_t f = 0; f < 12; ++f) r.add("146", {0.0, 0.0}, f);
  // 147 against 167 (a 4 blurred to a 6) and 127, a landmark of the other row: too close a
  // contest by the counts alone.
  for (size_t f = 0; f < 9; ++f) r.add("147", {2.5, 0.0}, f);
  for (size_t f = 9; f < 16; ++f) r.add("167", {2.5, 0.1}, f);
  for (size_t f = 16; f < 23; ++f) r.add("127", {2.5, -0.1}, f);
  for (size_t f = 0; f < 10; ++f) r.add("127", {2.5, 8.0}, f);
  // A contest whose rival is in sequence too (031 beside 032 as well as 033): left undecided.
  for (size_t f = 0; f < 10; ++f) r.add("031", {20.0, 0.0}, f);
  for (size_t f = 0; f < 10; ++f) r.add("034", {25.0, 0.0}, f);
  for (size_t f = 0; f < 6; ++f) r.add("033", {22.5, 0.0}, f);
  for (size_t f = 6; f < 11; ++f) r.add("032", {22.5, 0.1}, f);
  Consensus c = formConsensus(r.sightings, r.cast, {});
  const TextTrack* decided = find(c, "147");
  ASSERT_NE(decided, nullptr);
  EXPECT_EQ(decided->frame_sets, 9);
  EXPECT_NEAR(decided->place.x(), 2.5, 0.1);
  EXPECT_EQ(c.decided_by_sequence, std::vector<std::string>{"147"});
  EXPECT_EQ(find(c, "167"), nullptr);
  EXPECT_EQ(find(c, "033"), nullptr);
  EXPECT_EQ(find(c, "032"), nullptr);
  ASSERT_EQ(c.undecided.size(), 1u);
  EXPECT_NEAR(c.undecided[0].place.x(), 22.5, 0.1);

  ConsensusOptions off;
  off.sequence_decides_contests = false;
  c = formConsensus(r.sightings, r.cast, off);
  EXPECT_EQ(find(c, "147"), nullptr);
  EXPECT_EQ(c.undecided.size(), 2u);

  // The same reading winning a second contest on the other side of 146: one landmark only.
  for (size_t f = 30; f < 38; ++f) r.add("147", {-2.5, 0.0}, f);
  for (size_t f = 38; f < 45; ++f) r.add("167", {-2.5, 0.1}, f);
  c = formConsensus(r.sightings, r.cast, {});
  EXPECT_EQ(std::count_if(c.tracks.begin(), c.tracks.end(),
                          [](const TextTrack& t) { return t.text == "147"; }),
            1);
}

TEST(Consensus, TheRowsNumberingDecidesAContestAndWhichNeighbourIsTheMisread) {
  Readings r;
  // A row along x, numbers growing with x: 356 and 357 decided.
  for (size_t f = 0; f < 12; ++f) r.add("356", {0.0, 0.0}, f);
  for (size_t f = 0; f < 12; ++f) r.add("357", {3.2, 0.0}, f);
  // 10.7 m on, 361 misread 501 in more frame sets than 362 beside it is read.
  for (size_t f = 0; f < 9; ++f) r.add("501", {13.9, 0.0}, f);
  for (size_t f = 0; f < 6; ++f) r.add("362", {16.4, 0.0}, f);
  // 16.4 m back, a worn 7 of 350 read 2 more often than 7: 2 is the wrong way along the row.
  for (size_t f = 20; f < 28; ++f) r.add("352", {-16.4, 0.0}, f);
  for (size_t f = 28; f < 35; ++f) r.add("350", {-16.4, 0.1}, f);
  for (size_t f = 35; f < 36; ++f) r.add("349", {-16.4, -0.1}, f);  // once: does not compete
  Consensus c = formConsensus(r.sightings, r.cast, {});
  EXPECT_NE(find(c, "362"), nullptr);
  EXPECT_EQ(find(c, "501"), nullptr);
  EXPECT_EQ(c.out_of_sequence, std::vector<std::string>{"501"});
  EXPECT_NE(find(c, "350"), nullptr);
  EXPECT_EQ(find(c, "352"), nullptr);
  EXPECT_EQ(c.decided_by_sequence, std::vector<std::string>{"350"});

  // Without the rows: the more seen of the two neighbours stays, the contest stays open.
  ConsensusOptions off;
  off.row_sequence = false;
  c = formConsensus(r.sightings, r.cast, off);
  EXPECT_NE(find(c, "501"), nullptr);
  EXPECT_EQ(find(c, "362"), nullptr);
  EXPECT_EQ(find(c, "350"), nullptr);
  EXPECT_TRUE(c.decided_by_sequence.empty());
}

TEST(Consensus, TheSequenceMayTakeALessSeenReadingOfAContestedPlace) {
  Readings r;
  for (size_t f = 0; f < 12; ++f) r.add("131", {5.3, 0.0}, f);
  for (size_t f = 0; f < 12; ++f) r.add("133", {-0.4, 0.0}, f);
  // 132 between them, read 152 nearly as often (less often here).
  for (size_t f = 0; f < 8; ++f) r.add("152", {2.8, 0.0}, f);
  for (size_t f = 8; f < 14; ++f) r.add("132", {2.8, 0.1}, f);
  Consensus c = formConsensus(r.sightings, r.cast, {});
  ASSERT_NE(find(c, "132"), nullptr);
  EXPECT_EQ(find(c, "132")->frame_sets, 6);
  EXPECT_EQ(find(c, "152"), nullptr);

  ConsensusOptions most_seen_only;
  most_seen_only.sequence_decides_for_any_reading = false;
  c = formConsensus(r.sightings, r.cast, most_seen_only);
  EXPECT_EQ(find(c, "132"), nullptr);
}

TEST(Consensus, TwoPlacesReadTogetherAreTwoTextsNotALoop) {
  Readings r;
  // A012 and, 2.5 m before it, A011 read as A012 in the same frame sets (a 1 read as 2):
  // near enough for a loop, but one text is at one place in a frame set.
  for (size_t f = 0; f < 12; ++f) r.add("A012", {2.5, 0.0}, f);
  for (size_t f = 4; f < 9; ++f) r.add("A012", {0.0, 0.0}, f);
  Consensus c = formConsensus(r.sightings, r.cast, {});
  const TextTrack* kept = find(c, "A012");
  ASSERT_NE(kept, nullptr);
  EXPECT_EQ(kept->frame_sets, 12);
  EXPECT_NEAR(kept->place.x(), 2.5, 1e-9);
  EXPECT_EQ(c.loops, 0u);
  EXPECT_EQ(c.outweighed_duplicates, std::vector<std::string>{"A012"});

  // Without the check the two merge into one landmark between them.
  ConsensusOptions off;
  off.min_frame_sets_seen_apart = 0;
  c = formConsensus(r.sightings, r.cast, off);
  ASSERT_NE(find(c, "A012"), nullptr);
  EXPECT_EQ(c.loops, 1u);
  EXPECT_LT(find(c, "A012")->place.x(), 2.0);
}

}  // namespace
}  // namespace parkloc::mapping
