#include "config/yaml_writer.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <sstream>

namespace parkloc::config {

std::string yamlString(const std::string& s) {
  YAML::Emitter out;
  out << YAML::DoubleQuoted << s;
  return out.c_str();
}

void YamlWriter::comment(const std::string& lines) {
  std::istringstream in(lines);
  std::string l;
  while (std::getline(in, l)) text_ += l.empty() ? "#\n" : "# " + l + "\n";
}

void YamlWriter::line(const char* key, const std::string& value, const char* why) {
  if (why != nullptr && *why != '\0') text_ += indent() + "# " + why + "\n";
  text_ += indent() + key + ": " + value + "\n";
}

void YamlWriter::value(const char* key, bool& v, const char* why) {
  line(key, v ? "true" : "false", why);
}
void YamlWriter::value(const char* key, int& v, const char* why) {
  line(key, fmt::format("{}", v), why);
}
// The shortest text that reads back as the same number of its type (fmt's default), with a
// decimal point so that YAML readers see a float.
namespace {
template <typename Real>
std::string realText(Real v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}
}  // namespace

void YamlWriter::value(const char* key, double& v, const char* why) { line(key, realText(v), why); }
void YamlWriter::value(const char* key, float& v, const char* why) { line(key, realText(v), why); }
void YamlWriter::value(const char* key, std::string& v, const char* why) {
  line(key, yamlString(v), why);
}
void YamlWriter::value(const char* key, std::vector<double>& v, const char* why) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += fmt::format("{}{}", i ? ", " : "", v[i]);
  line(key, s + "]", why);
}

void YamlWriter::value(const char* key, std::vector<std::pair<float, float>>& v, const char* why) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i)
    s += fmt::format("{}[{}, {}]", i ? ", " : "", v[i].first, v[i].second);
  line(key, s + "]", why);
}

void YamlWriter::nameValue(const char* key, std::string& name,
                           const std::vector<std::string>& allowed, const char* why) {
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "" : " | ") + a;
  const std::string reason = std::string(why) + " (" + list + ")";
  line(key, name, reason.c_str());
}

void YamlWriter::section(const char* key, const char* why, const std::function<void()>& body) {
  if (depth_ == 0 && !text_.empty()) text_ += "\n";
  if (why != nullptr && *why != '\0') text_ += indent() + "# " + why + "\n";
  text_ += indent() + key + ":\n";
  ++depth_;
  body();
  --depth_;
}

}  // namespace parkloc::config
