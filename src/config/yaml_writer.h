#pragma once
// Writes options structs as YAML through their describe() walk: every key with its value
// and, above it, the one-line reason the walk gives. `parkloc config dump` prints this, and
// data/config/default.yaml is this text for the defaults (a test holds the two equal).
#include <string>
#include <vector>

#include "config/option_visitor.h"

namespace parkloc::config {

class YamlWriter : public OptionVisitor {
 public:
  void value(const char* key, bool& v, const char* why) override;
  void value(const char* key, int& v, const char* why) override;
  void value(const char* key, double& v, const char* why) override;
  void value(const char* key, float& v, const char* why) override;
  void value(const char* key, std::string& v, const char* why) override;
  void value(const char* key, std::vector<double>& v, const char* why) override;
  void value(const char* key, std::vector<std::pair<float, float>>& v, const char* why) override;
  void section(const char* key, const char* why, const std::function<void()>& body) override;

  // Lines written so far.
  const std::string& text() const { return text_; }
  // Text put before everything else (e.g. a header comment), each line as a comment.
  void comment(const std::string& lines);

 protected:
  void nameValue(const char* key, std::string& name, const std::vector<std::string>& allowed,
                 const char* why) override;

 private:
  void line(const char* key, const std::string& value, const char* why);
  std::string indent() const { return std::string(2 * depth_, ' '); }

  std::string text_;
  int depth_ = 0;
};

// A YAML scalar for `s`: double-quoted, with YAML's escapes, so it reads back as the same string.
std::string yamlString(const std::string& s);

}  // namespace parkloc::config
