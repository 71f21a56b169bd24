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
    }
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

TEST(Scenario, NumberingSchemes) {
  EXPECT_EQ(formatParkingNumber(NumberingScheme::kThreeDigit, "B2", 98, 'A'), "098");
  EXPECT_EQ(formatParkingNumber(NumberingScheme::kPlain, "B2", 117, 'A'), "117");
  EXPECT_EQ(formatParkingNumber(NumberingScheme::kLevelDash, "B2", 117, 'A'), "B2-117");
  EXPECT_EQ(formatParkingNumber(NumberingScheme::kZoneLetter, "B2", 23, 'A'), "A023");
}

}  // namespace
}  // namespace parkloc::sim
