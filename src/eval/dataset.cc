#include "eval/dataset.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/error.h"

namespace parkloc::eval {
namespace fs = std::filesystem;

std::vector<std::string> splitSequences(const std::string& dataset_dir, const std::string& split) {
  const fs::path root(dataset_dir);
  if (fs::is_regular_file(root / "calib.yaml")) return {root.string()};
  const fs::path splits_path = root / "splits.json";
  std::ifstream in(splits_path);
  if (!in) {
    throw InputError(
        fmt::format("{}: not found (DATASET must hold splits.json or be a sequence "
                    "folder with calib.yaml)",
                    splits_path.string()));
  }
  nlohmann::json splits;
  try {
    in >> splits;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: malformed JSON: {}", splits_path.string(), e.what()));
  }
  // {"test": [...]} or {"splits": {"test": [...]}}; entries are names or {"name": ...}.
  const nlohmann::json* table = &splits;
  if (splits.is_object() && splits.contains("splits") && splits["splits"].is_object()) {
    table = &splits["splits"];
  }
  if (!table->is_object() || !table->contains(split)) {
    std::string known;
    if (table->is_object()) {
      for (const auto& [name, _] : table->items()) known += (known.empty() ? "" : ", ") + name;
    }
    throw InputError(
        fmt::format("{}: split \"{}\" not found (splits: {})", splits_path.string(), split, known));
  }
  const nlohmann::json& entries = (*table)[split];
  if (!entries.is_array()) {
    throw InputError(fmt::format("{}: split \"{}\" is not a list", splits_path.string(), split));
  }
  std::vector<std::string> out;
  for (const nlohmann::json& entry : entries) {
    std::string name;
    if (entry.is_string()) {
      name = entry.get<std::string>();
    } else if (entry.is_object() && entry.contains("name") && entry["name"].is_string()) {
      name = entry["name"].get<std::string>();
    } else {
      throw InputError(
          fmt::format("{}: split \"{}\": bad entry {}", splits_path.string(), split, entry.dump()));
    }
    // A bare name lives under sequences/; a relative path is taken from the dataset root.
    fs::path dir = root / "sequences" / name;
    if (!fs::is_directory(dir) && fs::is_directory(root / name)) dir = root / name;
    if (!fs::is_directory(dir)) {
      throw InputError(fmt::format("{}: split \"{}\": sequence folder {} not found",
                                   splits_path.string(), split, dir.string()));
    }
    out.push_back(dir.string());
  }
  return out;
}

std::string sequenceLevel(const std::string& meta_json) {
  const nlohmann::json meta = nlohmann::json::parse(meta_json, nullptr, false);
  if (meta.is_object() && meta.contains("level") && meta["level"].is_string()) {
    return meta["level"].get<std::string>();
  }
  return "";
}

}  // namespace parkloc::eval
