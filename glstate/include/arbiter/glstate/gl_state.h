// The GL fixed-function state that ARB programs read through `state.*`, `program.env` and
// `program.local`, as a legacy engine keeps it: the model of the reference interpreter
// (arbiter/arbvp/exec.h aliases these types) and the input of the host library (values.h,
// uniforms.h). Header-only; needs GLM.
//
// The state is stored the way the state.* bindings read it: light positions and spot
// directions, clip planes and texgen eye planes in eye space, as GL keeps them after
// transforming them by the modelview matrix current when they were specified. An engine that
// tracks glLightfv(GL_POSITION) and friends stores what GL stored, not its arguments.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <map>

namespace arbiter::glstate {

using Vec4 = std::array<float, 4>;

// Texture coordinate sets and the legacy texture units of state.matrix.texture[n],
// state.texgen[n] and state.texenv[n]: Mesa's MAX_TEXTURE_COORDS and MAX_TEXTURE_UNITS.
inline constexpr int kMaxTextureCoords = 8;
inline constexpr int kMaxLights = 8;
inline constexpr int kMaxClipPlanes = 6;
inline constexpr int kMaxProgramMatrices = 8;  // state.matrix.program[n]
// Texture image units of fragment programs' texture[n]: Mesa's MAX_TEXTURE_IMAGE_UNITS.
inline constexpr int kMaxTextureImageUnits = 16;
// GL_DEPTH_TEXTURE_MODE's values (ARB_depth_texture; GL_RED is GL 3.0's).
inline constexpr uint32_t kDepthModeLuminance = 0x1909;  // GL_LUMINANCE, the initial value
inline constexpr uint32_t kDepthModeIntensity = 0x8049;  // GL_INTENSITY
inline constexpr uint32_t kDepthModeAlpha = 0x1906;      // GL_ALPHA
inline constexpr uint32_t kDepthModeRed = 0x1903;        // GL_RED
// env and local indices accepted by the model: Mesa's MAX_PROGRAM_ENV_PARAMETERS (the specs'
// minimum is 96 for vertex programs, 24 for fragment programs).
inline constexpr int kMaxProgramParams = 256;

// Defaults are GL's initial state (OpenGL 2.0 tables 6.x).

struct MaterialState {
  Vec4 ambient{0.2f, 0.2f, 0.2f, 1.0f};
  Vec4 diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  Vec4 specular{0.0f, 0.0f, 0.0f, 1.0f};
  Vec4 emission{0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;
};

struct LightState {
  Vec4 ambient{0.0f, 0.0f, 0.0f, 1.0f};
  Vec4 diffuse{0.0f, 0.0f, 0.0f, 1.0f};                    // light 0: (1,1,1,1)
  Vec4 specular{0.0f, 0.0f, 0.0f, 1.0f};                   // light 0: (1,1,1,1)
  Vec4 position{0.0f, 0.0f, 1.0f, 0.0f};                   // eye space
  std::array<float, 3> spot_direction{0.0f, 0.0f, -1.0f};  // eye space
  float spot_exponent = 0.0f;
  float spot_cutoff = 180.0f;  // degrees; state.light[n].spot.direction.w is its cosine
  float constant_attenuation = 1.0f;
  float linear_attenuation = 0.0f;
  float quadratic_attenuation = 0.0f;
};

struct TexGenState {
  // Per coordinate s, t, r, q. Eye planes as GL stores them (eye space).
  std::array<Vec4, 4> eye{Vec4{1, 0, 0, 0}, Vec4{0, 1, 0, 0}, Vec4{0, 0, 0, 0}, Vec4{0, 0, 0, 0}};
  std::array<Vec4, 4> object{Vec4{1, 0, 0, 0}, Vec4{0, 1, 0, 0}, Vec4{0, 0, 0, 0},
                             Vec4{0, 0, 0, 0}};
};

struct GlState {
  // The top of each matrix stack, as GL holds it (glm is column-major like GL: m[c][r] is
  // row r of column c). ARB programs read their rows.
  glm::mat4 modelview{1.0f};
  glm::mat4 projection{1.0f};
  std::array<glm::mat4, kMaxTextureCoords> texture{};  // identity after construction
  std::array<glm::mat4, kMaxProgramMatrices> program{};
  std::array<MaterialState, 2> material{};  // front, back
  std::array<LightState, kMaxLights> light{};
  Vec4 light_model_ambient{0.2f, 0.2f, 0.2f, 1.0f};
  std::array<TexGenState, kMaxTextureCoords> texgen{};
  Vec4 fog_color{0.0f, 0.0f, 0.0f, 0.0f};
  float fog_density = 1.0f;
  float fog_start = 0.0f;
  float fog_end = 1.0f;
  std::array<Vec4, kMaxClipPlanes> clip_plane{};  // eye space; (0,0,0,0) initially
  // Whether GL_CLIP_PLANEn is enabled (off initially). Not an ARB binding: translations to
  // dialects without an enable of their own read it as "clip[n].enabled" (uniforms.h).
  std::array<bool, kMaxClipPlanes> clip_enabled{};
  float point_size = 1.0f;
  float point_size_min = 0.0f;
  float point_size_max = 1.0f;  // GL's initial value is implementation-dependent; fixed here
  float point_fade_threshold = 1.0f;
  std::array<float, 3> point_attenuation{1.0f, 0.0f, 0.0f};
  std::array<Vec4, kMaxTextureCoords> texenv_color{};  // (0,0,0,0) initially
  float depth_near = 0.0f;
  float depth_far = 1.0f;
  // The height in pixels of the framebuffer drawn to. Not GL state an ARB program reads:
  // translations whose gl_FragCoord counts y from the other edge than fragment.position
  // (Vulkan; ES under OPTION ARB_fragment_coord_origin_upper_left) read it as
  // "framebuffer.height" (uniforms.h).
  float framebuffer_height = 0.0f;
  // GL_DEPTH_TEXTURE_MODE of the texture bound to each image unit: how a shadow lookup
  // (ARB_fragment_program_shadow) expands its result. Not an ARB state binding; translations
  // with state as uniforms read it as "texture[n].depthmode" (uniforms.h).
  std::array<uint32_t, kMaxTextureImageUnits> depth_texture_mode = [] {
    std::array<uint32_t, kMaxTextureImageUnits> modes{};
    modes.fill(kDepthModeLuminance);
    return modes;
  }();

  // Sets the identity matrices and light 0's white diffuse and specular colours.
  GlState() {
    // glm 0.9.9 leaves default-constructed matrices uninitialised: GL's initial value of
    // every matrix stack is the identity.
    modelview = glm::mat4(1.0f);
    projection = glm::mat4(1.0f);
    texture.fill(glm::mat4(1.0f));
    program.fill(glm::mat4(1.0f));
    // OpenGL 2.0 table 6.x: light 0 starts with white diffuse and specular colours.
    light[0].diffuse = {1.0f, 1.0f, 1.0f, 1.0f};
    light[0].specular = {1.0f, 1.0f, 1.0f, 1.0f};
  }
};

// The program parameters of one program: program.env is per target (the vertex program
// target's or the fragment program target's, glProgramEnvParameter4fvARB), program.local per
// program object (glProgramLocalParameter4fvARB). Indices not in the maps read (0,0,0,0),
// GL's initial value.
struct ProgramParameters {
  std::map<int, Vec4> env;
  std::map<int, Vec4> local;
};

}  // namespace arbiter::glstate
