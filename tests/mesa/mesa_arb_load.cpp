// mesa_arb_load: loads ARB programs into Mesa (OSMesa) and prints Mesa's verdict per file as JSON.
//
// Usage:
//   mesa_arb_load [--driver softpipe|llvmpipe] FILE...   one JSON line per file:
//     {"path":..., "target":"vertex"|"fragment", "accepted":true|false,
//      "error_position":N, "error_string":"..."}, plus "gl_error":"0x0502" when rejected,
//     "under_native_limits":true|false when accepted, and "io_error" for an unreadable file
//   mesa_arb_load [--driver ...] --query-limits           the implementation limits, as a
//     limit profile keyed like compiler/src/limits.def ({"name":..., "base":..., "limits":{...}})
//   mesa_arb_load [--driver ...] --extensions             {"renderer":..., "version":...,
//     "extensions":[...]}: what the context advertises (for `# REQUIRE` lines)
//
// The driver comes from --driver, else GALLIUM_DRIVER, else softpipe; anything but softpipe or
// llvmpipe is refused before a context exists (another value crashes OSMesa:
// docs/design/platform.md). Every GL entry point is loaded through OSMesaGetProcAddress: libGL must
// not be linked. Exit codes: 0 done (whatever the verdicts), 2 usage, 3 I/O or GL context error.

#include <GL/osmesa.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

// Core GL 1.x entry points, declared by hand so that nothing refers to libGL's symbols.
using GetErrorFn = GLenum(APIENTRYP)();
using GetIntegervFn = void(APIENTRYP)(GLenum, GLint*);
using GetStringFn = const GLubyte*(APIENTRYP)(GLenum);

struct Gl {
  GetErrorFn get_error = nullptr;
  GetIntegervFn get_integerv = nullptr;
  GetStringFn get_string = nullptr;
  PFNGLGENPROGRAMSARBPROC gen_programs = nullptr;
  PFNGLDELETEPROGRAMSARBPROC delete_programs = nullptr;
  PFNGLBINDPROGRAMARBPROC bind_program = nullptr;
  PFNGLPROGRAMSTRINGARBPROC program_string = nullptr;
  PFNGLGETPROGRAMIVARBPROC get_programiv = nullptr;
};

// Loads one entry point; false (with a message) if OSMesa does not know it.
template <typename Fn>
bool Load(Fn* fn, const char* name) {
  OSMESAproc proc = OSMesaGetProcAddress(name);
  if (proc == nullptr) {
    std::fprintf(stderr, "mesa_arb_load: OSMesaGetProcAddress(\"%s\") failed\n", name);
    return false;
  }
  *fn = reinterpret_cast<Fn>(proc);
  return true;
}

bool LoadGl(Gl* gl) {
  return Load(&gl->get_error, "glGetError") && Load(&gl->get_integerv, "glGetIntegerv") &&
         Load(&gl->get_string, "glGetString") && Load(&gl->gen_programs, "glGenProgramsARB") &&
         Load(&gl->delete_programs, "glDeleteProgramsARB") &&
         Load(&gl->bind_program, "glBindProgramARB") &&
         Load(&gl->program_string, "glProgramStringARB") &&
         Load(&gl->get_programiv, "glGetProgramivARB");
}

// Appends `s` as a JSON string literal. Invalid UTF-8 bytes become U+FFFD so the line stays
// valid JSON whatever the file name or Mesa's message holds.
void AppendJsonString(std::string* out, std::string_view s) {
  out->push_back('"');
  size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c == '\\') {
      out->push_back('\\');
      out->push_back(static_cast<char>(c));
      ++i;
    } else if (c == '\n') {
      out->append("\\n");
      ++i;
    } else if (c == '\r') {
      out->append("\\r");
      ++i;
    } else if (c == '\t') {
      out->append("\\t");
      ++i;
    } else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
      out->append(buf);
      ++i;
    } else if (c < 0x80) {
      out->push_back(static_cast<char>(c));
      ++i;
    } else {
      // Length of a well-formed UTF-8 sequence starting here, or 0.
      size_t len = 0;
      if (c >= 0xc2 && c <= 0xdf) {
        len = 2;
      } else if (c >= 0xe0 && c <= 0xef) {
        len = 3;
      } else if (c >= 0xf0 && c <= 0xf4) {
        len = 4;
      }
      bool ok = len != 0 && i + len <= s.size();
      for (size_t k = 1; ok && k < len; ++k) {
        ok = (static_cast<unsigned char>(s[i + k]) & 0xc0) == 0x80;
      }
      if (ok) {
        out->append(s.substr(i, len));
        i += len;
      } else {
        out->append("\\ufffd");
        ++i;
      }
    }
  }
  out->push_back('"');
}

bool ReadFile(const std::string& path, std::string* text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    return false;
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) {
    return false;
  }
  *text = ss.str();
  return true;
}

// The target Mesa loads a program into: vertex for a `!!ARBvp1.0` header, fragment for
// anything else (a bad header is then Mesa's to reject). Blanks and `#` comments before the
// header are skipped, as Mesa's lexer skips them (Mesa accepts a program that has them).
GLenum TargetOf(std::string_view text) {
  size_t pos = 0;
  while (pos < text.size()) {
    if (text[pos] == ' ' || text[pos] == '\t' || text[pos] == '\r' || text[pos] == '\n') {
      ++pos;
    } else if (text[pos] == '#') {
      pos = text.find_first_of("\r\n", pos);
    } else {
      break;
    }
  }
  const std::string_view rest = pos < text.size() ? text.substr(pos) : std::string_view();
  return rest.starts_with("!!ARBvp1.0") ? GL_VERTEX_PROGRAM_ARB : GL_FRAGMENT_PROGRAM_ARB;
}

// Loads one file and prints its JSON line; false on an I/O error.
bool LoadOne(const Gl& gl, const std::string& path) {
  std::string line = "{\"path\":";
  AppendJsonString(&line, path);
  std::string text;
  if (!ReadFile(path, &text)) {
    line += ",\"accepted\":false,\"error_position\":-1,\"error_string\":\"\",\"io_error\":";
    AppendJsonString(&line, std::string("cannot read: ") + std::strerror(errno));
    line += "}\n";
    std::fputs(line.c_str(), stdout);
    return false;
  }

  const GLenum target = TargetOf(text);
  while (gl.get_error() != GL_NO_ERROR) {
  }
  GLuint id = 0;
  gl.gen_programs(1, &id);
  gl.bind_program(target, id);
  gl.program_string(target, GL_PROGRAM_FORMAT_ASCII_ARB, static_cast<GLsizei>(text.size()),
                    text.data());
  const GLenum error = gl.get_error();
  GLint position = -1;
  gl.get_integerv(GL_PROGRAM_ERROR_POSITION_ARB, &position);
  const GLubyte* message = gl.get_string(GL_PROGRAM_ERROR_STRING_ARB);
  GLint native = 0;
  if (error == GL_NO_ERROR) {
    gl.get_programiv(target, GL_PROGRAM_UNDER_NATIVE_LIMITS_ARB, &native);
  }
  gl.bind_program(target, 0);
  gl.delete_programs(1, &id);
  while (gl.get_error() != GL_NO_ERROR) {
  }

  line += ",\"target\":";
  line += target == GL_VERTEX_PROGRAM_ARB ? "\"vertex\"" : "\"fragment\"";
  line += ",\"accepted\":";
  line += error == GL_NO_ERROR ? "true" : "false";
  if (error != GL_NO_ERROR) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%04x", static_cast<unsigned>(error));
    line += ",\"gl_error\":\"";
    line += buf;
    line += "\"";
  } else {
    line += ",\"under_native_limits\":";
    line += native != 0 ? "true" : "false";
  }
  line += ",\"error_position\":" + std::to_string(position);
  line += ",\"error_string\":";
  AppendJsonString(&line,
                   message != nullptr ? reinterpret_cast<const char*>(message) : std::string());
  line += "}\n";
  std::fputs(line.c_str(), stdout);
  return true;
}

// One limit: limits.def key, and where Mesa reports it.
struct LimitQuery {
  const char* key;
  GLenum target;  // 0: glGetIntegerv, else glGetProgramivARB(target, ...)
  GLenum pname;
  const char* extension;  // the limit is 0 when this extension is absent (nullptr: always)
};

constexpr LimitQuery kLimitQueries[] = {
    {"arbvp.max_instructions", GL_VERTEX_PROGRAM_ARB, GL_MAX_PROGRAM_INSTRUCTIONS_ARB, nullptr},
    {"arbvp.max_temporaries", GL_VERTEX_PROGRAM_ARB, GL_MAX_PROGRAM_TEMPORARIES_ARB, nullptr},
    {"arbvp.max_parameters", GL_VERTEX_PROGRAM_ARB, GL_MAX_PROGRAM_PARAMETERS_ARB, nullptr},
    {"arbvp.max_attribs", GL_VERTEX_PROGRAM_ARB, GL_MAX_PROGRAM_ATTRIBS_ARB, nullptr},
    {"arbvp.max_address_registers", GL_VERTEX_PROGRAM_ARB, GL_MAX_PROGRAM_ADDRESS_REGISTERS_ARB,
     nullptr},
    {"arbvp.max_env_parameters", GL_VERTEX_PROGRAM_ARB, GL_MAX_PROGRAM_ENV_PARAMETERS_ARB, nullptr},
    {"arbvp.max_local_parameters", GL_VERTEX_PROGRAM_ARB, GL_MAX_PROGRAM_LOCAL_PARAMETERS_ARB,
     nullptr},
    {"arbvp.max_vertex_attribs", 0, GL_MAX_VERTEX_ATTRIBS_ARB, nullptr},
    {"arbvp.max_texture_units", 0, GL_MAX_TEXTURE_UNITS, nullptr},
    {"arbvp.max_vertex_units", 0, GL_MAX_VERTEX_UNITS_ARB, "GL_ARB_vertex_blend"},
    {"arbvp.max_palette_matrices", 0, GL_MAX_PALETTE_MATRICES_ARB, "GL_ARB_matrix_palette"},
    {"arbfp.max_instructions", GL_FRAGMENT_PROGRAM_ARB, GL_MAX_PROGRAM_INSTRUCTIONS_ARB, nullptr},
    {"arbfp.max_alu_instructions", GL_FRAGMENT_PROGRAM_ARB, GL_MAX_PROGRAM_ALU_INSTRUCTIONS_ARB,
     nullptr},
    {"arbfp.max_tex_instructions", GL_FRAGMENT_PROGRAM_ARB, GL_MAX_PROGRAM_TEX_INSTRUCTIONS_ARB,
     nullptr},
    {"arbfp.max_tex_indirections", GL_FRAGMENT_PROGRAM_ARB, GL_MAX_PROGRAM_TEX_INDIRECTIONS_ARB,
     nullptr},
    {"arbfp.max_temporaries", GL_FRAGMENT_PROGRAM_ARB, GL_MAX_PROGRAM_TEMPORARIES_ARB, nullptr},
    {"arbfp.max_parameters", GL_FRAGMENT_PROGRAM_ARB, GL_MAX_PROGRAM_PARAMETERS_ARB, nullptr},
    {"arbfp.max_attribs", GL_FRAGMENT_PROGRAM_ARB, GL_MAX_PROGRAM_ATTRIBS_ARB, nullptr},
    {"arbfp.max_env_parameters", GL_FRAGMENT_PROGRAM_ARB, GL_MAX_PROGRAM_ENV_PARAMETERS_ARB,
     nullptr},
    {"arbfp.max_local_parameters", GL_FRAGMENT_PROGRAM_ARB, GL_MAX_PROGRAM_LOCAL_PARAMETERS_ARB,
     nullptr},
    {"arbfp.max_texture_coords", 0, GL_MAX_TEXTURE_COORDS_ARB, nullptr},
    {"arbfp.max_texture_image_units", 0, GL_MAX_TEXTURE_IMAGE_UNITS_ARB, nullptr},
    {"arbfp.max_texture_units", 0, GL_MAX_TEXTURE_UNITS, nullptr},
    {"arbfp.max_draw_buffers", 0, GL_MAX_DRAW_BUFFERS_ARB, nullptr},
    {"gl.max_lights", 0, GL_MAX_LIGHTS, nullptr},
    {"gl.max_clip_planes", 0, GL_MAX_CLIP_PLANES, nullptr},
    {"gl.max_program_matrices", 0, GL_MAX_PROGRAM_MATRICES_ARB, nullptr},
};

// The extensions the context advertises (glGetString(GL_EXTENSIONS), compatibility profile).
std::vector<std::string> Extensions(const Gl& gl) {
  const GLubyte* raw = gl.get_string(GL_EXTENSIONS);
  if (raw == nullptr) {
    return {};
  }
  std::istringstream words{std::string(reinterpret_cast<const char*>(raw))};
  return {std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
}

std::string GetString(const Gl& gl, GLenum name) {
  const GLubyte* raw = gl.get_string(name);
  return raw != nullptr ? reinterpret_cast<const char*>(raw) : "";
}

// Prints the renderer, the version and the extensions as one JSON object.
void PrintExtensions(const Gl& gl) {
  std::string out = "{\"renderer\":";
  AppendJsonString(&out, GetString(gl, GL_RENDERER));
  out += ",\"version\":";
  AppendJsonString(&out, GetString(gl, GL_VERSION));
  out += ",\"extensions\":[";
  bool first = true;
  for (const std::string& name : Extensions(gl)) {
    out += first ? "" : ",";
    first = false;
    AppendJsonString(&out, name);
  }
  out += "]}\n";
  std::fputs(out.c_str(), stdout);
}

// Prints the limits as a profile; false if a query failed.
bool QueryLimits(const Gl& gl, const std::string& driver) {
  while (gl.get_error() != GL_NO_ERROR) {
  }
  std::string out = "{\"name\":";
  AppendJsonString(&out, "mesa-" + driver);
  out += ",\"base\":\"mesa\",\"limits\":{";
  const std::vector<std::string> extensions = Extensions(gl);
  bool ok = true;
  bool first = true;
  for (const LimitQuery& q : kLimitQueries) {
    GLint value = 0;
    if (q.extension == nullptr ||
        std::find(extensions.begin(), extensions.end(), q.extension) != extensions.end()) {
      if (q.target == 0) {
        gl.get_integerv(q.pname, &value);
      } else {
        gl.get_programiv(q.target, q.pname, &value);
      }
      const GLenum error = gl.get_error();
      if (error != GL_NO_ERROR) {
        std::fprintf(stderr, "mesa_arb_load: querying %s failed: GL error 0x%04x\n", q.key,
                     static_cast<unsigned>(error));
        ok = false;
      }
    }
    out += first ? "\n  " : ",\n  ";
    first = false;
    AppendJsonString(&out, q.key);
    out += ": " + std::to_string(value);
  }
  out += "\n}}\n";
  std::fputs(out.c_str(), stdout);
  std::fprintf(stderr, "mesa_arb_load: %s, %s\n", GetString(gl, GL_RENDERER).c_str(),
               GetString(gl, GL_VERSION).c_str());
  return ok;
}

int Usage(const char* message) {
  if (message != nullptr) {
    std::fprintf(stderr, "mesa_arb_load: %s\n", message);
  }
  std::fputs(
      "usage: mesa_arb_load [--driver softpipe|llvmpipe] FILE...\n"
      "       mesa_arb_load [--driver softpipe|llvmpipe] --query-limits\n"
      "       mesa_arb_load [--driver softpipe|llvmpipe] --extensions\n",
      stderr);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string driver;
  bool query_limits = false;
  bool extensions = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--query-limits") {
      query_limits = true;
    } else if (arg == "--extensions") {
      extensions = true;
    } else if (arg == "--driver") {
      if (i + 1 >= argc) {
        return Usage("--driver needs a value");
      }
      driver = argv[++i];
    } else if (arg == "--help" || arg == "-h") {
      Usage(nullptr);
      return 0;
    } else if (arg == "--") {
      for (++i; i < argc; ++i) {
        files.emplace_back(argv[i]);
      }
    } else if (arg.starts_with("--")) {
      return Usage(("unknown option " + std::string(arg)).c_str());
    } else {
      files.emplace_back(arg);
    }
  }
  const int modes = (query_limits ? 1 : 0) + (extensions ? 1 : 0) + (files.empty() ? 0 : 1);
  if (modes != 1) {
    return Usage(modes == 0 ? "no input files" : "give files, --query-limits or --extensions");
  }

  if (driver.empty()) {
    const char* env = std::getenv("GALLIUM_DRIVER");
    driver = env != nullptr && env[0] != '\0' ? env : "softpipe";
  }
  if (driver != "softpipe" && driver != "llvmpipe") {
    std::fprintf(stderr, "mesa_arb_load: unsupported driver '%s' (softpipe or llvmpipe)\n",
                 driver.c_str());
    return 2;
  }
  setenv("GALLIUM_DRIVER", driver.c_str(), 1);
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);

  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
  OSMesaContext context = OSMesaCreateContextAttribs(attribs, nullptr);
  if (context == nullptr) {
    std::fputs("mesa_arb_load: OSMesaCreateContextAttribs failed\n", stderr);
    return 3;
  }
  constexpr GLsizei kSize = 16;
  std::vector<GLubyte> pixels(static_cast<size_t>(kSize) * kSize * 4);
  if (OSMesaMakeCurrent(context, pixels.data(), GL_UNSIGNED_BYTE, kSize, kSize) == GL_FALSE) {
    std::fputs("mesa_arb_load: OSMesaMakeCurrent failed\n", stderr);
    OSMesaDestroyContext(context);
    return 3;
  }
  Gl gl;
  if (!LoadGl(&gl)) {
    OSMesaDestroyContext(context);
    return 3;
  }

  int status = 0;
  if (query_limits) {
    status = QueryLimits(gl, driver) ? 0 : 3;
  } else if (extensions) {
    PrintExtensions(gl);
  } else {
    for (const std::string& path : files) {
      if (!LoadOne(gl, path)) {
        status = 3;
      }
    }
  }
  std::fflush(stdout);
  OSMesaDestroyContext(context);
  return status;
}
