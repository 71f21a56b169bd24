#include "io/sequence_conditions.h"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>

#include "common/error.h"

namespace parkloc::io {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Maps one word of a condition description to a subset name; empty when it names none.
std::string normalise(const std::string& word) {
  const std::string w = lower(word);
  if (w == "bright" || w == "bright_light" || w == "strong" || w == "strong_light") return "bright";
  if (w == "weak" || w == "weak_light" || w == "dim" || w == "dark" || w == "low_light")
    return "weak_light";
  if (w == "blur" || w == "blurry" || w == "fuzzy" || w == "motion_blur" || w == "defocus" ||
      w == "defocus_blur")
    return "blur";
  return "";
}

void addWords(const std::string& text, std::vector<std::string>& out) {
  std::string word;
  auto flush = [&] {
    if (const std::string name = normalise(word); !name.empty()) out.push_back(name);
    word.clear();
  };
  for (char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
      word += c;
    } else {
      flush();
    }
  }
  flush();
  // "weak_light" may also arrive as "weak light" or "weak-light": single words cover both.
}

void collect(const nlohmann::json& value, const std::string& key, std::vector<std::string>& out) {
  if (value.is_string()) {
    const std::string text = value.get<std::string>();
    // {"light": "weak"} names the light; {"blur": "motion"} names a blur.
    if (key == "blur" && !text.empty() && lower(text) != "none") {
      out.push_back("blur");
    } else {
      addWords(text, out);
    }
  } else if (value.is_boolean()) {
    if (value.get<bool>()) {
      if (const std::string name = normalise(key); !name.empty()) out.push_back(name);
    }
  } else if (value.is_number()) {
    // {"blur": 2.5}: a blur amount; any positive amount makes the sequence blurred.
    if (normalise(key) == "blur" && value.get<double>() > 0.0) out.push_back("blur");
  } else if (value.is_array()) {
    for (const auto& item : value) collect(item, key, out);
  } else if (value.is_object()) {
    for (const auto& [k, v] : value.items()) collect(v, k, out);
  }
}

}  // namespace

std::vector<std::string> sequenceConditions(const std::string& meta_json,
                                            const std::string& source_name) {
  nlohmann::json meta;
  try {
    meta = nlohmann::json::parse(meta_json.empty() ? "{}" : meta_json);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source_name + ": malformed JSON: " + e.what());
  }
  std::vector<std::string> out;
  if (meta.is_object()) {
    for (const char* key : {"condition", "conditions"}) {
      if (meta.contains(key)) collect(meta[key], key, out);
    }
    // The simulator's look (sim/appearance.h): "clean", "realistic" or the factors on.
    if (meta.contains("appearance") && meta["appearance"].is_object() &&
        meta["appearance"].contains("subset") && meta["appearance"]["subset"].is_string())
      out.push_back(meta["appearance"]["subset"].get<std::string>());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace parkloc::io
