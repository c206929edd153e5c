// Drawing: piglit's rectangles (a triangle strip of four corners, through the fixed-function
// vertex array or the piglit_vertex attribute) and [vertex data] with `draw arrays`.
#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <cstdlib>

#include "shader_test/gl_names.h"
#include "shader_test/session.h"
#include "shader_test/words.h"

namespace arbiter::runtime::shader_test {
namespace {

// One [vertex data] column: where its values go and how many per vertex.
struct Column {
  std::string name;
  int size = 0;
  bool integer = false;       // int or uint: fed as integers to a generic attribute
  std::vector<float> values;  // size per row
  std::vector<int32_t> ints;  // the same, for integer columns
};

int ComponentCount(const std::string& count) {
  static constexpr std::array<std::pair<std::string_view, int>, 12> kTypes{{
      {"float", 1},
      {"vec2", 2},
      {"vec3", 3},
      {"vec4", 4},
      {"int", 1},
      {"ivec2", 2},
      {"ivec3", 3},
      {"ivec4", 4},
      {"uint", 1},
      {"uvec2", 2},
      {"uvec3", 3},
      {"uvec4", 4},
  }};
  for (const auto& [name, n] : kTypes) {
    if (name == count) return n;
  }
  int n = 0;
  return ParseInt(count, &n) && n >= 1 && n <= 4 ? n : 0;
}

}  // namespace

void Session::BeforeDraw() {
  if (!link_ok_) Error("cannot draw: the GLSL program did not link");
  UploadTranslationState();
}

void Session::DrawRect(float x, float y, float w, float h, const float* tex) {
  BeforeDraw();
  const float verts[4][4] = {{x, y, 0.0f, 1.0f},
                             {x + w, y, 0.0f, 1.0f},
                             {x, y + h, 0.0f, 1.0f},
                             {x + w, y + h, 0.0f, 1.0f}};
  float texcoords[4][2] = {};
  if (tex != nullptr) {
    const float tx = tex[0], ty = tex[1], tw = tex[2], th = tex[3];
    const float t[4][2] = {{tx, ty}, {tx + tw, ty}, {tx, ty + th}, {tx + tw, ty + th}};
    std::copy(&t[0][0], &t[0][0] + 8, &texcoords[0][0]);
  }
  // piglit feeds piglit_vertex when the current GLSL program has it, else gl_Vertex.
  // A translation reading state from uniforms reads vertex.position at 0 and
  // vertex.texcoord[0] where its binding map says.
  const bool generic =
      StateUniforms() || (program_ != 0 && gl_.GetAttribLocation(program_, "piglit_vertex") >= 0);
  const int tex_location = StateUniforms() ? AttributeLocation("vertex.texcoord[0]") : 1;
  if (generic) {
    gl_.VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, verts);
    gl_.EnableVertexAttribArray(0);
    if (tex != nullptr && tex_location >= 0) {
      gl_.VertexAttribPointer(static_cast<GLuint>(tex_location), 2, GL_FLOAT, GL_FALSE, 0,
                              texcoords);
      gl_.EnableVertexAttribArray(static_cast<GLuint>(tex_location));
    }
  } else {
    gl_.VertexPointer(4, GL_FLOAT, 0, verts);
    gl_.EnableClientState(GL_VERTEX_ARRAY);
    if (tex != nullptr) {
      gl_.ClientActiveTexture(GL_TEXTURE0);
      gl_.TexCoordPointer(2, GL_FLOAT, 0, texcoords);
      gl_.EnableClientState(GL_TEXTURE_COORD_ARRAY);
    }
  }
  gl_.DrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  if (generic) {
    gl_.DisableVertexAttribArray(0);
    if (tex_location >= 0) gl_.DisableVertexAttribArray(static_cast<GLuint>(tex_location));
  } else {
    gl_.DisableClientState(GL_VERTEX_ARRAY);
    gl_.DisableClientState(GL_TEXTURE_COORD_ARRAY);
  }
}

void Session::DrawArrays(const std::vector<std::string>& a) {
  if (a.size() != 3) Error("expected 'draw arrays GL_MODE first count'");
  const GLenum mode = Enum(a[0]);
  const int first = Int(a, 1);
  const int count = Int(a, 2);
  if (test_.vertex_data.empty()) Error("'draw arrays' needs a [vertex data] section");
  BeforeDraw();

  // The header: name/type/count (or name/count) per column.
  std::vector<Column> columns;
  const int header_line = test_.vertex_data[0].line;
  for (const std::string& word : Words(test_.vertex_data[0].text)) {
    std::vector<std::string> parts;
    size_t pos = 0;
    while (true) {
      size_t slash = word.find('/', pos);
      parts.push_back(word.substr(pos, slash == std::string::npos ? slash : slash - pos));
      if (slash == std::string::npos) break;
      pos = slash + 1;
    }
    const int size = parts.size() >= 2 ? ComponentCount(parts.back()) : 0;
    if (size == 0 || parts.size() > 3) {
      throw TestError{header_line, fmt::format("malformed [vertex data] column '{}'", word)};
    }
    const bool integer = parts.size() == 3 && (parts[1] == "int" || parts[1] == "uint");
    columns.push_back({parts[0], size, integer, {}, {}});
  }
  int rows = 0;
  for (size_t r = 1; r < test_.vertex_data.size(); ++r) {
    const ShaderTestLine& row = test_.vertex_data[r];
    std::vector<std::string> words = Words(row.text);
    size_t w = 0;
    for (Column& c : columns) {
      for (int i = 0; i < c.size; ++i, ++w) {
        float v = 0.0f;
        if (w >= words.size() || !ParseFloat(words[w], &v)) {
          throw TestError{row.line, "a [vertex data] row does not match its header"};
        }
        c.values.push_back(v);
        c.ints.push_back(static_cast<int32_t>(std::strtoll(words[w].c_str(), nullptr, 0)));
      }
    }
    if (w != words.size()) throw TestError{row.line, "a [vertex data] row has extra values"};
    ++rows;
  }
  if (first < 0 || count <= 0 || first + count > rows) {
    Error(fmt::format("draw arrays {} {} is outside the {} rows of [vertex data]", first, count,
                      rows));
  }

  std::vector<GLenum> client_states;
  std::vector<GLuint> attribs;
  for (const Column& c : columns) {
    const float* data = c.values.data();
    int texunit = -1;
    int generic = -1;
    if (StateUniforms() && !FixedFunctionBinding(c.name).empty()) {
      // The translation reads these inputs from the generic attributes its binding map names.
      const std::string binding = FixedFunctionBinding(c.name);
      const int location = binding == "vertex.position" ? 0 : AttributeLocation(binding);
      if (location < 0) continue;  // an input the program does not read
      gl_.VertexAttribPointer(static_cast<GLuint>(location), c.size, GL_FLOAT, GL_FALSE, 0, data);
      gl_.EnableVertexAttribArray(static_cast<GLuint>(location));
      attribs.push_back(static_cast<GLuint>(location));
    } else if (c.name == "gl_Vertex") {
      gl_.VertexPointer(c.size, GL_FLOAT, 0, data);
      client_states.push_back(GL_VERTEX_ARRAY);
    } else if (c.name == "gl_Normal") {
      if (c.size != 3) Error("gl_Normal takes 3 components");
      gl_.NormalPointer(GL_FLOAT, 0, data);
      client_states.push_back(GL_NORMAL_ARRAY);
    } else if (c.name == "gl_Color") {
      gl_.ColorPointer(c.size, GL_FLOAT, 0, data);
      client_states.push_back(GL_COLOR_ARRAY);
    } else if (c.name == "gl_SecondaryColor") {
      gl_.SecondaryColorPointer(c.size, GL_FLOAT, 0, data);
      client_states.push_back(GL_SECONDARY_COLOR_ARRAY);
    } else if (c.name == "gl_FogCoord") {
      gl_.FogCoordPointer(GL_FLOAT, 0, data);
      client_states.push_back(GL_FOG_COORD_ARRAY);
    } else if (c.name.rfind("gl_MultiTexCoord", 0) == 0 && ParseInt(c.name.substr(16), &texunit) &&
               texunit >= 0 && texunit < 8) {
      gl_.ClientActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + texunit));
      gl_.TexCoordPointer(c.size, GL_FLOAT, 0, data);
      gl_.EnableClientState(GL_TEXTURE_COORD_ARRAY);
      gl_.ClientActiveTexture(GL_TEXTURE0);
    } else {
      // A GLSL attribute by name, or (arbiter extension, for ARB programs) a generic
      // attribute by its index.
      if (!ParseInt(c.name, &generic)) {
        generic = program_ != 0 ? gl_.GetAttribLocation(program_, c.name.c_str()) : -1;
      }
      if (generic < 0 || generic >= 16) {
        Error(fmt::format("[vertex data] column '{}' is no attribute of the program", c.name));
      }
      if (c.integer) {
        gl_.VertexAttribIPointer(static_cast<GLuint>(generic), c.size, GL_INT, 0, c.ints.data());
      } else {
        gl_.VertexAttribPointer(static_cast<GLuint>(generic), c.size, GL_FLOAT, GL_FALSE, 0, data);
      }
      gl_.EnableVertexAttribArray(static_cast<GLuint>(generic));
      attribs.push_back(static_cast<GLuint>(generic));
    }
  }
  for (GLenum state : client_states) gl_.EnableClientState(state);
  gl_.DrawArrays(mode, first, count);
  for (GLenum state : client_states) gl_.DisableClientState(state);
  for (int unit = 0; unit < 8; ++unit) {
    gl_.ClientActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    gl_.DisableClientState(GL_TEXTURE_COORD_ARRAY);
  }
  gl_.ClientActiveTexture(GL_TEXTURE0);
  for (GLuint attrib : attribs) gl_.DisableVertexAttribArray(attrib);
}

}  // namespace arbiter::runtime::shader_test
