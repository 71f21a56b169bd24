#include <gtest/gtest.h>

#include <set>

#include "common/error.h"
#include "sim/garage.h"
#include "sim/scenario.h"

namespace parkloc::sim {
namespace {

TEST(Scenario, ShippedDefaultYamlEqualsBuiltIn) {
  const Scenario file =
      loadScenario(std::string(PARKLOC_SOURCE_DIR) + "/data/scenarios/default.yaml");
  const Scenario code = defaultScenario();
  EXPECT_EQ(file.name, code.name);
  EXPECT_EQ(file.seed, code.seed);
  EXPECT_EQ(file.frame_rate, code.frame_rate);
  ASSERT_EQ(file.garages.size(), code.garages.size());
  for (size_t i = 0; i < code.garages.size(); ++i) {
    const GarageSpec &a = file.garages[i], &b = code.garages[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.split, b.split);
    EXPECT_EQ(a.levels, b.levels);
    EXPECT_EQ(a.aisles, b.aisles);
    EXPECT_EQ(a.slots_per_row, b.slots_per_row);
    EXPECT_EQ(a.numbering, b.numbering);
    EXPECT_EQ(a.first_number, b.first_number);
    EXPECT_DOUBLE_EQ(a.number_height, b.number_height);
    EXPECT_EQ(a.fonts, b.fonts);
    ASSERT_EQ(a.drives.size(), b.drives.size()) << a.name;
    for (size_t k = 0; k < a.drives.size(); ++k) {
      EXPECT_EQ(a.drives[k].route, b.drives[k].route);
      EXPECT_EQ(a.drives[k].condition, b.drives[k].condition);
      EXPECT_DOUBLE_EQ(a.drives[k].duration_s, b.drives[k].duration_s);
      EXPECT_EQ(a.drives[k].level, b.drives[k].level);
      EXPECT_EQ(a.drives[k].to_level, b.drives[k].to_level);
      EXPECT_DOUBLE_EQ(a.drives[k].transition_s, b.drives[k].transition_s);
      EXPECT_DOUBLE_EQ(a.drives[k].transition_at_s, b.drives[k].transition_at_s);
    }
    EXPECT_EQ(a.level_signs, b.level_signs);
  }
}

TEST(Scenario, DefaultSplitsKeepTestSchemesAndFontsUnseen) {
  const Scenario s = defaultScenario();
  std::set<NumberingScheme> train_schemes;
  std::set<std::string> train_fonts, conditions;
  std::map<std::string, int> garages_per_split;
  for (const auto& g : s.garages) {
    ++garages_per_split[g.split];
    for (const auto& d : g.drives) conditions.insert(d.condition);
    if (g.split != "train") continue;
    train_schemes.insert(g.numbering);
    train_fonts.insert(g.fonts.begin(), g.fonts.end());
  }
  EXPECT_EQ(garages_per_split["train"], 7);
  EXPECT_EQ(garages_per_split["val"], 2);
  EXPECT_EQ(garages_per_split["test"], 1);
  EXPECT_EQ(conditions, (std::set<std::string>{"blur", "bright", "weak"}));
  for (const auto& g : s.garages) {
    if (g.split != "test") continue;
    EXPECT_EQ(train_schemes.count(g.numbering), 0u);
    for (const auto& f : g.fonts) EXPECT_EQ(train_fonts.count(f), 0u) << f;
  }
}

TEST(Scenario, LegibilityOnTheImageIsTheRealisticScenariosChoice) {
  EXPECT_FALSE(parseScenario("garages: [{name: a}]", "x.yaml").legibility_on_image);
  EXPECT_TRUE(parseScenario("legibility_on_image: true\ngarages: [{name: a}]", "x.yaml")
                  .legibility_on_image);
  EXPECT_THROW(parseScenario("legibility_on_image: maybe\ngarages: [{name: a}]", "x.yaml"),
               InputError);
  const std::string dir = std::string(PARKLOC_SOURCE_DIR) + "/data/scenarios/";
  EXPECT_FALSE(loadScenario(dir + "default.yaml").legibility_on_image);
  EXPECT_TRUE(loadScenario(dir + "realistic.yaml").legibility_on_image);
  EXPECT_TRUE(loadScenario(dir + "realistic_test.yaml").legibility_on_image);
}

TEST(Scenario, BadFilesThrowWithTheField) {
  EXPECT_THROW(parseScenario("garages: []", "x.yaml"), InputError);
  EXPECT_THROW(parseScenario("[1, 2", "x.yaml"), InputError);
  try {
    parseScenario("garages:\n  - {name: a, aisles: 0}\n", "x.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("aisles"), std::string::npos) << e.what();
  }
  try {
    parseScenario("garages:\n  - {name: a, numbering: roman}\n", "x.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("roman"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseScenario("garages:\n  - {fonts: [NoSuchFont.ttf]}\n", "x.yaml"), InputError);
  EXPECT_THROW(loadScenario("/nonexistent/scenario.yaml"), InputError);
}

TEST(Scenario, LevelChangeKeys) {
  const Scenario s = parseScenario(
      "garages:\n  - levels: [P2, P3]\n    level_signs: true\n    drives:\n"
      "      - {route: tour, duration_s: 24, level: P2, to_level: P3, transition_s: 4,"
      " transition_at_s: 9}\n      - {route: park}\n",
      "x.yaml");
  const GarageSpec& g = s.garages.at(0);
  EXPECT_TRUE(g.level_signs);
  EXPECT_EQ(g.drives.at(0).to_level, "P3");
  EXPECT_EQ(g.drives.at(0).transition_s, 4.0);
  EXPECT_EQ(g.drives.at(0).transition_at_s, 9.0);
  EXPECT_EQ(g.drives.at(1).to_level, "");
  EXPECT_FALSE(parseScenario("garages:\n  - {name: a}\n", "x.yaml").garages[0].level_signs);
}

TEST(Scenario, BadLevelChangesNameTheField) {
  auto error = [](const std::string& drive) {
    try {
      parseScenario("garages:\n  - {name: a, levels: [B1, B2], drives: [" + drive + "]}\n",
                    "x.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("{to_level: B3}"),
            "x.yaml garage 0 drive 0: field 'to_level' 'B3' is not one of the garage's levels");
  EXPECT_EQ(error("{route: park, to_level: B2}"),
            "x.yaml garage 0 drive 0: field 'to_level' needs route tour, not 'park'");
  EXPECT_EQ(error("{level: B2, to_level: B2}"),
            "x.yaml garage 0 drive 0: field 'to_level' is the drive's own level 'B2'");
  EXPECT_EQ(error("{to_level: B2, transition_s: 0}"),
            "x.yaml garage 0 drive 0: field 'transition_s' out of range (0.5 to 60 s)");
  EXPECT_EQ(error("{to_level: B2, duration_s: 10, transition_at_s: 8, transition_s: 2}"),
            "x.yaml garage 0 drive 0: the ramp (transition_at_s, transition_s) does not fit in "
            "duration_s");
  EXPECT_EQ(error("{to_level: B2, duration_s: 3, transition_s: 3}"),
            "x.yaml garage 0 drive 0: the ramp (transition_at_s, transition_s) does not fit in "
            "duration_s");
  EXPECT_EQ(error("{to_level: B2, transition_at_s: .nan}"),
            "x.yaml garage 0 drive 0: field 'transition_at_s' out of range");
  EXPECT_NE(error("{to_level: [B2]}").find("field 'to_level' has an invalid value"),
            std::string::npos);
  EXPECT_EQ(error("{to_level: B2}"), "no error");
}

TEST(Scenario, ShippedLevelScenariosUseUnseenLevelsFontsAndSigns) {
  const Scenario base = defaultScenario();
  std::set<std::string> base_levels, base_fonts;
  for (const auto& g : base.garages) {
    base_levels.insert(g.levels.begin(), g.levels.end());
    base_fonts.insert(g.fonts.begin(), g.fonts.end());
  }
  for (const char* file : {"levels.yaml", "unseen.yaml"}) {
    const Scenario s = loadScenario(std::string(PARKLOC_SOURCE_DIR) + "/data/scenarios/" + file);
    EXPECT_NE(s.seed, base.seed) << file;
    int level_changes = 0, plain = 0;
    for (const auto& g : s.garages) {
      for (const auto& l : g.levels) EXPECT_EQ(base_levels.count(l), 0u) << file << " " << l;
      for (const auto& f : g.fonts) EXPECT_EQ(base_fonts.count(f), 0u) << file << " " << f;
      EXPECT_EQ(g.level_signs, g.levels.size() > 1) << file << " " << g.name;
      for (const auto& d : g.drives) (d.to_level.empty() ? plain : level_changes)++;
    }
    EXPECT_GE(level_changes, 2) << file;
    EXPECT_GE(plain, 1) << file;
  }
}

TEST(Scenario, NumberingSchemes) {
  EXPECT_EQ(formatParkingNumber(NumberingScheme::kThreeDigit, "B2", 98, 'A'), "098");
  EXPECT_EQ(formatParkingNumber(NumberingScheme::kPlain, "B2", 117, 'A'), "117");
  EXPECT_EQ(formatParkingNumber(NumberingScheme::kLevelDash, "B2", 117, 'A'), "B2-117");
  EXPECT_EQ(formatParkingNumber(NumberingScheme::kZoneLetter, "B2", 23, 'A'), "A023");
}

}  // namespace
}  // namespace parkloc::sim
