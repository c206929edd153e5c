// port-to-core: a port, end to end. One ARB vertex + fragment program pair, drawn twice:
//   (a) legacy: the ARB programs on a compatibility-profile context, the GL state set the way a
//       legacy engine sets it, with GL's fixed-function calls (glLoadMatrixf, glLightfv,
//       glMaterialfv, glFogfv, glProgramLocalParameter4fvARB, ...);
//   (b) port: the pair's glsl330 translation (arbiter's library, at run time) on a core 3.3
//       context, the same state kept in an arbiter::glstate::GlState and fed to the uniforms
//       the binding map names (glstate::UniformValue), the vertex arrays at the binding map's
//       attribute locations.
// Both draw the same lit, textured terrain into a 128x128 RGBA8 framebuffer object with Mesa's
// software rasteriser (EGL, no window, no GPU); every pixel is compared (README.md).
//   port-to-core PROGRAM.vp PROGRAM.fp [PICTURES.ppm]
// Exit 0 when the pictures match, 1 when they differ, 2 usage, 3 a program, translation or GL
// error.
#define GL_GLEXT_PROTOTYPES 1  // the core entry points, from libOpenGL
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/emit.h"
#include "arbiter/compiler/render.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glstate/uniforms.h"

namespace arbvp = arbiter::arbvp;
namespace compiler = arbiter::compiler;
namespace gs = arbiter::glstate;

namespace {

constexpr int kSize = 128;  // the picture is kSize x kSize pixels

[[noreturn]] void Fail(const std::string& what) {
  std::fprintf(stderr, "port-to-core: %s\n", what.c_str());
  std::exit(3);
}

// ---------------------------------------------------------------------------------------
// The engine's data: what it used to hand to GL's fixed-function state, and its meshes.

struct Vertex {
  float position[3];
  float normal[3];
  float color[4];
  float texcoord[2];
};

struct Scene {
  glm::mat4 projection{1.0f};
  glm::mat4 view{1.0f};                              // the camera: the modelview matrix
  glm::vec4 light_position{0.0f, 0.0f, 1.0f, 0.0f};  // as given to glLightfv, in world space
  gs::Vec4 light_ambient{}, light_diffuse{}, light_specular{};
  gs::Vec4 scene_ambient{};  // GL_LIGHT_MODEL_AMBIENT
  gs::MaterialState material;
  gs::Vec4 fog_color{};
  float fog_start = 0.0f, fog_end = 1.0f, fog_density = 1.0f;
  // glProgramEnvParameter4fvARB and glProgramLocalParameter4fvARB, per target. The example
  // binds one program per target, so its local parameters sit beside the env ones.
  gs::ProgramParameters vertex_params, fragment_params;
  std::vector<Vertex> vertices;
  std::vector<uint16_t> indices;  // triangles
  std::vector<uint8_t> texture;   // 8x8 RGBA8, bound to texture units 0 to 3
};

Scene MakeScene() {
  Scene s;
  s.projection = glm::frustum(-0.4f, 0.4f, -0.4f, 0.4f, 1.0f, 8.0f);
  s.view = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -3.2f)) *
           glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(1.0f, 0.0f, 0.0f)) *
           glm::rotate(glm::mat4(1.0f), 0.4f, glm::vec3(0.0f, 1.0f, 0.0f));
  s.light_position = {-0.8f, 0.7f, 0.2f, 0.0f};  // a directional light (sun)
  s.light_ambient = {0.2f, 0.2f, 0.25f, 1.0f};
  s.light_diffuse = {0.8f, 0.75f, 0.6f, 1.0f};
  s.light_specular = {0.4f, 0.4f, 0.35f, 1.0f};
  s.scene_ambient = {0.1f, 0.1f, 0.1f, 1.0f};
  s.material.ambient = {0.6f, 0.7f, 0.5f, 1.0f};
  s.material.diffuse = {0.45f, 0.7f, 0.35f, 1.0f};
  s.material.specular = {0.6f, 0.6f, 0.6f, 1.0f};
  s.material.emission = {0.05f, 0.0f, 0.0f, 1.0f};
  s.material.shininess = 48.0f;
  s.fog_color = {0.6f, 0.65f, 0.75f, 1.0f};
  s.fog_start = 2.6f;
  s.fog_end = 4.6f;
  s.fog_density = 0.5f;
  s.vertex_params.local[0] = {3.0f, 3.0f, 2.0f, 2.0f};    // terrain: detail and base scales
  s.fragment_params.local[0] = {0.4f, 0.0f, 0.0f, 0.0f};  // detail fade distance
  s.fragment_params.env[24] = {1.0f, 0.9f, 0.8f, 1.0f};   // a tint

  // A 24x24 height field over [-1, 1]^2 in the xz plane, its normals and vertex colours.
  constexpr int kGrid = 24;
  for (int j = 0; j <= kGrid; ++j) {
    for (int i = 0; i <= kGrid; ++i) {
      const float x = -1.0f + 2.0f * static_cast<float>(i) / kGrid;
      const float z = -1.0f + 2.0f * static_cast<float>(j) / kGrid;
      const float y = 0.25f * std::sin(3.0f * x) * std::cos(2.5f * z);
      const glm::vec3 n =
          glm::normalize(glm::vec3(-0.75f * std::cos(3.0f * x) * std::cos(2.5f * z), 1.0f,
                                   0.625f * std::sin(3.0f * x) * std::sin(2.5f * z)));
      s.vertices.push_back({{x, y, z},
                            {n.x, n.y, n.z},
                            {0.5f + 0.5f * x, 0.8f, 0.5f - 0.5f * z, 1.0f},
                            {0.5f + 0.5f * x, 0.5f + 0.5f * z}});
    }
  }
  for (int j = 0; j < kGrid; ++j) {
    for (int i = 0; i < kGrid; ++i) {
      const auto v = static_cast<uint16_t>(j * (kGrid + 1) + i);
      const auto up = static_cast<uint16_t>(v + kGrid + 1);
      for (uint16_t index : {v, static_cast<uint16_t>(v + 1), up, up, static_cast<uint16_t>(v + 1),
                             static_cast<uint16_t>(up + 1)}) {
        s.indices.push_back(index);
      }
    }
  }
  for (int t = 0; t < 8 * 8; ++t) {  // a green and brown checkerboard with a gradient
    const bool odd = ((t % 8) + (t / 8)) % 2 != 0;
    s.texture.insert(s.texture.end(), {static_cast<uint8_t>(odd ? 200 : 90 + 10 * (t % 8)),
                                       static_cast<uint8_t>(odd ? 180 : 160),
                                       static_cast<uint8_t>(odd ? 120 : 60 + 20 * (t / 8)), 255});
  }
  return s;
}

// ---------------------------------------------------------------------------------------
// What both contexts share: EGL without a surface, the mesh in buffer objects, the texture,
// a framebuffer object to draw into and read back.

EGLDisplay Display() {
  static EGLDisplay display = [] {
    EGLDisplay d =
        eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d == EGL_NO_DISPLAY || eglInitialize(d, nullptr, nullptr) != EGL_TRUE) {
      Fail("no EGL surfaceless display (Mesa's libEGL: Debian libegl1 and libegl-mesa0)");
    }
    return d;
  }();
  return display;
}

// A desktop GL context without a surface, made current: compatibility profile (any version)
// or core profile 3.3.
EGLContext MakeContext(bool core) {
  EGLDisplay display = Display();
  eglBindAPI(EGL_OPENGL_API);
  const EGLint compat[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                           EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
  const EGLint core33[] = {EGL_CONTEXT_MAJOR_VERSION,
                           3,
                           EGL_CONTEXT_MINOR_VERSION,
                           3,
                           EGL_CONTEXT_OPENGL_PROFILE_MASK,
                           EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                           EGL_NONE};
  EGLContext context =
      eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, core ? core33 : compat);
  if (context == EGL_NO_CONTEXT ||
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    char why[80];
    std::snprintf(why, sizeof why, "cannot create a %s context (EGL error 0x%04x)",
                  core ? "core 3.3" : "compatibility", eglGetError());
    Fail(why);
  }
  std::printf("%s context: %s, %s\n", core ? "core" : "compatibility",
              reinterpret_cast<const char*>(glGetString(GL_VERSION)),
              reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  return context;
}

void UploadMeshAndTexture(const Scene& s) {
  GLuint buffers[2];
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(s.vertices.size() * sizeof(Vertex)),
               s.vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(s.indices.size() * 2),
               s.indices.data(), GL_STATIC_DRAW);
  GLuint texture;
  glGenTextures(1, &texture);
  for (int unit = 3; unit >= 0; --unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, texture);
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, s.texture.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

void BindFramebuffer() {
  GLuint framebuffer, renderbuffers[2];
  glGenFramebuffers(1, &framebuffer);
  glGenRenderbuffers(2, renderbuffers);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kSize, kSize);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            renderbuffers[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, kSize, kSize);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffers[1]);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    Fail("the framebuffer object is incomplete");
  }
  glViewport(0, 0, kSize, kSize);
  glClearColor(0.1f, 0.1f, 0.15f, 0.0f);  // alpha 0: not drawn
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
}

std::vector<uint8_t> DrawAndRead(const Scene& s, EGLContext context) {
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(s.indices.size()), GL_UNSIGNED_SHORT, nullptr);
  std::vector<uint8_t> pixels(kSize * kSize * 4);
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    Fail("GL error " + std::to_string(error));
  }
  eglMakeCurrent(Display(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(Display(), context);
  return pixels;
}

// ---------------------------------------------------------------------------------------
// (a) The legacy engine: ARB programs and fixed-function state on a compatibility context.

// The ARB_vertex_program entry points are an extension's: eglGetProcAddress.
template <typename Fn>
Fn Proc(const char* name) {
  auto fn = reinterpret_cast<Fn>(eglGetProcAddress(name));
  if (fn == nullptr) Fail(std::string("no ") + name + " (GL_ARB_vertex_program)");
  return fn;
}

std::vector<uint8_t> DrawLegacy(const Scene& s, const std::string& vp, const std::string& fp) {
  EGLContext context = MakeContext(/*core=*/false);
  auto GenPrograms = Proc<PFNGLGENPROGRAMSARBPROC>("glGenProgramsARB");
  auto BindProgram = Proc<PFNGLBINDPROGRAMARBPROC>("glBindProgramARB");
  auto ProgramString = Proc<PFNGLPROGRAMSTRINGARBPROC>("glProgramStringARB");
  auto ProgramEnv = Proc<PFNGLPROGRAMENVPARAMETER4FVARBPROC>("glProgramEnvParameter4fvARB");
  auto ProgramLocal = Proc<PFNGLPROGRAMLOCALPARAMETER4FVARBPROC>("glProgramLocalParameter4fvARB");

  // The programs, and their parameters: env per target, local per (bound) program.
  GLuint programs[2];
  GenPrograms(2, programs);
  const GLenum targets[2] = {GL_VERTEX_PROGRAM_ARB, GL_FRAGMENT_PROGRAM_ARB};
  const std::string* texts[2] = {&vp, &fp};
  const gs::ProgramParameters* params[2] = {&s.vertex_params, &s.fragment_params};
  for (int k = 0; k < 2; ++k) {
    BindProgram(targets[k], programs[k]);
    ProgramString(targets[k], GL_PROGRAM_FORMAT_ASCII_ARB, static_cast<GLsizei>(texts[k]->size()),
                  texts[k]->data());
    GLint error_position = -1;
    glGetIntegerv(GL_PROGRAM_ERROR_POSITION_ARB, &error_position);
    if (error_position != -1) {
      Fail(std::string("the driver rejects the ARB program: ") +
           reinterpret_cast<const char*>(glGetString(GL_PROGRAM_ERROR_STRING_ARB)));
    }
    glEnable(targets[k]);
    for (const auto& [index, value] : params[k]->env) ProgramEnv(targets[k], index, value.data());
    for (const auto& [index, value] : params[k]->local) {
      ProgramLocal(targets[k], index, value.data());
    }
  }

  // The fixed-function state the programs read through state.*.
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(glm::value_ptr(s.projection));
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(glm::value_ptr(s.view));
  glLightfv(GL_LIGHT0, GL_POSITION, glm::value_ptr(s.light_position));  // GL stores view * p
  glLightfv(GL_LIGHT0, GL_AMBIENT, s.light_ambient.data());
  glLightfv(GL_LIGHT0, GL_DIFFUSE, s.light_diffuse.data());
  glLightfv(GL_LIGHT0, GL_SPECULAR, s.light_specular.data());
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, s.scene_ambient.data());
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, s.material.ambient.data());
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, s.material.diffuse.data());
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, s.material.specular.data());
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, s.material.emission.data());
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, s.material.shininess);
  glFogfv(GL_FOG_COLOR, s.fog_color.data());
  glFogf(GL_FOG_START, s.fog_start);
  glFogf(GL_FOG_END, s.fog_end);
  glFogf(GL_FOG_DENSITY, s.fog_density);

  // The conventional vertex arrays, from the buffer object.
  UploadMeshAndTexture(s);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableClientState(GL_NORMAL_ARRAY);
  glNormalPointer(GL_FLOAT, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, normal)));
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(4, GL_FLOAT, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, color)));
  glClientActiveTexture(GL_TEXTURE0);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, sizeof(Vertex),
                    reinterpret_cast<void*>(offsetof(Vertex, texcoord)));

  BindFramebuffer();
  return DrawAndRead(s, context);
}

// ---------------------------------------------------------------------------------------
// (b) The port: the glsl330 translation, GL state as uniforms, on a core 3.3 context.

// The state the legacy path gave GL, kept by the engine: what glLoadMatrixf, glLightfv,
// glMaterialfv and glFogf stored.
gs::GlState KeepState(const Scene& s) {
  gs::GlState state;  // GL's initial state
  state.projection = s.projection;
  state.modelview = s.view;
  // glLightfv(GL_POSITION) stores the position in eye space: transformed by the modelview
  // matrix current at the call.
  const glm::vec4 eye = s.view * s.light_position;
  state.light[0].position = {eye.x, eye.y, eye.z, eye.w};
  state.light[0].ambient = s.light_ambient;
  state.light[0].diffuse = s.light_diffuse;
  state.light[0].specular = s.light_specular;
  state.light_model_ambient = s.scene_ambient;
  state.material[0] = s.material;  // GL_FRONT_AND_BACK: front ...
  state.material[1] = s.material;  // ... and back
  state.fog_color = s.fog_color;
  state.fog_start = s.fog_start;
  state.fog_end = s.fog_end;
  state.fog_density = s.fog_density;
  return state;
}

GLuint CompileShader(GLenum type, const std::string& text) {
  GLuint shader = glCreateShader(type);
  const char* source = text.c_str();
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[4096] = "";
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    Fail(std::string("the driver rejects the translation: ") + log);
  }
  return shader;
}

// The vertex arrays a binding map may ask for: its attributes' ARB spellings.
struct VertexArray {
  const char* binding;
  GLint size;
  size_t offset;
};
constexpr VertexArray kArrays[] = {
    {"vertex.position", 3, offsetof(Vertex, position)},
    {"vertex.normal", 3, offsetof(Vertex, normal)},
    {"vertex.color.primary", 4, offsetof(Vertex, color)},
    {"vertex.texcoord[0]", 2, offsetof(Vertex, texcoord)},
};

std::vector<uint8_t> DrawCore(const Scene& s, const arbvp::PairTranslation& glsl) {
  EGLContext context = MakeContext(/*core=*/true);
  const arbvp::BindingMap& map = glsl.bindings;
  GLuint program = glCreateProgram();
  glAttachShader(program, CompileShader(GL_VERTEX_SHADER, glsl.vertex));
  glAttachShader(program, CompileShader(GL_FRAGMENT_SHADER, glsl.fragment));
  glLinkProgram(program);
  GLint linked = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE) Fail("the driver does not link the translation");
  glUseProgram(program);

  // The state uniforms: each named by its ARB spelling, valued by the host library.
  const gs::GlState state = KeepState(s);
  for (const arbvp::StateUniform& u : map.state) {
    gs::UniformData value;
    if (!gs::UniformValue(state, gs::ProgramParameters{}, u.binding, &value)) {
      Fail("the host library does not know " + u.binding);
    }
    const GLint location = glGetUniformLocation(program, u.name.c_str());
    if (value.type == gs::UniformType::Matrix) {
      glUniformMatrix4fv(location, 1, GL_FALSE, value.data.data());
    } else {
      glUniform4fv(location, 1, value.data.data());
    }
  }
  // program.env and program.local: one vec4 array per target and kind.
  for (const arbvp::ParameterArray& a : map.parameters) {
    const gs::ProgramParameters& params =
        a.target == arbvp::ProgramKind::Vertex ? s.vertex_params : s.fragment_params;
    std::vector<float> values;
    for (int i = 0; i < a.size; ++i) {
      const gs::Vec4 v = gs::ParameterValue(a.local ? params.local : params.env, i);
      values.insert(values.end(), v.begin(), v.end());
    }
    glUniform4fv(glGetUniformLocation(program, a.name.c_str()), a.size, values.data());
  }
  // Samplers: the texture unit the ARB program named.
  for (const arbvp::SamplerBinding& sampler : map.samplers) {
    if (sampler.target != arbvp::TexTarget::Tex2D || sampler.unit > 3) {
      Fail("this example binds 2D textures to units 0 to 3 only: " + sampler.name);
    }
    glUniform1i(glGetUniformLocation(program, sampler.name.c_str()), sampler.unit);
  }

  // The vertex arrays, at the binding map's locations (a vertex array object: core profile).
  GLuint vertex_array;
  glGenVertexArrays(1, &vertex_array);
  glBindVertexArray(vertex_array);
  UploadMeshAndTexture(s);
  for (const arbvp::AttributeBinding& a : map.attributes) {
    const auto array = std::find_if(std::begin(kArrays), std::end(kArrays),
                                    [&](const VertexArray& v) { return a.binding == v.binding; });
    if (array == std::end(kArrays)) Fail("this example has no vertex array for " + a.binding);
    const GLint location =
        a.location >= 0 ? a.location : glGetAttribLocation(program, a.name.c_str());
    glEnableVertexAttribArray(static_cast<GLuint>(location));
    glVertexAttribPointer(static_cast<GLuint>(location), array->size, GL_FLOAT, GL_FALSE,
                          sizeof(Vertex), reinterpret_cast<void*>(array->offset));
  }

  BindFramebuffer();
  return DrawAndRead(s, context);
}

// ---------------------------------------------------------------------------------------

// Reads and checks one ARB program; the diagnostics go to stderr.
std::unique_ptr<arbvp::Program> Check(const compiler::SourceFile& source) {
  compiler::DiagnosticSink sink;
  arbvp::CheckResult checked = arbvp::CheckProgram(source, arbvp::CheckOptions{}, &sink);
  compiler::FileReport report{source.path(), sink.diagnostics(), sink.dropped()};
  std::fputs(compiler::RenderText(report, compiler::TextOptions{}).c_str(), stderr);
  if (!checked.ok) Fail(source.path() + " does not check");
  return std::move(checked.program);
}

void WritePictures(const char* path, const std::vector<uint8_t>& left,
                   const std::vector<uint8_t>& right) {
  std::FILE* file = std::fopen(path, "wb");
  if (file == nullptr) Fail(std::string("cannot write ") + path);
  std::fprintf(file, "P6\n%d %d\n255\n", 2 * kSize, kSize);
  for (int y = kSize - 1; y >= 0; --y) {  // GL's rows go up, PPM's down
    for (const std::vector<uint8_t>* picture : {&left, &right}) {
      for (int x = 0; x < kSize; ++x) std::fwrite(&(*picture)[4 * (y * kSize + x)], 1, 3, file);
    }
  }
  std::fclose(file);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: port-to-core PROGRAM.vp PROGRAM.fp [PICTURES.ppm]\n");
    return 2;
  }
  std::string vp_text, fp_text, error;
  if (!compiler::ReadFileBytes(argv[1], &vp_text, &error) ||
      !compiler::ReadFileBytes(argv[2], &fp_text, &error)) {
    Fail(error);
  }
  const compiler::SourceFile vp_source(argv[1], vp_text), fp_source(argv[2], fp_text);
  const std::unique_ptr<arbvp::Program> vp = Check(vp_source), fp = Check(fp_source);

  // The translation: a pair with matching varyings, GLSL 3.30 core, state as uniforms.
  arbvp::EmitOptions options;
  options.target = arbvp::EmitTarget::Glsl330;
  options.state = arbvp::StateSource::Uniforms;
  const arbvp::PairTranslation glsl =
      arbvp::EmitGlslPair(*vp, *fp, options, &vp_source, &fp_source);

  const Scene scene = MakeScene();
  const std::vector<uint8_t> legacy = DrawLegacy(scene, vp_text, fp_text);
  const std::vector<uint8_t> core = DrawCore(scene, glsl);
  if (argc == 4) WritePictures(argv[3], legacy, core);

  // Every channel of every pixel. The derived state may differ in its last bits (README.md:
  // Mesa inverts a matrix it classifies as a rotation by transposing it, glstate computes the
  // general inverse), which moves a value across a rounding boundary of the 8-bit picture at
  // a rare pixel: up to 1/255 at up to 1% of the pixels is a match; a translation or state
  // bug changes far more.
  int differing = 0, largest = 0, drawn = 0;
  for (size_t p = 0; p < legacy.size(); p += 4) {
    int difference = 0;
    for (size_t c = 0; c < 4; ++c) {
      difference = std::max(difference, std::abs(legacy[p + c] - core[p + c]));
    }
    differing += difference > 0 ? 1 : 0;
    largest = std::max(largest, difference);
    drawn += legacy[p + 3] != 0 ? 1 : 0;  // cleared to alpha 0; the programs write alpha 1
  }
  std::printf("%d of %d pixels differ, by at most %d/255; the terrain covers %d pixels\n",
              differing, kSize * kSize, largest, drawn);
  if (drawn < kSize * kSize / 4) {
    std::printf("FAIL: the terrain covers too little of the picture to compare\n");
    return 1;
  }
  const bool match = largest <= 1 && differing <= kSize * kSize / 100;
  std::printf(match ? "ok: the pictures match\n" : "FAIL: the pictures differ\n");
  return match ? 0 : 1;
}
