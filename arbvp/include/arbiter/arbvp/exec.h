// The execution model shared by every engine (the reference interpreter in arbvp/, Mesa in
// runtime/): the inputs one run of an ARB program (or a vertex + fragment pair) reads, and
// the output registers it produces per input vector.
//
// The GL state is stored the way the state.* bindings read it (eye-space light positions,
// clip and texgen eye planes as GL keeps them after the modelview transform), so an engine
// that feeds GL loads the identity modelview before specifying those.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/ir.h"
#include "arbiter/glstate/gl_state.h"

namespace arbiter::arbvp {

// The GL state model is glstate's (arbiter/glstate/gl_state.h), shared with the host
// library that feeds a translation's uniforms; the state.* bindings read it through
// arbiter/glstate/values.h.
using glstate::GlState;
using glstate::kMaxClipPlanes;
using glstate::kMaxLights;
using glstate::kMaxProgramMatrices;
using glstate::kMaxProgramParams;
using glstate::kMaxTextureCoords;
using glstate::LightState;
using glstate::MaterialState;
using glstate::ProgramParameters;
using glstate::TexGenState;
using glstate::Vec4;

// Texture image units (texture[n] of TEX, TXP, TXB), a separate and larger set than the
// texture coordinate sets (kMaxTextureCoords): Mesa's fragment MAX_TEXTURE_IMAGE_UNITS_ARB
// (`arbfp.max_texture_image_units` in compiler/src/limits.def). Real programs sample past the
// coordinate sets (Unity: 8 to 15).
inline constexpr int kMaxTextureImageUnits = 32;
inline constexpr int kMaxGenericAttribs = 16;

// The value a state.* binding (kind State) reads from `state`: glstate::StateValue, the
// derived items (half vectors, light products, scene colours, the mvp, inverses and
// transposes computed with GLM) as the specs define them (ARBvp 2.14.3.x tables, ARBfp
// 3.11.3.x).
Vec4 ReadStateBinding(const GlState& state, const Binding& binding);

// ---------------------------------------------------------------------------------------
// Textures.

enum class TexDim : uint8_t { Tex1D, Tex2D, Tex3D, Cube, Rect };
// The dimension of texture a sampling target reads (SHADOW2D reads a 2D texture), and whether
// the target compares depths.
TexDim TargetDim(TexTarget target);
// The ARB spelling of a texture's dimension: "1D", "2D", "3D", "CUBE", "RECT".
std::string_view TexDimName(TexDim dim);
bool IsShadowTarget(TexTarget target);
enum class TexFilter : uint8_t { Nearest, Linear };
enum class TexWrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat };
// GL_TEXTURE_COMPARE_FUNC for depth textures in GL_COMPARE_R_TO_TEXTURE mode.
enum class CompareFunc : uint8_t { Never, Less, Equal, Lequal, Greater, Notequal, Gequal, Always };
// GL_DEPTH_TEXTURE_MODE: how a depth (or comparison) result d becomes RGBA.
enum class DepthMode : uint8_t { Luminance, Intensity, Alpha };

// One texture bound to one unit: a single mipmap level (minification and magnification use
// the same filter). A program that samples a unit with a target other than the bound
// texture's dimension reads an incomplete texture: (0,0,0,1).
struct Texture {
  TexDim dim = TexDim::Tex2D;
  int width = 1;
  int height = 1;  // 1 for 1D
  int depth = 1;   // 3D: slices; Cube: 6 faces (+X -X +Y -Y +Z -Z), each width x height
  // RGBA texels, x fastest, then y, then slice/face. A depth texture uses only the red
  // channel of each texel as its depth value.
  std::vector<float> texels;
  TexFilter filter = TexFilter::Nearest;
  TexWrap wrap = TexWrap::Repeat;  // s, t and r; RECT allows ClampToEdge only
  bool depth_texture = false;
  bool compare = false;  // GL_COMPARE_R_TO_TEXTURE (shadow targets need it)
  CompareFunc compare_func = CompareFunc::Lequal;
  DepthMode depth_mode = DepthMode::Luminance;
};

// ---------------------------------------------------------------------------------------
// Per-vector inputs.

// Vertex attributes as GL holds them (the current values' defaults). The program reads
// vertex.normal as (x, y, z, 1), vertex.fogcoord as (f, 0, 0, 1) and vertex.color.secondary
// as (r, g, b, 1) whatever the stored components (ARBvp table X.1; GL 2.0 2.7: GL has no
// such components, and secondary A is always 1).
struct VertexInput {
  Vec4 position{0.0f, 0.0f, 0.0f, 1.0f};
  Vec4 weight{1.0f, 0.0f, 0.0f, 0.0f};
  Vec4 normal{0.0f, 0.0f, 1.0f, 1.0f};
  Vec4 color{1.0f, 1.0f, 1.0f, 1.0f};
  Vec4 secondary_color{0.0f, 0.0f, 0.0f, 1.0f};
  Vec4 fogcoord{0.0f, 0.0f, 0.0f, 1.0f};
  std::array<Vec4, kMaxTextureCoords> texcoord;  // (0,0,0,1)
  Vec4 matrix_index{0.0f, 0.0f, 0.0f, 0.0f};
  // (0,0,0,1). generic[0] is never read: vertex.attrib[0] is `position` (ARBvp 2.7).
  std::array<Vec4, kMaxGenericAttribs> generic;
  VertexInput();
};

// Fragment inputs of a fragment program run alone (a pair takes them from the vertex
// program). fragment.position is not an input: every engine places vector i at the pixel
// FragmentPixel(i), so fragment.position = (x + 0.5, y + 0.5, depth, 1) (other origin and
// centre under the fragment coordinate options: FragmentCoordXY) with `depth` the
// window depth below. fragment.fogcoord reads (fogcoord, 0, 0, 1).
struct FragmentInput {
  Vec4 color{1.0f, 1.0f, 1.0f, 1.0f};
  Vec4 secondary_color{0.0f, 0.0f, 0.0f, 1.0f};
  std::array<Vec4, kMaxTextureCoords> texcoord;  // (0,0,0,1)
  float fogcoord = 0.0f;
  float depth = 0.5f;  // window z in [depth_near, depth_far]
  FragmentInput();
};

struct InputVector {
  VertexInput vertex;
  FragmentInput fragment;
};

// Where vector `index` is drawn: pixel (index % kFramebufferWidth, index / kFramebufferWidth).
inline constexpr int kFramebufferWidth = 64;
struct Pixel {
  int x = 0;
  int y = 0;
};
inline Pixel FragmentPixel(size_t index) {
  return {static_cast<int>(index % kFramebufferWidth), static_cast<int>(index / kFramebufferWidth)};
}
// The rows of the framebuffer `count` vectors are drawn to.
inline int FramebufferHeight(size_t count) {
  return static_cast<int>((count + kFramebufferWidth - 1) / kFramebufferWidth);
}

// The fragment coordinate conventions of ARB_fragment_coord_conventions: the origin (lower or
// upper left of the framebuffer) and the pixel centre (half or whole pixel) that
// fragment.position's x and y follow.
struct FragCoordConvention {
  bool upper_left = false;
  bool integer_center = false;
};
inline FragCoordConvention FragCoordConventionOf(const Program& fragment) {
  return {fragment.HasOption(OptionId::OriginUpperLeft),
          fragment.HasOption(OptionId::PixelCenterInteger)};
}

// fragment.position.xy of vector `index` of `count` under `convention`.
inline std::array<float, 2> FragmentCoordXY(size_t index, size_t count,
                                            FragCoordConvention convention) {
  const Pixel p = FragmentPixel(index);
  const float offset = convention.integer_center ? 0.0f : 0.5f;
  const int row = convention.upper_left ? FramebufferHeight(count) - 1 - p.y : p.y;
  return {static_cast<float>(p.x) + offset, static_cast<float>(row) + offset};
}

// Everything one run reads. program.env is per target; program.local per program
// (ProgramParameters: indices not in the maps read (0,0,0,0), GL's initial value).
struct ExecInputs {
  GlState state;
  ProgramParameters vertex_params;
  ProgramParameters fragment_params;
  std::map<int, Texture> textures;  // by texture image unit
  std::vector<InputVector> vectors;
};

// ---------------------------------------------------------------------------------------
// Results.

// One result register a program wrote (a pair reports the fragment program's outputs).
struct OutputRegister {
  Binding binding;   // kind Result: result.color[1], result.texcoord[3], result.depth, ...
  std::string name;  // BindingName(binding), e.g. "result.color.back.secondary"
  Vec4 value{0.0f, 0.0f, 0.0f, 0.0f};
  uint8_t written = 0;  // mask of the components the program wrote (bit 0 = x)
  // Per component: empty when the specs define the value; else why not, naming the
  // instruction, e.g. "LG2 of a non-positive value at 4:1" (interpreter only; other
  // engines leave these empty).
  std::array<std::string, 4> undefined;
  // Interpreter only, the tolerance model (docs/verify.md): per component, how far a
  // conforming engine's value may be from `value` (+inf: within rounding of a discontinuity,
  // not comparable), and the known Mesa deviations it depends on (deviations.h).
  std::array<float, 4> tolerance{};
  std::array<uint32_t, 4> deviations{};
};

struct VectorResult {
  // In a stable order (ResultRegOrder below). Empty when the fragment was killed: GL writes
  // nothing for it.
  std::vector<OutputRegister> outputs;
  bool killed = false;  // fragment programs: a KIL discarded the fragment
  // Interpreter only: non-empty when whether a KIL discarded the fragment depends on an
  // undefined value (then every reported output component is tagged with it too).
  std::string kill_undefined;
  // Interpreter only: whether KIL discards is within rounding of its threshold (then every
  // output tolerance is +inf), and the deviations that decision depends on.
  bool kill_unstable = false;
  uint32_t kill_deviations = 0;
};

// The stable order of result registers (position, colours, fog, point size, texcoords by
// index, then fragment colours by index, depth): engines sort their outputs with it.
bool ResultRegOrder(const Binding& a, const Binding& b);

}  // namespace arbiter::arbvp
