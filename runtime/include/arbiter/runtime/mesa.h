// Mesa in process through OSMesa: Mesa's verdict on GLSL shaders and ARB programs.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/ir.h"
#include "arbiter/glsl/check.h"

namespace arbiter::runtime {

// What Mesa says about one shader or program.
struct MesaVerdict {
  bool accepted = false;  // compiled (and linked, when a link was asked for) / loaded
  // GLSL: the compile status alone, the compile info log, and the link info log (empty when
  // no link was asked for or the compile failed, as then there is no link).
  bool compiled = false;
  bool linked = false;
  std::string compile_log;
  std::string link_log;
  // ARB: GL_PROGRAM_ERROR_POSITION_ARB (a byte offset, -1 when accepted) and
  // GL_PROGRAM_ERROR_STRING_ARB ("line 3, char 1: error: ..."; may hold warnings when accepted).
  int error_position = -1;
  std::string error_string;
  // Set when the verdict means nothing because the call itself went wrong: the context could
  // not be made current, the input is too large for GL, or GL raised an error other than the
  // one a rejected ARB program raises (GL_INVALID_OPERATION). Lower-case, e.g. "GL error
  // 0x0500 (GL_INVALID_ENUM)".
  std::string failure;
};

// The first line of Mesa's messages that reports an error ("0:3(5): error: ..." for GLSL,
// "line 3, char 1: error: ..." for ARB), else the first non-empty line; "" when Mesa said
// nothing.
std::string FirstErrorLine(const MesaVerdict& verdict);

struct MesaOptions {
  // The gallium driver: "softpipe" or "llvmpipe". Anything else is refused before OSMesa is
  // touched (another GALLIUM_DRIVER value crashes OSMesaCreateContextAttribs:
  // docs/design/platform.md).
  std::string driver = "softpipe";
};

// True for the driver names MesaOptions accepts.
bool IsSupportedMesaDriver(std::string_view name);

// One OSMesa compatibility-profile context with a small colour buffer, reused for every
// shader. Every call is serialised by an internal mutex and makes the context current on the
// calling thread, so worker threads may share one context (one call at a time).
// Mesa runs in this process: hostile input that crashes Mesa crashes the caller.
class MesaContext {
 public:
  virtual ~MesaContext() = default;

  // "softpipe" or "llvmpipe": the driver that really runs (OSMesa picks it once per process).
  virtual const std::string& driver() const = 0;
  // GL_RENDERER and GL_VERSION, as "softpipe, 3.3 (Compatibility Profile) Mesa 22.3.6".
  virtual const std::string& description() const = 0;
  // The extensions the context advertises (compatibility profile: GL_EXTENSIONS).
  virtual const std::vector<std::string>& extensions() const = 0;

  // Compiles `sources` as the strings of one shader (glShaderSource with several strings, in
  // order) and, when `link`, attaches it alone to a program and links that.
  virtual MesaVerdict CompileGlsl(glsl::Stage stage, const std::vector<std::string_view>& sources,
                                  bool link) = 0;

  // Loads an ARB program with glProgramStringARB into the vertex or fragment program target.
  virtual MesaVerdict LoadArbProgram(arbvp::ProgramKind kind, std::string_view text) = 0;
};

// Creates the context: checks the driver name, sets GALLIUM_DRIVER and
// MESA_SHADER_CACHE_DISABLE=true in the environment (how Mesa is configured; call this before
// starting threads that read the environment), creates the context and loads every GL entry
// point through OSMesaGetProcAddress. On failure returns null and sets `error` to a
// lower-case reason. OSMesa chooses its driver once per process: asking for another driver
// than an earlier context's is an error.
[[nodiscard]] std::unique_ptr<MesaContext> CreateMesaContext(const MesaOptions& options,
                                                             std::string* error);

}  // namespace arbiter::runtime
