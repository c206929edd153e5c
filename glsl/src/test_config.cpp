// piglit's `// [config]` block of GLSL parser tests.
#include "arbiter/glsl/test_config.h"

#include <set>
#include <sstream>

namespace arbiter::glsl {

ParserTestConfig ParseParserTestConfig(std::string_view text) {
  ParserTestConfig config;
  std::istringstream in{std::string(text)};
  bool inside = false;
  for (std::string s; std::getline(in, s);) {
    s.erase(0, s.find_first_not_of(" \t"));
    for (const char* leader : {"//", "/*", "*"}) {
      if (s.rfind(leader, 0) == 0) {
        s.erase(0, std::string(leader).size());
        break;
      }
    }
    s.erase(0, s.find_first_not_of(" \t"));
    while (!s.empty() &&
           (s.back() == '\r' || s.back() == ' ' || s.back() == '/' || s.back() == '*')) {
      s.pop_back();
    }
    if (s == "[config]") {
      inside = true;
    } else if (s == "[end config]") {
      config.found = inside;
      break;
    } else if (inside && !s.empty()) {
      size_t colon = s.find(':');
      if (colon == std::string::npos) {
        config.error = "config line without ':': " + s;
        continue;
      }
      std::string key = s.substr(0, colon);
      std::string value = s.substr(colon + 1);
      value.erase(0, value.find_first_not_of(" \t"));
      static const std::set<std::string> kKeys = {"expect_result", "glsl_version",
                                                  "require_extensions", "check_link"};
      if (kKeys.count(key) == 0) config.error = "unknown config key '" + key + "'";
      if (!config.values.emplace(key, value).second) config.error = "duplicate key '" + key + "'";
    }
  }
  if (!config.found && config.error.empty()) {
    config.error = inside ? "[config] without [end config]" : "no [config] ... [end config] block";
  }
  return config;
}

}  // namespace arbiter::glsl
