#include "config/yaml_reader.h"

#include <cmath>
#include <type_traits>
#include <utility>

#include "common/error.h"

namespace parkloc::config {
namespace {

// Every dotted key under `node` (mappings only; a sequence is one value).
void collectKeys(const YAML::Node& node, const std::string& prefix,
                 std::vector<std::string>& keys) {
  for (const auto& kv : node) {
    const std::string key = prefix + kv.first.as<std::string>();
    keys.push_back(key);
    if (kv.second.IsMap()) collectKeys(kv.second, key + ".", keys);
  }
}

}  // namespace

YamlReader::YamlReader(YAML::Node root, std::string where)
    : where_(std::move(where)), root_(root) {
  if (root.IsNull()) root_ = YAML::Node(YAML::NodeType::Map);
  if (!root_.IsMap()) throw InputError(where_ + ": expected a mapping of option sections");
  stack_.push_back(root_);
}

std::string YamlReader::path(const char* key) const {
  std::string p;
  for (const std::string& s : prefix_) p += s + ".";
  return p + key;
}

YAML::Node YamlReader::find(const char* key) {
  known_.insert(path(key));
  const YAML::Node& mapping = stack_.back();
  if (!mapping.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  for (const auto& kv : mapping)
    if (kv.first.as<std::string>() == key) return kv.second;
  return YAML::Node(YAML::NodeType::Undefined);
}

template <typename T>
void YamlReader::scalar(const char* key, T& v, const char* kind) {
  const YAML::Node node = find(key);
  if (!node.IsDefined()) return;
  T parsed{};
  bool ok = node.IsScalar();
  if (ok) {
    try {
      parsed = node.as<T>();
    } catch (const YAML::Exception&) {
      ok = false;
    }
  }
  if constexpr (std::is_floating_point_v<T>) ok = ok && std::isfinite(parsed);
  if (!ok)
    throw InputError(where_ + ": option '" + path(key) + "' must be " + kind + ", not '" +
                     YAML::Dump(node) + "'");
  v = parsed;
}

void YamlReader::value(const char* key, bool& v, const char*) { scalar(key, v, "true or false"); }
void YamlReader::value(const char* key, int& v, const char*) { scalar(key, v, "an integer"); }
void YamlReader::value(const char* key, double& v, const char*) {
  scalar(key, v, "a finite number");
}
void YamlReader::value(const char* key, float& v, const char*) {
  scalar(key, v, "a finite number");
}
void YamlReader::value(const char* key, std::string& v, const char*) {
  scalar(key, v, "a string");
}

void YamlReader::value(const char* key, std::vector<double>& v, const char*) {
  const YAML::Node node = find(key);
  if (!node.IsDefined()) return;
  std::vector<double> parsed;
  bool ok = node.IsSequence();
  for (size_t i = 0; ok && i < node.size(); ++i) {
    try {
      parsed.push_back(node[i].as<double>());
      ok = std::isfinite(parsed.back());
    } catch (const YAML::Exception&) {
      ok = false;
    }
  }
  if (!ok)
    throw InputError(where_ + ": option '" + path(key) +
                     "' must be a list of finite numbers, not '" + YAML::Dump(node) + "'");
  v = parsed;
}

void YamlReader::value(const char* key, std::vector<std::pair<float, float>>& v, const char*) {
  const YAML::Node node = find(key);
  if (!node.IsDefined()) return;
  std::vector<std::pair<float, float>> parsed;
  bool ok = node.IsSequence();
  for (size_t i = 0; ok && i < node.size(); ++i) {
    ok = node[i].IsSequence() && node[i].size() == 2;
    try {
      if (ok) parsed.emplace_back(node[i][0].as<float>(), node[i][1].as<float>());
      ok = ok && std::isfinite(parsed.back().first) && std::isfinite(parsed.back().second);
    } catch (const YAML::Exception&) {
      ok = false;
    }
  }
  if (!ok)
    throw InputError(where_ + ": option '" + path(key) +
                     "' must be a list of number pairs, not '" + YAML::Dump(node) + "'");
  v = parsed;
}

void YamlReader::nameValue(const char* key, std::string& name,
                           const std::vector<std::string>& allowed, const char*) {
  std::string read = name;
  scalar(key, read, "a string");
  std::string list;
  for (const std::string& a : allowed) {
    if (a == read) {
      name = read;
      return;
    }
    list += (list.empty() ? "" : ", ") + a;
  }
  throw InputError(where_ + ": option '" + path(key) + "' must be one of " + list + ", not '" +
                   read + "'");
}

void YamlReader::section(const char* key, const char*, const std::function<void()>& body) {
  YAML::Node node = find(key);
  if (node.IsDefined() && !node.IsNull() && !node.IsMap())
    throw InputError(where_ + ": option section '" + path(key) + "' must be a mapping");
  stack_.push_back(node.IsDefined() && node.IsMap() ? node
                                                    : YAML::Node(YAML::NodeType::Undefined));
  prefix_.emplace_back(key);
  body();
  prefix_.pop_back();
  stack_.pop_back();
}

void YamlReader::requireAllKnown() const {
  std::vector<std::string> keys;
  collectKeys(root_, "", keys);
  for (const std::string& key : keys)
    if (!known_.count(key)) throw InputError(where_ + ": unknown option '" + key + "'");
}

}  // namespace parkloc::config
