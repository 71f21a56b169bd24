#pragma once
// Reads a YAML configuration onto options structs through their describe() walk. A key the
// file leaves out keeps the struct's value, so a file may hold only what it changes; a key
// the walk does not know, or a value of the wrong kind, is an InputError naming the file and
// the dotted key (a misspelt option must not be ignored in silence).
#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>

#include "config/option_visitor.h"

namespace parkloc::config {

class YamlReader : public OptionVisitor {
 public:
  // `root` is the file's top mapping; `where` names the file in error messages.
  YamlReader(YAML::Node root, std::string where);

  void value(const char* key, bool& v, const char* why) override;
  void value(const char* key, int& v, const char* why) override;
  void value(const char* key, double& v, const char* why) override;
  void value(const char* key, float& v, const char* why) override;
  void value(const char* key, std::string& v, const char* why) override;
  void value(const char* key, std::vector<double>& v, const char* why) override;
  void value(const char* key, std::vector<std::pair<float, float>>& v, const char* why) override;
  void section(const char* key, const char* why, const std::function<void()>& body) override;

  // Throws InputError for the first key of the file that no walk visited.
  void requireAllKnown() const;

 protected:
  void nameValue(const char* key, std::string& name, const std::vector<std::string>& allowed,
                 const char* why) override;

 private:
  // The node at `key` in the current mapping, or an undefined node; marks the key known.
  YAML::Node find(const char* key);
  std::string path(const char* key) const;
  template <typename T>
  void scalar(const char* key, T& v, const char* kind);

  std::string where_;
  std::vector<YAML::Node> stack_;
  std::vector<std::string> prefix_;
  std::set<std::string> known_;  // dotted keys visited
  YAML::Node root_;
};

}  // namespace parkloc::config
