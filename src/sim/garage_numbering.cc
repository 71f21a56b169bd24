#include <fmt/format.h>

#include "sim/garage.h"
#include "sim/garage_builder.h"

namespace parkloc::sim {

std::string formatParkingNumber(NumberingScheme scheme, const std::string& level, int number,
                                int zone) {
  switch (scheme) {
    case NumberingScheme::kThreeDigit:
      return fmt::format("{:03d}", number);
    case NumberingScheme::kPlain:
      return std::to_string(number);
    case NumberingScheme::kLevelDash:
      return fmt::format("{}-{:03d}", level, number);
    case NumberingScheme::kZoneLetter:
      return fmt::format("{}{:03d}", static_cast<char>(zone), number);
  }
  return std::to_string(number);
}

namespace detail {

// The label painted on a pillar's three visible faces, in one of four styles a garage keeps
// for all its pillars: the level ("B1"), the row and column ("C-4"), both ("B1-C4"), or the
// row and column run together ("C4").
std::string pillarLabel(int style, const std::string& level, char zone, int column) {
  switch (style) {
    case 0:
      return level;
    case 1:
      return fmt::format("{}-{}", zone, column);
    case 2:
      return fmt::format("{}-{}{}", level, zone, column);
    default:
      return fmt::format("{}{}", zone, column);
  }
}

// A licence plate of one or two letters, two letters and a number: text the cameras see
// that is not in the map (cars move).
std::string randomPlate(Rng& rng) {
  const std::string letters = "ABCDEFGHKLMNPRSTUVWXYZ";
  auto letter = [&] {
    return letters[std::uniform_int_distribution<size_t>(0, letters.size() - 1)(rng)];
  };
  std::string s;
  s += letter();
  if (chance(rng, 0.6)) s += letter();
  s += "-";
  s += letter();
  s += letter();
  s += " ";
  s += std::to_string(std::uniform_int_distribution<int>(10, 9999)(rng));
  return s;
}

}  // namespace detail
}  // namespace parkloc::sim
