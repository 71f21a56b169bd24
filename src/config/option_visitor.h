#pragma once
// One walk over an options struct serves every use of it: reading a YAML file onto it,
// writing it out with the reason for each value, listing its keys. Each options struct has a
// `describe(OptionVisitor&, Struct&)` that names its fields in the order the file shows them,
// with a one-line reason each (localize_options.cc, ocr_options.cc); the visitor decides
// what a field means to it. So a new option is one line, and the file, the dump and the
// loader cannot disagree about its name.
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace parkloc::config {

class OptionVisitor {
 public:
  virtual ~OptionVisitor() = default;

  virtual void value(const char* key, bool& v, const char* why) = 0;
  virtual void value(const char* key, int& v, const char* why) = 0;
  virtual void value(const char* key, double& v, const char* why) = 0;
  virtual void value(const char* key, float& v, const char* why) = 0;
  virtual void value(const char* key, std::string& v, const char* why) = 0;
  virtual void value(const char* key, std::vector<double>& v, const char* why) = 0;
  // A list of factor pairs, written [[a, b], ...].
  virtual void value(const char* key, std::vector<std::pair<float, float>>& v, const char* why) = 0;

  // A nested mapping: `body` describes its fields.
  virtual void section(const char* key, const char* why, const std::function<void()>& body) = 0;

  // A value that is one of a few names (an enum), written and read by name.
  template <typename E>
  void choice(const char* key, E& v, const std::vector<std::pair<const char*, E>>& names,
              const char* why) {
    std::string name;
    for (const auto& [n, e] : names)
      if (e == v) name = n;
    std::vector<std::string> allowed;
    for (const auto& [n, e] : names) allowed.emplace_back(n);
    nameValue(key, name, allowed, why);
    for (const auto& [n, e] : names)
      if (name == n) v = e;
  }

  // An optional sub-struct: a section with `enabled`, whose other fields describe the struct
  // (the defaults of `T` when it is off).
  template <typename T, typename Describe>
  void optionalSection(const char* key, std::optional<T>& v, const char* why, Describe&& describe) {
    section(key, why, [&] {
      bool enabled = v.has_value();
      T fields = v.value_or(T{});
      value("enabled", enabled, "off: the rule does not run");
      describe(fields);
      v = enabled ? std::optional<T>(fields) : std::nullopt;
    });
  }

 protected:
  // `name` is one of `allowed`; a reader replaces it, a writer writes it.
  virtual void nameValue(const char* key, std::string& name,
                         const std::vector<std::string>& allowed, const char* why) = 0;
};

}  // namespace parkloc::config
