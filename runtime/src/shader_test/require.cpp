// [require]: GL and GLSL versions, extensions (a leading ! means "must be absent"),
// implementation limits, and the lines piglit accepts but arbiter need not act on.
#include <fmt/format.h>

#include "shader_test/gl_names.h"
#include "shader_test/session.h"
#include "shader_test/words.h"

namespace arbiter::runtime::shader_test {
namespace {

// "<", "<=", ... applied to a and b; false (with `known` false) for another operator.
bool Compare(double a, const std::string& op, double b, bool* known) {
  *known = true;
  if (op == "<") return a < b;
  if (op == "<=") return a <= b;
  if (op == "==" || op == "=") return a == b;
  if (op == "!=") return a != b;
  if (op == ">=") return a >= b;
  if (op == ">") return a > b;
  *known = false;
  return false;
}

}  // namespace

// A malformed line (an unknown operator or limit, a version that is not a number) is a
// TestError: the test fails rather than skips.
std::string Session::UnmetRequirement() {
  for (const ShaderTestLine& r : test_.require) {
    std::vector<std::string> w = Words(r.text);
    if (w.empty()) continue;
    line_ = r.line;
    auto where = [&](std::string what) {
      return fmt::format("{}:{}: {}", test_.path, r.line, what);
    };
    auto version = [&](const std::string& name, size_t op, double have) -> std::string {
      double want = 0.0;
      bool known = false;
      if (w.size() != op + 2 || !ParseDouble(w[op + 1], &want)) {
        Error(fmt::format("malformed requirement '{}'", r.text));
      }
      if (Compare(have, w[op], want, &known)) return "";
      if (!known) Error(fmt::format("unknown operator '{}'", w[op]));
      return where(
          fmt::format("requires {} {} {}, the context has {:.2f}", name, w[op], w[op + 1], have));
    };
    std::string unmet;
    if (w[0] == "GL" && w.size() > 1 && (w[1] == "ES" || w[1] == "CORE")) {
      unmet = where(fmt::format("requires OpenGL {}: arbiter runs a compatibility context",
                                w[1] == "ES" ? "ES" : "core profile"));
    } else if (w[0] == "GLSL" && w.size() > 1 && w[1] == "ES") {
      unmet = where("requires GLSL ES: arbiter runs desktop GLSL");
    } else if (w[0] == "GL" && w.size() > 1 && w[1] == "COMPAT") {
      unmet = version("GL COMPAT", 2, info_.gl_version);
    } else if (w[0] == "GL") {
      unmet = version("GL", 1, info_.gl_version);
    } else if (w[0] == "GLSL") {
      unmet = version("GLSL", 1, info_.glsl_version);
    } else if (w[0] == "SIZE" || w[0] == "rlimit" || w[0] == "depthbuffer" || w[0] == "fbo" ||
               w[0] == "auto") {
      // The window size is read before the run; the others are piglit harness settings.
    } else if (w[0].rfind("GL_MAX_", 0) == 0 || (w[0] == "INT" && w.size() > 1) ||
               (w[0] == "FLOAT" && w.size() > 1)) {
      const bool typed = w[0] == "INT" || w[0] == "FLOAT";
      const std::string& name = typed ? w[1] : w[0];
      GLenum limit = 0;
      if (!GlEnumByName(name, &limit)) {
        Error(fmt::format("unknown limit '{}'", name));
      } else {
        GLfloat have[4] = {0, 0, 0, 0};
        gl_.GetFloatv(limit, have);
        for (int i = 0; i < 16 && gl_.GetError() != GL_NO_ERROR; ++i) {
        }
        unmet = version(name, typed ? 2 : 1, static_cast<double>(have[0]));
      }
    } else if (w.size() == 1 && (w[0].rfind("GL_", 0) == 0 || w[0].rfind("!GL_", 0) == 0)) {
      const bool absent = w[0][0] == '!';
      const std::string name = absent ? w[0].substr(1) : w[0];
      const bool have = info_.extensions.count(name) != 0;
      if (have == absent) {
        unmet = where(absent ? fmt::format("requires {} to be absent", name)
                             : fmt::format("requires {}, which the context lacks", name));
      }
    }
    // Anything else (an extension name without its GL_ prefix, say) is ignored, as piglit
    // ignores it.
    if (!unmet.empty()) return unmet;
  }
  return "";
}

}  // namespace arbiter::runtime::shader_test
