#include "localize/level_estimate.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "localize/shared_places.h"

namespace parkloc::localize {
namespace {

map::Landmark landmark(const std::string& text, const std::string& level, double x,
                       map::TextClass cls = map::TextClass::kParkingNumber) {
  map::Landmark l;
  l.id = level + "/" + text + "/" + std::to_string(x);
  l.text = text;
  l.level = level;
  l.cls = cls;
  l.position = {x, 0.0, 0.0};
  l.width = 0.9;
  l.height = 0.4;
  return l;
}

// "117" is painted at one place on both levels, "118" at different places; B2's pillar says
// "A-1" where B1's says "B1"; "LIFT" is on B1 only.
map::HdMap twoLevels() {
  const auto pillar = map::TextClass::kPillar;
  return map::HdMap({landmark("117", "B1", 0.0), landmark("117", "B2", 0.0),
                     landmark("118", "B1", 3.0), landmark("118", "B2", 9.0),
                     landmark("B1", "B1", 6.0, pillar), landmark("A-1", "B2", 6.0, pillar),
                     landmark("LIFT", "B1", 12.0, map::TextClass::kOther)},
                    "two levels");
}

struct Seen {
  std::vector<CameraResult> cameras{CameraResult{}};
  std::vector<Association> associations;
  Seen& read(const std::string& text, const std::string& accepted_id = "",
             map::TextClass cls = map::TextClass::kParkingNumber) {
    ocr::TextInstance i;
    i.text = text;
    i.cls = cls;
    i.recognition_score = 0.9f;
    cameras[0].instances.push_back(i);
    Association a;
    a.text = text;
    a.landmark_id = accepted_id;
    a.verdict = accepted_id.empty() ? AssociationVerdict::kNotInMap : AssociationVerdict::kAccepted;
    associations.push_back(a);
    return *this;
  }
};

void see(LevelEstimate& e, double t, const Seen& seen, std::vector<std::string>* warnings = nullptr) {
  std::vector<std::string> w;
  e.predict(t);
  e.update(seen.cameras, seen.associations, warnings ? *warnings : w);
}

TEST(LevelEstimateTest, TextsOnEveryLevelDecideNothing) {
  const map::HdMap map = twoLevels();
  LevelEstimate e(map, {}, "");
  EXPECT_FALSE(e.belief().decided);
  for (int i = 0; i < 20; ++i) see(e, 0.1 * i, Seen().read("117").read("118"));
  EXPECT_FALSE(e.belief().decided);
  EXPECT_NEAR(e.belief().probability, 0.5, 1e-9);
  EXPECT_EQ(e.restriction(), "");
}

TEST(LevelEstimateTest, ALevelSignDecidesWithinAFewReadings) {
  const map::HdMap map = twoLevels();
  LevelEstimate e(map, {}, "");
  see(e, 0.0, Seen().read("B1", "", map::TextClass::kPillar));
  EXPECT_FALSE(e.belief().decided);  // one reading is not 99:1
  EXPECT_EQ(e.belief().level, "B1");
  see(e, 0.1, Seen().read("B1", "", map::TextClass::kPillar));
  EXPECT_TRUE(e.belief().decided);
  EXPECT_EQ(e.restriction(), "B1");
}

TEST(LevelEstimateTest, OneTextSeenTwiceInAFrameSetCountsOnce) {
  const map::HdMap map = twoLevels();
  LevelEstimate once(map, {}, ""), twice(map, {}, "");
  see(once, 0.0, Seen().read("A-1", "", map::TextClass::kPillar));
  see(twice, 0.0,
      Seen().read("A-1", "", map::TextClass::kPillar).read("A-1", "", map::TextClass::kPillar));
  EXPECT_EQ(once.belief().level, "B2");
  EXPECT_DOUBLE_EQ(once.belief().probability, twice.belief().probability);
  const double ratio = LevelOptions{}.text_ratio;
  EXPECT_NEAR(once.belief().probability, ratio / (1.0 + ratio), 1e-9);
}

TEST(LevelEstimateTest, ThePlaceOfAGatedTextTellsTheLevel) {
  const map::HdMap map = twoLevels();
  LevelEstimate e(map, {}, "");
  // "118" associated with B2's landmark: only B2 has it there.
  const std::string b2_118 = map.findByText("118", "B2").front()->id;
  for (int i = 0; i < 4; ++i) see(e, 0.1 * i, Seen().read("118", b2_118));
  EXPECT_TRUE(e.belief().decided);
  EXPECT_EQ(e.belief().level, "B2");
  // "117" associated at its shared place says nothing.
  LevelEstimate shared(map, {}, "");
  const std::string b1_117 = map.findByText("117", "B1").front()->id;
  for (int i = 0; i < 4; ++i) see(shared, 0.1 * i, Seen().read("117", b1_117));
  EXPECT_FALSE(shared.belief().decided);
}

TEST(LevelEstimateTest, AHintStartsDecidedAndTheEstimateFollowsALevelChange) {
  const map::HdMap map = twoLevels();
  const std::string b1_117 = map.findByText("117", "B1").front()->id;
  LevelEstimate e(map, {}, "B1");
  EXPECT_TRUE(e.belief().decided);
  EXPECT_EQ(e.belief().level, "B1");
  // A minute on B1, "117" in view, now and then its sign.
  double t = 0.0;
  for (int i = 0; i < 600; ++i, t += 0.1) {
    Seen seen = Seen().read("117", b1_117);
    if (i % 10 == 0) seen.read("B1", "", map::TextClass::kPillar);
    see(e, t, seen);
  }
  EXPECT_EQ(e.restriction(), "B1");
  // A ramp: 4 s without text.
  for (int i = 0; i < 40; ++i, t += 0.1) see(e, t, Seen());
  EXPECT_EQ(e.belief().level, "B1");
  // B2: "117" at its shared place, and B2's pillar label.
  int frames = 0;
  while (e.restriction() != "B2" && frames < 100) {
    see(e, t, Seen().read("117", b1_117).read("A-1", "", map::TextClass::kPillar));
    t += 0.1;
    ++frames;
  }
  EXPECT_EQ(e.restriction(), "B2");
  EXPECT_LE(frames, 5);
}

TEST(LevelEstimateTest, WithoutARampAChangeNeedsManyReadings) {
  const map::HdMap map = twoLevels();
  const std::string b1_117 = map.findByText("117", "B1").front()->id;
  LevelEstimate e(map, {}, "");
  double t = 0.0;
  for (int i = 0; i < 100; ++i, t += 0.1)
    see(e, t, Seen().read("117", b1_117).read("B1", "", map::TextClass::kPillar));
  ASSERT_EQ(e.restriction(), "B1");
  int frames = 0;
  while (e.restriction() != "B2" && frames < 100) {
    see(e, t, Seen().read("117", b1_117).read("A-1", "", map::TextClass::kPillar));
    t += 0.1;
    ++frames;
  }
  EXPECT_EQ(e.restriction(), "B2");  // the probability floor lets it come back
  EXPECT_GE(frames, 6);
}

TEST(LevelEstimateTest, OneMisreadingDoesNotUndoADecidedLevel) {
  const map::HdMap map = twoLevels();
  LevelEstimate e(map, {}, "");
  for (int i = 0; i < 10; ++i) see(e, 0.1 * i, Seen().read("LIFT", "", map::TextClass::kOther));
  ASSERT_EQ(e.restriction(), "B1");
  see(e, 1.0, Seen().read("A-1", "", map::TextClass::kPillar));
  EXPECT_EQ(e.restriction(), "B1");
}

TEST(LevelEstimateTest, ReadingsThatAreNoEvidenceAreIgnored) {
  const map::HdMap map = twoLevels();
  LevelEstimate e(map, {}, "");
  Seen fitted = Seen().read("B1", "", map::TextClass::kPillar);
  fitted.cameras[0].instances[0].read = false;  // a corner fit at a predicted place
  Seen second = Seen().read("B1", "", map::TextClass::kPillar);
  second.cameras[0].instances[0].second_opinion = true;
  for (int i = 0; i < 10; ++i) {
    see(e, 0.2 * i, fitted);
    see(e, 0.2 * i + 0.1, second);
  }
  EXPECT_NEAR(e.belief().probability, 0.5, 1e-9);
}

TEST(LevelEstimateTest, ASignOfALevelTheMapLacksIsIgnoredAndLoggedOnce) {
  const map::HdMap map = twoLevels();
  LevelEstimate e(map, {}, "");
  std::vector<std::string> warnings;
  see(e, 0.0, Seen().read("B3", "", map::TextClass::kPillar), &warnings);
  see(e, 0.1, Seen().read("B3", "", map::TextClass::kPillar), &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("B3"), std::string::npos);
  EXPECT_NEAR(e.belief().probability, 0.5, 1e-9);
}

TEST(LevelEstimateTest, AHintTheMapLacksIsAnError) {
  const map::HdMap map = twoLevels();
  EXPECT_THROW(LevelEstimate(map, {}, "B7"), InputError);
}

TEST(LevelEstimateTest, AOneLevelMapIsDecidedFromTheStart) {
  const map::HdMap map({landmark("117", "P1", 0.0)}, "one level");
  const LevelEstimate e(map, {}, "");
  EXPECT_TRUE(e.belief().decided);
  EXPECT_EQ(e.restriction(), "P1");
}

TEST(LevelEstimateTest, LevelSignsLookLikeLevelNames) {
  for (const char* t : {"B2", "P1", "L3", "-1", "UG1", "b 2"}) EXPECT_TRUE(looksLikeLevelSign(t)) << t;
  for (const char* t : {"117", "B-112", "A-1", "LIFT", "B", ""}) EXPECT_FALSE(looksLikeLevelSign(t)) << t;
}

TEST(SharedPlacesTest, OneLandmarkPerPlaceAndTextOnThePreferredLevel) {
  const map::HdMap map = twoLevels();
  const auto kept = onePerPlace(map.findByText("117"), "B2", 0.3, 0.05);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0]->level, "B2");
  EXPECT_EQ(onePerPlace(map.findByText("118"), "B2", 0.3, 0.05).size(), 2u);  // two places
  // One place, but painted narrower on B2: its corners would not fix the pose alike.
  map::Landmark narrow = landmark("117", "B2", 0.0);
  narrow.width = 0.7;
  const map::HdMap fonts({landmark("117", "B1", 0.0), narrow}, "two fonts");
  EXPECT_EQ(onePerPlace(fonts.findByText("117"), "B2", 0.3, 0.05).size(), 2u);
}

TEST(SharedPlacesTest, APlaceAsksForTheTextOfEveryLevel) {
  const map::HdMap map = twoLevels();
  std::vector<const map::Landmark*> all;
  for (const auto& l : map.landmarks()) all.push_back(&l);
  const auto places = sharedPlaces(all, "B2", 0.3);
  // 117 (shared), 118 on B1, 118 on B2, the pillar (B1 / A-1), LIFT.
  ASSERT_EQ(places.size(), 5u);
  const auto pillar = std::find_if(places.begin(), places.end(), [](const SharedPlace& p) {
    return p.landmark->cls == map::TextClass::kPillar;
  });
  ASSERT_NE(pillar, places.end());
  EXPECT_EQ(pillar->landmark->text, "A-1");
  EXPECT_EQ(pillar->texts, (std::vector<std::string>{"A-1", "B1"}));
}


TEST(SharedPlacesTest, ASurveyedPlaceIsOnePlaceWithinWhatItsErrorAllows) {
  // 117 on each level 40 cm and 4 degrees apart and 15 % apart in width: one place for a map
  // that says its positions are known to 10 cm and headings to 2 degrees (40 cm is 2.8 sigmas
  // of the difference, 4 degrees 1.4), another place for a map that says nothing (exact:
  // 0.3 m, 20 degrees and 10 % are the tolerances then); 1 m apart is two places either way.
  map::Landmark b1 = landmark("117", "B1", 0.0), b2 = landmark("117", "B2", 0.25);
  b2.heading = 4.0 * M_PI / 180.0;
  b2.width = 0.9 * 1.15;
  EXPECT_TRUE(samePlace(b1, b2, 0.3));
  EXPECT_FALSE(interchangeable(b1, b2, 0.3, 0.05));  // 15 % in width: another font
  b2.position.x() = 0.40;
  EXPECT_FALSE(samePlace(b1, b2, 0.3));
  for (map::Landmark* l : {&b1, &b2}) l->accuracy = {0.10, 2.0 * M_PI / 180.0};
  EXPECT_TRUE(samePlace(b1, b2, 0.3));
  EXPECT_TRUE(interchangeable(b1, b2, 0.3, 0.05));  // a survey's nominal sizes (5 %)
  EXPECT_FALSE(interchangeable(b1, b2, 0.3, 0.02));  // known to 2 %: 10 %, as one font
  b2.position.x() = 1.0;
  EXPECT_FALSE(samePlace(b1, b2, 0.3));
}

}  // namespace
}  // namespace parkloc::localize
