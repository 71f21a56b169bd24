#include "config/yaml_reader.h"

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "common/error.h"

namespace parkloc::config {
namespace {

// A value as an error message shows it: on one line, control characters as '?', at most 40
// characters (the message is one line on stderr).
std::string shown(const std::string& text) {
  std::string out;
  for (const char c : text) out += (c >= 0 && c < 0x20) || c == 0x7f ? (c == '\n' ? ' ' : '?') : c;
  return out.size() > 40 ? out.substr(0, 37) + "..." : out;
}
std::string shown(const YAML::Node& node) { return shown(YAML::Dump(node)); }

// A mapping's key as the file names it; a key that is a list or a mapping names no option.
std::string keyName(const YAML::Node& key) {
  return key.IsScalar() ? key.Scalar() : "(" + shown(key) + ")";
}

// Every dotted key under `node` (mappings only; a sequence is one value).
void collectKeys(const YAML::Node& node, const std::string& prefix,
                 std::vector<std::string>& keys) {
  for (const auto& kv : node) {
    const std::string key = prefix + keyName(kv.first);
    keys.push_back(key);
    if (kv.second.IsMap()) collectKeys(kv.second, key + ".", keys);
  }
}

// Whether `s` is UTF-8 of printable characters: no control characters (C0, DEL, C1), no
// overlong or broken sequences, surrogates, byte-order marks or code points past U+10FFFF.
bool printableUtf8(const std::string& s) {
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const size_t n = c < 0x80           ? 1
                     : (c >> 5) == 0x6  ? 2
                     : (c >> 4) == 0xe  ? 3
                     : (c >> 3) == 0x1e ? 4
                                        : 0;
    if (n == 0 || i + n > s.size()) return false;
    uint32_t cp = n == 1 ? c : c & (0x7f >> n);
    for (size_t k = 1; k < n; ++k) {
      const auto t = static_cast<unsigned char>(s[i + k]);
      if ((t >> 6) != 0x2) return false;
      cp = (cp << 6) | (t & 0x3f);
    }
    const uint32_t min_of_length[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < min_of_length[n] || cp < 0x20 || (cp >= 0x7f && cp <= 0x9f) ||
        (cp >= 0xd800 && cp <= 0xdfff) || cp > 0x10ffff || cp == 0xfeff || cp == 0xfffe ||
        cp == 0xffff)
      return false;
    i += n;
  }
  return true;
}

}  // namespace

YamlReader::YamlReader(YAML::Node root, std::string where) : where_(std::move(where)), root_(root) {
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
    if (kv.first.IsScalar() && kv.first.Scalar() == key) return kv.second;
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
                     shown(node) + "'");
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
// Options that are text (paths, alphabets, names) are printable UTF-8: a control character or
// a broken byte sequence is a damaged file, and could not be written back as it was read.
void YamlReader::value(const char* key, std::string& v, const char*) {
  std::string read = v;
  scalar(key, read, "a string");
  if (!printableUtf8(read))
    throw InputError(where_ + ": option '" + path(key) +
                     "' must be printable UTF-8 text, without control characters");
  v = read;
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
                     "' must be a list of finite numbers, not '" + shown(node) + "'");
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
    throw InputError(where_ + ": option '" + path(key) + "' must be a list of number pairs, not '" +
                     shown(node) + "'");
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
                   shown(read) + "'");
}

void YamlReader::section(const char* key, const char*, const std::function<void()>& body) {
  YAML::Node node = find(key);
  if (node.IsDefined() && !node.IsNull() && !node.IsMap())
    throw InputError(where_ + ": option section '" + path(key) + "' must be a mapping");
  stack_.push_back(node.IsDefined() && node.IsMap() ? node : YAML::Node(YAML::NodeType::Undefined));
  prefix_.emplace_back(key);
  body();
  prefix_.pop_back();
  stack_.pop_back();
}

void YamlReader::requireAllKnown() const {
  std::vector<std::string> keys;
  collectKeys(root_, "", keys);
  for (const std::string& key : keys)
    if (!known_.count(key)) throw InputError(where_ + ": unknown option '" + shown(key) + "'");
}

}  // namespace parkloc::config
