// Commands that set program inputs and GL state: parameter (ARB env/local), uniform (GLSL),
// light, and arbiter's material, lightmodel, fog, texenv and matrix extensions.
#include <fmt/format.h>

#include <array>

#include "shader_test/session.h"
#include "shader_test/words.h"

namespace arbiter::runtime::shader_test {
namespace {

// A GLSL type of the `uniform` command: its base and shape.
struct UniformType {
  std::string_view name;
  char base;  // 'f' float, 'i' int/bool/sampler, 'u' uint
  int columns;
  int rows;  // 1 for scalars and vectors
};

constexpr std::array<UniformType, 25> kUniformTypes{{
    {"float", 'f', 1, 1},  {"vec2", 'f', 2, 1},   {"vec3", 'f', 3, 1},   {"vec4", 'f', 4, 1},
    {"int", 'i', 1, 1},    {"ivec2", 'i', 2, 1},  {"ivec3", 'i', 3, 1},  {"ivec4", 'i', 4, 1},
    {"bool", 'i', 1, 1},   {"bvec2", 'i', 2, 1},  {"bvec3", 'i', 3, 1},  {"bvec4", 'i', 4, 1},
    {"uint", 'u', 1, 1},   {"uvec2", 'u', 2, 1},  {"uvec3", 'u', 3, 1},  {"uvec4", 'u', 4, 1},
    {"mat2", 'f', 2, 2},   {"mat3", 'f', 3, 3},   {"mat4", 'f', 4, 4},   {"mat2x3", 'f', 2, 3},
    {"mat2x4", 'f', 2, 4}, {"mat3x2", 'f', 3, 2}, {"mat3x4", 'f', 3, 4}, {"mat4x2", 'f', 4, 2},
    {"mat4x3", 'f', 4, 3},
}};

}  // namespace

void Session::SetParameter(const std::vector<std::string>& a) {
  if (a.size() != 6)
    Error("expected 'parameter env_vp|local_vp|env_fp|local_fp index (x, y, z, w)'");
  const std::string& which = a[0];
  if (which != "env_vp" && which != "local_vp" && which != "env_fp" && which != "local_fp") {
    Error(fmt::format("unknown parameter kind '{}'", which));
  }
  const bool local = which[0] == 'l';
  const bool vertex = which.back() == 'p' && which[which.size() - 2] == 'v';
  const int index = Int(a, 1);
  if (index < 0 || index >= 256) Error(fmt::format("parameter index {} out of range", index));
  const std::array<float, 4> v = {Float(a, 2), Float(a, 3), Float(a, 4), Float(a, 5)};
  const auto kind = vertex ? arbvp::ProgramKind::Vertex : arbvp::ProgramKind::Fragment;
  parameters_[{kind, local, index}] = v;
  if (translated_) return;  // uploaded as uniforms before each draw
  const GLenum target = vertex ? GL_VERTEX_PROGRAM_ARB : GL_FRAGMENT_PROGRAM_ARB;
  if (local) {
    gl_.ProgramLocalParameter4fvARB(target, static_cast<GLuint>(index), v.data());
  } else {
    gl_.ProgramEnvParameter4fvARB(target, static_cast<GLuint>(index), v.data());
  }
}

void Session::SetUniform(const std::vector<std::string>& a) {
  if (a.size() < 3) Error("expected 'uniform type name values...'");
  if (program_ == 0) Error("'uniform' without a GLSL program");
  if (!link_ok_) Error("'uniform' after a failed link");
  const UniformType* type = nullptr;
  for (const UniformType& t : kUniformTypes) {
    if (t.name == a[0] || (a[0] == "mat2x2" && t.name == "mat2") ||
        (a[0] == "mat3x3" && t.name == "mat3") || (a[0] == "mat4x4" && t.name == "mat4")) {
      type = &t;
    }
  }
  const bool sampler = a[0].rfind("sampler", 0) == 0 || a[0].rfind("isampler", 0) == 0 ||
                       a[0].rfind("usampler", 0) == 0;
  static constexpr UniformType kSampler{"sampler", 'i', 1, 1};
  if (sampler) type = &kSampler;
  if (type == nullptr) Error(fmt::format("unsupported uniform type '{}'", a[0]));
  const GLint location = gl_.GetUniformLocation(program_, a[1].c_str());
  if (location < 0) Error(fmt::format("the program has no active uniform '{}'", a[1]));
  const size_t per = static_cast<size_t>(type->columns * type->rows);
  size_t given = a.size() - 2;
  // piglit sets the values it was given; the rest of the last element reads as zero.
  const size_t padded = (given + per - 1) / per * per;
  std::vector<std::string> args = a;
  args.resize(padded + 2, "0");
  const auto count = static_cast<GLsizei>(padded / per);
  given = padded;
  if (type->base == 'f') {
    std::vector<float> v(given);
    for (size_t i = 0; i < given; ++i) v[i] = Float(args, 2 + i);
    const std::string shape =
        type->rows == 1 ? "" : fmt::format("{}x{}", type->columns, type->rows);
    using Matrix = void(APIENTRYP)(GLint, GLsizei, GLboolean, const GLfloat*);
    const std::array<std::pair<std::string_view, Matrix>, 9> matrices{{
        {"2x2", gl_.UniformMatrix2fv},
        {"3x3", gl_.UniformMatrix3fv},
        {"4x4", gl_.UniformMatrix4fv},
        {"2x3", gl_.UniformMatrix2x3fv},
        {"2x4", gl_.UniformMatrix2x4fv},
        {"3x2", gl_.UniformMatrix3x2fv},
        {"3x4", gl_.UniformMatrix3x4fv},
        {"4x2", gl_.UniformMatrix4x2fv},
        {"4x3", gl_.UniformMatrix4x3fv},
    }};
    if (type->rows == 1) {
      using Vector = void(APIENTRYP)(GLint, GLsizei, const GLfloat*);
      const std::array<Vector, 4> vectors{gl_.Uniform1fv, gl_.Uniform2fv, gl_.Uniform3fv,
                                          gl_.Uniform4fv};
      vectors[static_cast<size_t>(type->columns - 1)](location, count, v.data());
    } else {
      for (const auto& [name, set] : matrices) {
        if (name == shape) set(location, count, GL_FALSE, v.data());
      }
    }
  } else if (type->base == 'i') {
    std::vector<GLint> v(given);
    for (size_t i = 0; i < given; ++i) v[i] = Int(args, 2 + i);
    using Vector = void(APIENTRYP)(GLint, GLsizei, const GLint*);
    const std::array<Vector, 4> vectors{gl_.Uniform1iv, gl_.Uniform2iv, gl_.Uniform3iv,
                                        gl_.Uniform4iv};
    vectors[static_cast<size_t>(type->columns - 1)](location, count, v.data());
  } else {
    std::vector<GLuint> v(given);
    for (size_t i = 0; i < given; ++i) {
      unsigned u = 0;
      if (!ParseUint(args[2 + i], &u)) {
        Error(fmt::format("'{}' is not an unsigned integer", args[2 + i]));
      }
      v[i] = u;
    }
    using Vector = void(APIENTRYP)(GLint, GLsizei, const GLuint*);
    const std::array<Vector, 4> vectors{gl_.Uniform1uiv, gl_.Uniform2uiv, gl_.Uniform3uiv,
                                        gl_.Uniform4uiv};
    vectors[static_cast<size_t>(type->columns - 1)](location, count, v.data());
  }
}

void Session::SetState(const std::string& command, const std::vector<std::string>& a) {
  // The values after an optional "float" word, up to 16.
  auto values = [&](size_t first, size_t min, size_t max) {
    if (first < a.size() && a[first] == "float") ++first;
    const size_t n = a.size() >= first ? a.size() - first : 0;
    if (n < min || n > max) {
      Error(fmt::format("'{}' takes {} to {} values after its names", command, min, max));
    }
    std::vector<float> v(16, 0.0f);
    for (size_t i = 0; i < n; ++i) v[i] = Float(a, first + i);
    return v;
  };
  if (command == "light") {  // light <n> <pname> float <values>
    if (a.size() < 3) Error("expected 'light n GL_PNAME float values...'");
    const int n = Int(a, 0);
    if (n < 0 || n >= 8) Error(fmt::format("light {} out of range", n));
    gl_.Lightfv(static_cast<GLenum>(GL_LIGHT0 + n), Enum(a[1]), values(2, 1, 4).data());
  } else if (command == "material") {  // material <face> <pname> float <values>
    if (a.size() < 3) Error("expected 'material GL_FACE GL_PNAME float values...'");
    gl_.Materialfv(Enum(a[0]), Enum(a[1]), values(2, 1, 4).data());
  } else if (command == "lightmodel") {  // lightmodel <pname> float <values>
    if (a.empty()) Error("expected 'lightmodel GL_PNAME float values...'");
    gl_.LightModelfv(Enum(a[0]), values(1, 1, 4).data());
  } else if (command == "fog") {  // fog GL_FOG_MODE GL_LINEAR | fog <pname> float <values>
    if (a.size() == 2 && a[1].rfind("GL_", 0) == 0) {
      gl_.Fogf(Enum(a[0]), static_cast<float>(Enum(a[1])));
    } else {
      if (a.empty()) Error("expected 'fog GL_PNAME float values...'");
      gl_.Fogfv(Enum(a[0]), values(1, 1, 4).data());
    }
  } else if (command == "texenv") {  // texenv <unit> <pname> float <values>
    if (a.size() < 3) Error("expected 'texenv unit GL_PNAME float values...'");
    const int unit = Int(a, 0);
    if (unit < 0 || unit >= 8) Error(fmt::format("texture unit {} out of range", unit));
    const std::vector<float> v = values(2, 1, 4);
    const GLenum pname = Enum(a[1]);
    GLint active = GL_TEXTURE0;
    gl_.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
    gl_.ActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    gl_.TexEnvfv(GL_TEXTURE_ENV, pname, v.data());
    gl_.ActiveTexture(static_cast<GLenum>(active));  // texparameter keeps its unit
  } else if (command == "matrix") {                  // matrix <which> <16 floats, column-major>
    if (a.empty()) Error("expected 'matrix GL_MODELVIEW m0 ... m15'");
    const std::vector<float> m = values(1, 16, 16);
    const std::string& which = a[0];
    GLenum mode = Enum(which);
    GLint unit = -1;
    if (mode >= GL_TEXTURE0 && mode < GL_TEXTURE0 + 8) {
      unit = static_cast<GLint>(mode - GL_TEXTURE0);
      mode = GL_TEXTURE;
    } else if (mode != GL_MODELVIEW && mode != GL_PROJECTION &&
               (mode < GL_MATRIX0_ARB || mode >= GL_MATRIX0_ARB + 8)) {
      Error(fmt::format("'{}' is not a matrix this command loads", which));
    }
    GLint active = GL_TEXTURE0;
    gl_.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
    if (unit >= 0) gl_.ActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    gl_.MatrixMode(mode);
    gl_.LoadMatrixf(m.data());
    gl_.MatrixMode(GL_MODELVIEW);
    gl_.ActiveTexture(static_cast<GLenum>(active));
  }
}

}  // namespace arbiter::runtime::shader_test
