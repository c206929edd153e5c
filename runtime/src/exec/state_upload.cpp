// GL state and program parameters: see state_upload.h.
#include "exec/state_upload.h"

#include <array>

namespace arbiter::runtime::exec {
namespace {

void LoadMatrix(const ExecGl& gl, GLenum mode, const glm::mat4& m) {
  gl.MatrixMode(mode);
  gl.LoadMatrixf(&m[0][0]);  // glm is column-major, as GL
}

void UploadLight(const ExecGl& gl, int index, const arbvp::LightState& light) {
  const GLenum id = static_cast<GLenum>(GL_LIGHT0 + index);
  gl.Lightfv(id, GL_AMBIENT, light.ambient.data());
  gl.Lightfv(id, GL_DIFFUSE, light.diffuse.data());
  gl.Lightfv(id, GL_SPECULAR, light.specular.data());
  gl.Lightfv(id, GL_POSITION, light.position.data());
  gl.Lightfv(id, GL_SPOT_DIRECTION, light.spot_direction.data());
  gl.Lightf(id, GL_SPOT_EXPONENT, light.spot_exponent);
  gl.Lightf(id, GL_SPOT_CUTOFF, light.spot_cutoff);
  gl.Lightf(id, GL_CONSTANT_ATTENUATION, light.constant_attenuation);
  gl.Lightf(id, GL_LINEAR_ATTENUATION, light.linear_attenuation);
  gl.Lightf(id, GL_QUADRATIC_ATTENUATION, light.quadratic_attenuation);
}

void UploadMaterial(const ExecGl& gl, GLenum face, const arbvp::MaterialState& m) {
  gl.Materialfv(face, GL_AMBIENT, m.ambient.data());
  gl.Materialfv(face, GL_DIFFUSE, m.diffuse.data());
  gl.Materialfv(face, GL_SPECULAR, m.specular.data());
  gl.Materialfv(face, GL_EMISSION, m.emission.data());
  gl.Materialf(face, GL_SHININESS, m.shininess);
}

constexpr std::array<GLenum, 4> kTexGenCoords = {GL_S, GL_T, GL_R, GL_Q};

}  // namespace

void UploadGlState(const ExecGl& gl, const arbvp::GlState& state) {
  // Eye-space items first, under the identity modelview.
  gl.MatrixMode(GL_MODELVIEW);
  gl.LoadIdentity();
  for (int i = 0; i < arbvp::kMaxLights; ++i)
    UploadLight(gl, i, state.light[static_cast<size_t>(i)]);
  for (int i = 0; i < arbvp::kMaxClipPlanes; ++i) {
    const arbvp::Vec4& p = state.clip_plane[static_cast<size_t>(i)];
    const GLdouble plane[4] = {static_cast<GLdouble>(p[0]), static_cast<GLdouble>(p[1]),
                               static_cast<GLdouble>(p[2]), static_cast<GLdouble>(p[3])};
    gl.ClipPlane(static_cast<GLenum>(GL_CLIP_PLANE0 + i), plane);
  }
  for (int unit = 0; unit < arbvp::kMaxTextureCoords; ++unit) {
    const size_t u = static_cast<size_t>(unit);
    gl.ActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    for (size_t c = 0; c < 4; ++c) {
      gl.TexGenfv(kTexGenCoords[c], GL_EYE_PLANE, state.texgen[u].eye[c].data());
      gl.TexGenfv(kTexGenCoords[c], GL_OBJECT_PLANE, state.texgen[u].object[c].data());
    }
    LoadMatrix(gl, GL_TEXTURE, state.texture[u]);
    gl.TexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, state.texenv_color[u].data());
  }
  gl.ActiveTexture(GL_TEXTURE0);
  LoadMatrix(gl, GL_MODELVIEW, state.modelview);
  LoadMatrix(gl, GL_PROJECTION, state.projection);
  for (int i = 0; i < arbvp::kMaxProgramMatrices; ++i) {
    LoadMatrix(gl, static_cast<GLenum>(GL_MATRIX0_ARB + i), state.program[static_cast<size_t>(i)]);
  }
  gl.MatrixMode(GL_MODELVIEW);
  UploadMaterial(gl, GL_FRONT, state.material[0]);
  UploadMaterial(gl, GL_BACK, state.material[1]);
  gl.LightModelfv(GL_LIGHT_MODEL_AMBIENT, state.light_model_ambient.data());
  gl.Fogfv(GL_FOG_COLOR, state.fog_color.data());
  gl.Fogf(GL_FOG_DENSITY, state.fog_density);
  gl.Fogf(GL_FOG_START, state.fog_start);
  gl.Fogf(GL_FOG_END, state.fog_end);
  gl.PointSize(state.point_size);
  gl.PointParameterf(GL_POINT_SIZE_MIN, state.point_size_min);
  gl.PointParameterf(GL_POINT_SIZE_MAX, state.point_size_max);
  gl.PointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, state.point_fade_threshold);
  gl.PointParameterfv(GL_POINT_DISTANCE_ATTENUATION, state.point_attenuation.data());
  gl.DepthRange(static_cast<GLclampd>(state.depth_near), static_cast<GLclampd>(state.depth_far));
}

void UploadEnvParameters(const ExecGl& gl, GLenum target, const std::map<int, arbvp::Vec4>& env) {
  const arbvp::Vec4 zero{0.0f, 0.0f, 0.0f, 0.0f};
  for (int i = 0; i < arbvp::kMaxProgramParams; ++i) {
    auto it = env.find(i);
    gl.ProgramEnvParameter4fvARB(target, static_cast<GLuint>(i),
                                 (it != env.end() ? it->second : zero).data());
  }
}

void UploadLocalParameters(const ExecGl& gl, GLenum target,
                           const std::map<int, arbvp::Vec4>& local) {
  // Every index, zero where `local` has none: a program reused from the cache keeps the
  // values of its previous run.
  const arbvp::Vec4 zero{0.0f, 0.0f, 0.0f, 0.0f};
  for (int i = 0; i < arbvp::kMaxProgramParams; ++i) {
    auto it = local.find(i);
    gl.ProgramLocalParameter4fvARB(target, static_cast<GLuint>(i),
                                   (it != local.end() ? it->second : zero).data());
  }
}

}  // namespace arbiter::runtime::exec
