// piglit's GLSL parser-test convention: the `// [config]` comment block at the top of a
// shader (docs/design/formats.md), used by the corpus, the agreement test and later by `arbiter
// run`.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace arbiter::glsl {

struct ParserTestConfig {
  bool found = false;  // a complete [config] ... [end config] block
  // expect_result, glsl_version, require_extensions, check_link -> value
  std::map<std::string, std::string> values;
  std::string error;  // an unknown or duplicate key, a line without ':'; "" when well formed
};

// Reads the block; comment leaders may be //, /* or *.
ParserTestConfig ParseParserTestConfig(std::string_view text);

}  // namespace arbiter::glsl
