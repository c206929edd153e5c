// Texture upload: see textures.h.
#include "exec/textures.h"

#include <fmt/format.h>

#include <set>

namespace arbiter::runtime::exec {
namespace {

GLenum Target(arbvp::TexDim dim) {
  switch (dim) {
    case arbvp::TexDim::Tex1D:
      return GL_TEXTURE_1D;
    case arbvp::TexDim::Tex2D:
      return GL_TEXTURE_2D;
    case arbvp::TexDim::Tex3D:
      return GL_TEXTURE_3D;
    case arbvp::TexDim::Cube:
      return GL_TEXTURE_CUBE_MAP;
    case arbvp::TexDim::Rect:
      return GL_TEXTURE_RECTANGLE_ARB;
  }
  return GL_TEXTURE_2D;
}

GLint Wrap(arbvp::TexWrap wrap) {
  switch (wrap) {
    case arbvp::TexWrap::Repeat:
      return GL_REPEAT;
    case arbvp::TexWrap::ClampToEdge:
      return GL_CLAMP_TO_EDGE;
    case arbvp::TexWrap::MirroredRepeat:
      return GL_MIRRORED_REPEAT;
  }
  return GL_REPEAT;
}

GLint CompareFunc(arbvp::CompareFunc func) {
  switch (func) {
    case arbvp::CompareFunc::Never:
      return GL_NEVER;
    case arbvp::CompareFunc::Less:
      return GL_LESS;
    case arbvp::CompareFunc::Equal:
      return GL_EQUAL;
    case arbvp::CompareFunc::Lequal:
      return GL_LEQUAL;
    case arbvp::CompareFunc::Greater:
      return GL_GREATER;
    case arbvp::CompareFunc::Notequal:
      return GL_NOTEQUAL;
    case arbvp::CompareFunc::Gequal:
      return GL_GEQUAL;
    case arbvp::CompareFunc::Always:
      return GL_ALWAYS;
  }
  return GL_LEQUAL;
}

// Uploads level 0 (or one cube face) of `t` from `data` (RGBA, or one depth per texel).
void Image(const ExecGl& gl, GLenum target, const arbvp::Texture& t, const float* data) {
  const GLint internal = t.depth_texture ? GL_DEPTH_COMPONENT32F : GL_RGBA32F_ARB;
  const GLenum format = t.depth_texture ? GL_DEPTH_COMPONENT : GL_RGBA;
  switch (t.dim) {
    case arbvp::TexDim::Tex1D:
      gl.TexImage1D(target, 0, internal, t.width, 0, format, GL_FLOAT, data);
      break;
    case arbvp::TexDim::Tex3D:
      gl.TexImage3D(target, 0, internal, t.width, t.height, t.depth, 0, format, GL_FLOAT, data);
      break;
    case arbvp::TexDim::Tex2D:
    case arbvp::TexDim::Cube:
    case arbvp::TexDim::Rect:
      gl.TexImage2D(target, 0, internal, t.width, t.height, 0, format, GL_FLOAT, data);
      break;
  }
}

bool Upload(const ExecGl& gl, int unit, const arbvp::Texture& t, bool compatibility,
            std::string* error) {
  const int layers = t.dim == arbvp::TexDim::Cube ? 6 : t.dim == arbvp::TexDim::Tex3D ? t.depth : 1;
  const int height = t.dim == arbvp::TexDim::Tex1D ? 1 : t.height;
  if (t.width < 1 || height < 1 || layers < 1) {
    *error = fmt::format("texture on unit {} has an empty size", unit);
    return false;
  }
  const size_t texels =
      static_cast<size_t>(t.width) * static_cast<size_t>(height) * static_cast<size_t>(layers);
  if (t.texels.size() != texels * 4) {
    *error = fmt::format("texture on unit {} holds {} floats; its size needs {}", unit,
                         t.texels.size(), texels * 4);
    return false;
  }
  // A depth texture takes the red channel of each texel.
  std::vector<float> data;
  if (t.depth_texture) {
    data.resize(texels);
    for (size_t i = 0; i < texels; ++i) data[i] = t.texels[i * 4];
  }
  const float* base = t.depth_texture ? data.data() : t.texels.data();
  const size_t channels = t.depth_texture ? 1 : 4;
  const GLenum target = Target(t.dim);
  gl.ActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  if (t.dim == arbvp::TexDim::Cube) {
    const size_t face_size =
        static_cast<size_t>(t.width) * static_cast<size_t>(t.height) * channels;
    for (int face = 0; face < 6; ++face) {
      Image(gl, static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), t,
            base + face_size * static_cast<size_t>(face));
    }
  } else {
    Image(gl, target, t, base);
  }
  const GLint filter = t.filter == arbvp::TexFilter::Linear ? GL_LINEAR : GL_NEAREST;
  gl.TexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
  gl.TexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
  gl.TexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
  gl.TexParameteri(target, GL_TEXTURE_WRAP_S, Wrap(t.wrap));
  if (t.dim != arbvp::TexDim::Tex1D) gl.TexParameteri(target, GL_TEXTURE_WRAP_T, Wrap(t.wrap));
  if (t.dim == arbvp::TexDim::Tex3D || t.dim == arbvp::TexDim::Cube) {
    gl.TexParameteri(target, GL_TEXTURE_WRAP_R, Wrap(t.wrap));
  }
  if (t.depth_texture) {
    gl.TexParameteri(target, GL_TEXTURE_COMPARE_MODE,
                     t.compare ? GL_COMPARE_R_TO_TEXTURE : GL_NONE);
    gl.TexParameteri(target, GL_TEXTURE_COMPARE_FUNC, CompareFunc(t.compare_func));
    if (compatibility)
      gl.TexParameteri(target, GL_DEPTH_TEXTURE_MODE, DepthTextureMode(t.depth_mode));
  }
  return true;
}

}  // namespace

GLint DepthTextureMode(arbvp::DepthMode mode) {
  switch (mode) {
    case arbvp::DepthMode::Luminance:
      return GL_LUMINANCE;
    case arbvp::DepthMode::Intensity:
      return GL_INTENSITY;
    case arbvp::DepthMode::Alpha:
      return GL_ALPHA;
  }
  return GL_LUMINANCE;
}

bool UploadTextures(const ExecGl& gl, const std::map<int, arbvp::Texture>& textures,
                    std::vector<GLuint>* created, std::string* error, bool compatibility,
                    const std::set<int>& as_2d) {
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (const auto& [unit, model] : textures) {
    arbvp::Texture flat;
    const bool emulated = as_2d.count(unit) != 0 &&
                          (model.dim == arbvp::TexDim::Tex1D || model.dim == arbvp::TexDim::Rect);
    if (emulated) {  // the same texels as a 2D texture: N x 1, or W x H without levels
      flat = model;
      if (flat.dim == arbvp::TexDim::Tex1D) flat.height = 1;
      flat.dim = arbvp::TexDim::Tex2D;
    }
    const arbvp::Texture& texture = emulated ? flat : model;
    if (unit < 0 || unit >= arbvp::kMaxTextureImageUnits) {
      *error =
          fmt::format("texture unit {} is outside 0..{}", unit, arbvp::kMaxTextureImageUnits - 1);
      return false;
    }
    GLuint name = 0;
    gl.GenTextures(1, &name);
    created->push_back(name);
    gl.ActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    gl.BindTexture(Target(texture.dim), name);
    if (!Upload(gl, unit, texture, compatibility, error)) return false;
  }
  gl.ActiveTexture(GL_TEXTURE0);
  return true;
}

void DeleteTextures(const ExecGl& gl, std::vector<GLuint>* created) {
  if (!created->empty()) gl.DeleteTextures(static_cast<GLsizei>(created->size()), created->data());
  created->clear();
}

}  // namespace arbiter::runtime::exec
