// The GLSL execution cases. Every expected value is derived by hand from the GLSL 1.10/1.20
// spec's definitions (section numbers are GLSL 1.20's; the comment says how where it is not
// obvious); none was copied from an engine's output. Inputs come from uniforms, attributes
// and varyings, never from constants, so that the engines compute them rather than their
// compilers folding them.
#include "glsl_cases.h"

#include <utility>

namespace arbiter::glsl_cases {
namespace {

using V = std::vector<float>;

// Values of pi for the trigonometric cases (the float nearest each).
constexpr float kPi = 3.14159265f;
constexpr float kPi2 = 1.57079633f;   // pi / 2
constexpr float kPi3 = 1.04719755f;   // pi / 3
constexpr float kPi4 = 0.785398163f;  // pi / 4
constexpr float kPi6 = 0.523598776f;  // pi / 6

// The tolerances. Each names why the spec gives no exact value.
// sin, cos and tan of these angles lie in [-1, 1]: GL's 1 part in 10^5 of that range, as an
// absolute bound so that results at 0 (sin(0), cos(pi/2)) need no exact zero.
constexpr float kTrigBound = kGlPrecision;
// asin, acos and atan lie in [-pi, pi]: 1 part in 10^5 of pi, absolute for atan(0) = 0.
constexpr float kInverseTrigBound = kGlPrecision * 4.0f;

GlslExpect Eq(std::string name, V value, size_t vector = 0) {
  GlslExpect e;
  e.vector = vector;
  e.name = std::move(name);
  e.value = std::move(value);
  return e;
}
// Which stages an expression case runs in.
enum Stages : uint8_t { kVertex = 1, kFragment = 2, kBoth = 3 };

// What an expression case may add to its shaders and expectation.
struct More {
  Tolerance tolerance = Tolerance::Exact;
  float bound = 0.0f;
  std::string version;  // "120" for GLSL 1.20 features
  uint8_t stages = kBoth;
  std::vector<std::string> textures;
  std::function<void(std::map<int, arbvp::Texture>&)> make_textures;
  std::vector<std::string> state;
  std::string vulkan_refusal;

  More& Refused(std::string reason) {
    vulkan_refusal = std::move(reason);
    return *this;
  }
  More& Tol(Tolerance t, float b) {
    tolerance = t;
    bound = b;
    return *this;
  }
  More& Version(std::string v) {
    version = std::move(v);
    return *this;
  }
  More& Stages(uint8_t s) {
    stages = s;
    return *this;
  }
  More& Textures(std::vector<std::string> t) {
    textures = std::move(t);
    return *this;
  }
  More& MakeTextures(std::function<void(std::map<int, arbvp::Texture>&)> m) {
    make_textures = std::move(m);
    return *this;
  }
};

// Relative to the value: the approximated operations (exp, log, pow, sqrt, inversesqrt and
// what is built from them: length, distance, normalize, refract, smoothstep's division;
// texture filtering), which GLSL 1.20 4.1.4 holds to GL's 1 part in 10^5.
More Approx() { return More().Tol(Tolerance::Relative, kGlPrecision); }

// A case that computes a vec4 `r` from its uniforms: run in a vertex shader (read back as the
// varying `v`) and in a fragment shader (as gl_FragColor), as "<name>_vs" and "<name>_fs".
struct Expr {
  std::string name;
  std::string spec;
  std::string decls;  // uniforms, functions, structs
  std::string body;   // statements that set `vec4 r` (0 on entry)
  std::vector<std::string> uniforms;
  V want;
  More more;
};

std::string Version(const std::string& v) { return v.empty() ? "" : "#version " + v + "\n"; }

void Add(std::vector<GlslCase>* out, const Expr& e) {
  for (uint8_t stage : {kVertex, kFragment}) {
    if (!(e.more.stages & stage)) continue;
    GlslCase c;
    c.spec = e.spec;
    c.uniforms = e.uniforms;
    c.textures = e.more.textures;
    c.make_textures = e.more.make_textures;
    c.state = e.more.state;
    c.vulkan_refusal = e.more.vulkan_refusal;
    GlslExpect x = Eq("", e.want);
    x.tolerance = e.more.tolerance;
    x.bound = e.more.bound;
    if (stage == kVertex) {
      c.name = e.name + "_vs";
      c.vertex = Version(e.more.version) + e.decls + "varying vec4 v;\nvoid main() {\n" +
                 "  gl_Position = gl_Vertex;\n  vec4 r = vec4(0.0);\n" + e.body + "\n  v = r;\n}\n";
      x.name = "v";
    } else {
      c.name = e.name + "_fs";
      c.fragment = Version(e.more.version) + e.decls + "void main() {\n  vec4 r = vec4(0.0);\n" +
                   e.body + "\n  gl_FragColor = r;\n}\n";
      x.name = "gl_FragColor";
    }
    c.expects.push_back(std::move(x));
    out->push_back(std::move(c));
  }
}

void Add(std::vector<GlslCase>* out, std::string name, std::string spec, std::string decls,
         std::string body, std::vector<std::string> uniforms, V want, More more = More()) {
  Add(out, Expr{std::move(name), std::move(spec), std::move(decls), std::move(body),
                std::move(uniforms), std::move(want), std::move(more)});
}

// A cube map of 1x1 faces, face f (+X -X +Y -Y +Z -Z) holding (f + 1, 0, 0, 1).
void CubeFaces(std::map<int, arbvp::Texture>& textures) {
  arbvp::Texture t;
  t.dim = arbvp::TexDim::Cube;
  t.depth = 6;
  for (int f = 0; f < 6; ++f) t.texels.insert(t.texels.end(), {float(f + 1), 0, 0, 1});
  textures[0] = t;
}

// A 2x1 comparing depth texture (depths 0.25, 0.75, LEQUAL) whose GL_DEPTH_TEXTURE_MODE is
// ALPHA: a shadow lookup's result r reads (0, 0, 0, r) (GL 2.0 section 3.8.14).
void AlphaDepth(std::map<int, arbvp::Texture>& textures) {
  arbvp::Texture t;
  t.width = 2;
  t.texels = {0.25f, 0, 0, 1, 0.75f, 0, 0, 1};
  t.depth_texture = true;
  t.compare = true;
  t.depth_mode = arbvp::DepthMode::Alpha;
  textures[0] = t;
}

// 8.1 Angle and trigonometry functions.
void AngleAndTrigonometry(std::vector<GlslCase>* c) {
  const std::string a = "uniform vec4 a;\n";
  const std::string ab = "uniform vec4 a, b;\n";
  // radians = pi / 180 * degrees: a product with an inexact constant.
  Add(c, "radians", "8.1 radians", a, "r = radians(a);", {"a=180,90,-45,0"}, {kPi, kPi2, -kPi4, 0},
      Approx());
  Add(c, "degrees", "8.1 degrees", a, "r = degrees(a);", {"a=3.14159265,1.57079633,-0.5,0"},
      {180, 90, -28.6478898f, 0}, Approx());
  Add(c, "sin", "8.1 sin", a, "r = sin(a);", {"a=0.523598776,1.57079633,-0.523598776,0"},
      {0.5f, 1, -0.5f, 0}, More().Tol(Tolerance::Absolute, kTrigBound));
  Add(c, "cos", "8.1 cos", a, "r = cos(a);", {"a=0,1.04719755,3.14159265,1.57079633"},
      {1, 0.5f, -1, 0}, More().Tol(Tolerance::Absolute, kTrigBound));
  // tan(atan(0.5)) = 0.5.
  Add(c, "tan", "8.1 tan", a, "r = tan(a);", {"a=0.785398163,-0.785398163,0,0.463647609"},
      {1, -1, 0, 0.5f}, More().Tol(Tolerance::Absolute, kTrigBound));
  Add(c, "asin", "8.1 asin", a, "r = asin(a);", {"a=0.5,-1,0,1"}, {kPi6, -kPi2, 0, kPi2},
      More().Tol(Tolerance::Absolute, kInverseTrigBound));
  Add(c, "acos", "8.1 acos", a, "r = acos(a);", {"a=0.5,-1,1,0"}, {kPi3, kPi, 0, kPi2},
      More().Tol(Tolerance::Absolute, kInverseTrigBound));
  // atan(y, x): the angle of (x, y), in [-pi, pi]; x = 0 with y != 0 is defined.
  Add(c, "atan2", "8.1 atan(y, x)", ab, "r = atan(a, b);", {"a=1,1,-1,2", "b=1,-1,-1,0"},
      {kPi4, 3 * kPi4, -3 * kPi4, kPi2}, More().Tol(Tolerance::Absolute, kInverseTrigBound));
  Add(c, "atan", "8.1 atan(y_over_x)", a, "r = atan(a);", {"a=1,-1,0,0.5"},
      {kPi4, -kPi4, 0, 0.463647609f}, More().Tol(Tolerance::Absolute, kInverseTrigBound));
}

// 8.2 Exponential functions: all approximated (Relative, GL's 1 part in 10^5).
void Exponential(std::vector<GlslCase>* c) {
  const std::string a = "uniform vec4 a;\n";
  const Tolerance rel = Tolerance::Relative;
  // pow(x, y) = x^y, defined for x > 0 (and x = 0 with y > 0).
  Add(c, "pow", "8.2 pow", "uniform vec4 a, b;\n", "r = pow(a, b);",
      {"a=2,4,9,0.25", "b=10,0.5,1.5,-1"}, {1024, 2, 27, 4}, More().Tol(rel, kGlPrecision));
  Add(c, "exp", "8.2 exp", a, "r = exp(a);", {"a=0,1,-1,2"},
      {1, 2.71828183f, 0.367879441f, 7.3890561f}, More().Tol(rel, kGlPrecision));
  Add(c, "log", "8.2 log", a, "r = log(a);", {"a=2.71828183,7.3890561,0.5,10"},
      {1, 2, -0.693147181f, 2.30258509f}, More().Tol(rel, kGlPrecision));
  Add(c, "exp2", "8.2 exp2", a, "r = exp2(a);", {"a=3,-2,0.5,10"}, {8, 0.25f, 1.41421356f, 1024},
      More().Tol(rel, kGlPrecision));
  Add(c, "log2", "8.2 log2", a, "r = log2(a);", {"a=8,0.25,1024,3"}, {3, -2, 10, 1.5849625f},
      More().Tol(rel, kGlPrecision));
  Add(c, "sqrt", "8.2 sqrt", a, "r = sqrt(a);", {"a=4,2,0.25,10000"}, {2, 1.41421356f, 0.5f, 100},
      More().Tol(rel, kGlPrecision));
  Add(c, "inversesqrt", "8.2 inversesqrt", a, "r = inversesqrt(a);", {"a=4,0.25,2,100"},
      {0.5f, 2, 0.707106781f, 0.1f}, More().Tol(rel, kGlPrecision));
}

// 8.3 Common functions: defined exactly on representable values (Exact).
void Common(std::vector<GlslCase>* c) {
  const std::string a = "uniform vec4 a;\n";
  const std::string ab = "uniform vec4 a, b;\n";
  const std::string abc = "uniform vec4 a, b, c;\n";
  Add(c, "abs", "8.3 abs", a, "r = abs(a);", {"a=-1.5,2,-0.25,0"}, {1.5f, 2, 0.25f, 0});
  Add(c, "sign", "8.3 sign", a, "r = sign(a);", {"a=-3,0,0.5,-0.125"}, {-1, 0, 1, -1});
  Add(c, "floor", "8.3 floor", a, "r = floor(a);", {"a=1.5,-1.5,2,-0.25"}, {1, -2, 2, -1});
  Add(c, "ceil", "8.3 ceil", a, "r = ceil(a);", {"a=1.5,-1.5,2,-0.25"}, {2, -1, 2, 0});
  // fract(x) = x - floor(x).
  Add(c, "fract", "8.3 fract", a, "r = fract(a);", {"a=1.75,-1.25,3,-0.5"},
      {0.75f, 0.75f, 0, 0.5f});
  // mod(x, y) = x - y * floor(x / y): 7.5 - 2 * 3; -1.5 - 2 * -1; 5 - -3 * -2; 7 - 3 * 2
  // (7 / 3 is inexact, its floor is not).
  Add(c, "mod", "8.3 mod", ab, "r = mod(a, b);", {"a=7.5,-1.5,5,7", "b=2,2,-3,3"},
      {1.5f, 0.5f, -1, 1});
  Add(c, "mod_scalar", "8.3 mod(genType, float)", "uniform vec4 a;\nuniform float s;\n",
      "r = mod(a, s);", {"a=9,-1,4.5,3", "s=4"}, {1, 3, 0.5f, 3});
  Add(c, "min", "8.3 min", ab, "r = min(a, b);", {"a=1,-2,3,0.5", "b=2,-3,3,0.25"},
      {1, -3, 3, 0.25f});
  Add(c, "max", "8.3 max", ab, "r = max(a, b);", {"a=1,-2,3,0.5", "b=2,-3,3,0.25"},
      {2, -2, 3, 0.5f});
  Add(c, "min_max_scalar", "8.3 min, max (genType, float)", "uniform vec4 a;\nuniform float s;\n",
      "r = vec4(min(a.xy, s), max(a.zw, s));", {"a=1,-2,3,0.25", "s=0.5"}, {0.5f, -2, 3, 0.5f});
  // clamp(x, lo, hi) = min(max(x, lo), hi).
  Add(c, "clamp", "8.3 clamp", abc, "r = clamp(a, b, c);",
      {"a=-1,0.5,2,0.75", "b=0,0,0,0.8", "c=1,1,1,1"}, {0, 0.5f, 1, 0.8f});
  Add(c, "clamp_scalar", "8.3 clamp(genType, float, float)",
      "uniform vec4 a;\nuniform float s, t;\n", "r = clamp(a, s, t);",
      {"a=-3,0.5,4,2", "s=-1", "t=2"}, {-1, 0.5f, 2, 2});
  // mix(x, y, a) = x (1 - a) + y a: 0 .75 + 4 .25; 10 .5 + 20 .5; -4 .25 + 4 .75; 3.
  Add(c, "mix", "8.3 mix", abc, "r = mix(a, b, c);",
      {"a=0,10,-4,1", "b=4,20,4,3", "c=0.25,0.5,0.75,1"}, {1, 15, 2, 3});
  Add(c, "mix_scalar", "8.3 mix(genType, genType, float)", "uniform vec4 a, b;\nuniform float s;\n",
      "r = mix(a, b, s);", {"a=0,4,8,-8", "b=4,8,0,8", "s=0.25"}, {1, 5, 6, -4});
  // step(edge, x) = x < edge ? 0 : 1.
  Add(c, "step", "8.3 step", ab, "r = step(a, b);", {"a=1,1,1,0", "b=0.5,1,2,0"}, {0, 1, 1, 1});
  Add(c, "step_scalar", "8.3 step(float, genType)", "uniform vec4 a;\nuniform float s;\n",
      "r = step(s, a);", {"a=1,2,3,-5", "s=2"}, {0, 1, 1, 0});
  // smoothstep: t = clamp((x - e0) / (e1 - e0), 0, 1), t * t * (3 - 2 t). The division makes
  // it approximate (Relative): t = .5, 0, 1, .25 give .5, 0, 1, .15625.
  Add(c, "smoothstep", "8.3 smoothstep", "uniform vec4 a;\nuniform float s, t;\n",
      "r = smoothstep(s, t, a);", {"a=1,-1,3,0.5", "s=0", "t=2"}, {0.5f, 0, 1, 0.15625f}, Approx());
  // t = .25, .5, .5, .75.
  Add(c, "smoothstep_vec", "8.3 smoothstep(genType, genType, genType)", abc,
      "r = smoothstep(a, b, c);", {"a=0,1,-1,2", "b=4,3,1,6", "c=1,2,0,5"},
      {0.15625f, 0.5f, 0.5f, 0.84375f}, Approx());
}

// 8.4 Geometric functions.
void Geometric(std::vector<GlslCase>* c) {
  const std::string ab = "uniform vec4 a, b;\n";
  const std::string abc = "uniform vec4 a, b, c;\n";
  // length: a square root (Relative). |(2,3,6)| = 7, |(3,4)| = 5, |-2| = 2, |(1,1,1,1)| = 2.
  Add(c, "length", "8.4 length", ab,
      "r = vec4(length(a.xyz), length(b.xy), length(b.z), length(vec4(b.w)));",
      {"a=2,3,6,0", "b=3,4,-2,1"}, {7, 5, 2, 2}, Approx());
  Add(c, "distance", "8.4 distance", ab,
      "r = vec4(distance(a.xyz, b.xyz), distance(a.xy, b.xy), distance(a.w, b.w), 1.0);",
      {"a=1,2,3,1", "b=4,6,3,4"}, {5, 5, 3, 1}, Approx());
  // dot: sums of products of small integers (Exact): 5 - 12 + 21 + 2; 5 - 12; 5; 14.
  Add(c, "dot", "8.4 dot", ab,
      "r = vec4(dot(a, b), dot(a.xy, b.xy), dot(a.x, b.x), dot(a.xyz, b.xyz));",
      {"a=1,2,3,4", "b=5,-6,7,0.5"}, {16, -7, 5, 14});
  // cross: (2*6 - 3*5, 3*4 - 1*6, 1*5 - 2*4).
  Add(c, "cross", "8.4 cross", ab, "r = vec4(cross(a.xyz, b.xyz), 1.0);",
      {"a=1,2,3,0", "b=4,5,6,0"}, {-3, 6, -3, 1});
  // normalize(x) = x / length(x): (0, 3, 0, 4) / 5.
  Add(c, "normalize", "8.4 normalize", "uniform vec4 a;\n", "r = normalize(a);", {"a=0,3,0,4"},
      {0, 0.6f, 0, 0.8f}, Approx());
  // faceforward(N, I, Nref) = dot(Nref, I) < 0 ? N : -N.
  Add(c, "faceforward", "8.4 faceforward", abc,
      "r = vec4(faceforward(a.xyz, b.xyz, c.xyz), faceforward(a.w, b.w, c.w));",
      {"a=1,2,3,5", "b=0,0,1,1", "c=0,1,1,-1"}, {-1, -2, -3, 5});
  // reflect(I, N) = I - 2 dot(N, I) N: (1,-1,0) about (0,1,0) is (1,1,0); 3 about 1 is -3.
  Add(c, "reflect", "8.4 reflect", ab, "r = vec4(reflect(a.xyz, b.xyz), reflect(a.w, b.w));",
      {"a=1,-1,0,3", "b=0,1,0,1"}, {1, 1, 0, -3});
  // refract(I, N, eta): k = 1 - eta^2 (1 - dot(N, I)^2); k < 0 gives 0, else
  // eta I - (eta dot(N, I) + sqrt(k)) N. I = (.6, -.8, 0), N = (0, 1, 0): eta .5 gives
  // k = .91 and (.3, -.4 - (-.4 + sqrt(.91)), 0) = (.3, -.953939, 0); eta 2 gives k = -.44
  // (total internal reflection): 0. The square root makes it approximate (Relative).
  Add(c, "refract", "8.4 refract", "uniform vec4 a, b;\nuniform float s, t;\n",
      "r = vec4(refract(a.xyz, b.xyz, s).xy, refract(a.xyz, b.xyz, t).xy);",
      {"a=0.6,-0.8,0,0", "b=0,1,0,0", "s=0.5", "t=2"}, {0.3f, -0.953939201f, 0, 0}, Approx());
}

// 8.5 Matrix functions and 5.11 matrix operators: sums of products of small integers (Exact).
// Matrices are given column by column, as GLSL's constructors take them.
void Matrices(std::vector<GlslCase>* c) {
  const std::string mn = "uniform mat2 m, n;\n";
  // matrixCompMult: component by component: (1*5, 2*6, 3*7, 4*8).
  Add(c, "matrix_comp_mult", "8.5 matrixCompMult", mn,
      "mat2 p = matrixCompMult(m, n);\nr = vec4(p[0], p[1]);", {"m=1,2,3,4", "n=5,6,7,8"},
      {5, 12, 21, 32});
  // outerProduct(c, r): column i is c * r[i]: (3, 6), (4, 8).
  Add(c, "outer_product", "8.5 outerProduct (1.20)", "uniform vec2 p, q;\n",
      "mat2 o = outerProduct(p, q);\nr = vec4(o[0], o[1]);", {"p=1,2", "q=3,4"}, {3, 6, 4, 8},
      More().Version("120"));
  // transpose: mat3 columns (1,2,3) (4,5,6) (7,8,9) become rows.
  Add(c, "transpose", "8.5 transpose (1.20)", "uniform mat3 m;\n",
      "mat3 t = transpose(m);\nr = vec4(t[0], t[2].x);", {"m=1,2,3,4,5,6,7,8,9"}, {1, 4, 7, 3},
      More().Version("120"));
  // matrix * vector: the columns weighted by the vector: 1 (1,2,3) + 2 (7,8,9).
  Add(c, "matrix_times_vector", "5.11 matrix * vector", "uniform mat3 m;\nuniform vec3 u;\n",
      "r = vec4(m * u, 1.0);", {"m=1,2,3,4,5,6,7,8,9", "u=1,0,2"}, {15, 18, 21, 1});
  // vector * matrix: dot products with the columns: (1+6, 4+12, 7+18).
  Add(c, "vector_times_matrix", "5.11 vector * matrix", "uniform mat3 m;\nuniform vec3 u;\n",
      "r = vec4(u * m, 1.0);", {"m=1,2,3,4,5,6,7,8,9", "u=1,0,2"}, {7, 16, 25, 1});
  // matrix * matrix: column j of m * n is m * n[j]: 5 (1,2) + 6 (3,4); 7 (1,2) + 8 (3,4).
  Add(c, "matrix_times_matrix", "5.11 matrix * matrix", mn,
      "mat2 p = m * n;\nr = vec4(p[0], p[1]);", {"m=1,2,3,4", "n=5,6,7,8"}, {23, 34, 31, 46});
  // + and * by a scalar are component-wise.
  Add(c, "matrix_componentwise", "5.9 matrix + matrix, matrix * scalar", mn,
      "r = vec4((m + n)[0], (m * 3.0)[1]);", {"m=1,2,3,4", "n=5,6,7,8"}, {6, 8, 9, 12});
  // m[1][0]: column 1, row 0; *= by a matrix multiplies on the right.
  Add(c, "matrix_index_and_assign", "5.6 matrix indexing, 5.8 *=", mn,
      "mat2 p = m;\np *= n;\nr = vec4(m[1][0], m[0].y, p[1]);", {"m=1,2,3,4", "n=5,6,7,8"},
      {3, 2, 31, 46});
  // A non-square matrix (1.20): mat2x3 * vec2 = 1 (1,2,3) + 2 (4,5,6).
  Add(c, "matrix_nonsquare", "4.1.6 mat2x3 (1.20)", "uniform mat2x3 m;\nuniform vec2 u;\n",
      "r = vec4(m * u, 1.0);", {"m=1,2,3,4,5,6", "u=1,2"}, {9, 12, 15, 1}, More().Version("120"));
  // mat2(mat4) takes the upper-left 2x2 (1.20: matrices from matrices); mat3(s) is s on the
  // diagonal.
  Add(c, "matrix_from_matrix", "5.4.2 matrix constructors (1.20)",
      "uniform mat4 m;\nuniform float s;\n",
      "mat2 p = mat2(m);\nmat3 d = mat3(s);\nr = vec4(p[0], p[1].y, d[1].y + d[1].x);",
      {"m=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16", "s=2.5"}, {1, 2, 6, 2.5f},
      More().Version("120"));
}

// 8.6 Vector relational functions: exact comparisons.
void Relational(std::vector<GlslCase>* c) {
  const std::string ab = "uniform vec4 a, b;\n";
  const std::vector<std::string> in = {"a=1,2,3,4", "b=2,2,2,5"};
  Add(c, "less_than", "8.6 lessThan", ab, "r = vec4(lessThan(a, b));", in, {1, 0, 0, 1});
  Add(c, "less_than_equal", "8.6 lessThanEqual", ab, "r = vec4(lessThanEqual(a, b));", in,
      {1, 1, 0, 1});
  Add(c, "greater_than", "8.6 greaterThan", ab, "r = vec4(greaterThan(a, b));", in, {0, 0, 1, 0});
  Add(c, "greater_than_equal", "8.6 greaterThanEqual", ab, "r = vec4(greaterThanEqual(a, b));", in,
      {0, 1, 1, 0});
  Add(c, "equal", "8.6 equal", ab, "r = vec4(equal(a, b));", in, {0, 1, 0, 0});
  Add(c, "not_equal", "8.6 notEqual", ab, "r = vec4(notEqual(a, b));", in, {1, 0, 1, 1});
  Add(c, "relational_ivec", "8.6 lessThan, equal on ivec", "uniform ivec3 i, j;\n",
      "r = vec4(vec3(lessThan(i, j)), float(equal(i, j).z));", {"i=1,5,-2", "j=2,5,-2"},
      {1, 0, 0, 1});
  // any, all, not on bvec4(true, false, true, true).
  Add(c, "any_all_not", "8.6 any, all, not", "uniform bvec4 f;\n",
      "r = vec4(float(any(f)), float(all(f)), float(all(f.zw)), float(not(f).y));", {"f=1,0,1,1"},
      {1, 0, 1, 1});
}

// 8.7 Texture lookups, on nearest-filtered textures whose texels are exact: "gradient" holds
// each texel's centre ((i + 0.5) / size) in r, g, b; "depth-gradient-compare" a depth of the
// s centre compared with LEQUAL (1 when r <= depth), read as luminance (L, L, L, 1).
void Textures(std::vector<GlslCase>* c) {
  // A 1D texture of 4: s = .3 is texel 1 (centre .375); g and b are the centres of the one
  // row and slice (.5).
  Add(c, "texture1d", "8.7 texture1D", "uniform sampler1D t;\nuniform float s;\n",
      "r = texture1D(t, s);", {"t=0", "s=0.3"}, {0.375f, 0.5f, 0.5f, 1},
      More().Textures({"0=1d:gradient:4x1"}));
  // 4x2: (.6, .2) is texel (2, 0).
  Add(c, "texture2d", "8.7 texture2D", "uniform sampler2D t;\nuniform vec2 u;\n",
      "r = texture2D(t, u);", {"t=0", "u=0.6,0.2"}, {0.625f, 0.25f, 0.5f, 1},
      More().Textures({"0=2d:gradient:4x2"}));
  // The texture is on unit 3, the sampler says so.
  Add(c, "texture2d_unit", "8.7 texture2D, a sampler on unit 3",
      "uniform sampler2D t;\nuniform vec2 u;\n", "r = texture2D(t, u);", {"t=3", "u=0.9,0.9"},
      {0.875f, 0.75f, 0.5f, 1}, More().Textures({"3=2d:gradient:4x2"}));
  // A bias (fragment shaders only) selects among levels: with one level, the same texel.
  Add(c, "texture2d_bias", "8.7 texture2D with bias", "uniform sampler2D t;\nuniform vec2 u;\n",
      "r = texture2D(t, u, 1.0);", {"t=0", "u=0.6,0.2"}, {0.625f, 0.25f, 0.5f, 1},
      More().Stages(kFragment).Textures({"0=2d:gradient:4x2"}));
  // 2x2x2: (.7, .2, .8) is texel (1, 0, 1).
  Add(c, "texture3d", "8.7 texture3D", "uniform sampler3D t;\nuniform vec3 u;\n",
      "r = texture3D(t, u);", {"t=0", "u=0.7,0.2,0.8"}, {0.75f, 0.25f, 0.75f, 1},
      More().Textures({"0=3d:gradient:2x2x2"}));
  // The face of the largest magnitude component: +X (1), -Y (4), -Z (6) (GL 2.0 3.8.6).
  Add(c, "texture_cube", "8.7 textureCube", "uniform samplerCube t;\nuniform vec4 a, b, c;\n",
      "r = vec4(textureCube(t, a.xyz).x, textureCube(t, b.xyz).x,\n"
      "         textureCube(t, c.xyz).x, 0.0);",
      {"t=0", "a=1,0.2,0.3,0", "b=0.1,-2,0.5,0", "c=0.1,0.2,-3,0"}, {1, 4, 6, 0},
      More().MakeTextures(CubeFaces));
  // Proj: the coordinates divided by the last component (2: exact).
  Add(c, "texture1d_proj", "8.7 texture1DProj", "uniform sampler1D t;\nuniform vec4 u;\n",
      "r = vec4(texture1DProj(t, u.xy).x, texture1DProj(t, u).x, 0.0, 0.0);",
      {"t=0", "u=0.6,2,0,4"}, {0.375f, 0.125f, 0, 0}, More().Textures({"0=1d:gradient:4x1"}));
  // (1.2, .4) / 2 = (.6, .2): texel (2, 0); (1.2, .4, -, 4) / 4 = (.3, .1): texel (1, 0).
  Add(c, "texture2d_proj", "8.7 texture2DProj", "uniform sampler2D t;\nuniform vec4 u;\n",
      "r = vec4(texture2DProj(t, u.xyz).xy, texture2DProj(t, vec4(u.xy, 0.0, 4.0)).xy);",
      {"t=0", "u=1.2,0.4,2,0"}, {0.625f, 0.25f, 0.375f, 0.25f},
      More().Textures({"0=2d:gradient:4x2"}));
  Add(c, "texture3d_proj", "8.7 texture3DProj", "uniform sampler3D t;\nuniform vec4 u;\n",
      "r = texture3DProj(t, u);", {"t=0", "u=1.4,0.4,1.6,2"}, {0.75f, 0.25f, 0.75f, 1},
      More().Textures({"0=3d:gradient:2x2x2"}));
  // shadow1D(t, (s, -, r)): depth .625 at s = .6; r = .5 passes, r = .75 fails.
  Add(c, "shadow1d", "8.7 shadow1D", "uniform sampler1DShadow t;\nuniform vec2 u;\n",
      "r = vec4(shadow1D(t, vec3(0.6, 0.0, u.x)).xw, shadow1D(t, vec3(0.6, 0.0, u.y)).xw);",
      {"t=0", "u=0.5,0.75"}, {1, 1, 0, 1}, More().Textures({"0=1d:depth-gradient-compare:4x1"}));
  // shadow2D: depth .625 at s = .6 and .125 at s = .1; r = .5.
  Add(c, "shadow2d", "8.7 shadow2D", "uniform sampler2DShadow t;\nuniform vec2 u;\n",
      "r = vec4(shadow2D(t, vec3(u.x, 0.2, 0.5)).xy, shadow2D(t, vec3(u.y, 0.2, 0.5)).xw);",
      {"t=0", "u=0.6,0.1"}, {1, 1, 0, 1}, More().Textures({"0=2d:depth-gradient-compare:4x2"}));
  // Under ALPHA: r = 0.5 <= 0.75 at s = .75 passes: (0, 0, 0, 1); <= 0.25 at s = .25 fails.
  Add(c, "shadow2d_alpha", "8.7 shadow2D; GL 2.0 3.8.14 DEPTH_TEXTURE_MODE",
      "uniform sampler2DShadow t;\nuniform vec2 u;\n",
      "r = shadow2D(t, vec3(u.x, 0.5, 0.5)) + shadow2D(t, vec3(u.y, 0.5, 0.5)) * 2.0;",
      {"t=0", "u=0.75,0.25"}, {0, 0, 0, 1}, More().MakeTextures(AlphaDepth));
  // shadow2DProj: (1.2, .4, 1, 2) / 2 = (.6, .2, .5): passes; r = 1.6 / 2 = .8 fails.
  Add(c, "shadow2d_proj", "8.7 shadow2DProj", "uniform sampler2DShadow t;\nuniform vec4 u;\n",
      "r = vec4(shadow2DProj(t, u).x, shadow2DProj(t, vec4(u.xy, 1.6, u.w)).x, 0.0, 0.0);",
      {"t=0", "u=1.2,0.4,1,2"}, {1, 0, 0, 0}, More().Textures({"0=2d:depth-gradient-compare:4x2"}));
  // The Lod forms (vertex shaders only): one level, so the lod changes nothing.
  Add(c, "texture2d_lod", "8.7 texture2DLod", "uniform sampler2D t;\nuniform vec2 u;\n",
      "r = texture2DLod(t, u, 0.0);", {"t=0", "u=0.6,0.2"}, {0.625f, 0.25f, 0.5f, 1},
      More().Stages(kVertex).Textures({"0=2d:gradient:4x2"}));
  Add(c, "texture_proj_lod", "8.7 texture2DProjLod, texture1DLod",
      "uniform sampler2D t;\nuniform sampler1D w;\nuniform vec4 u;\n",
      "r = vec4(texture2DProjLod(t, u.xyz, 0.0).xy, texture1DLod(w, u.w, 0.0).xy);",
      {"t=0", "w=1", "u=1.2,0.4,2,0.9"}, {0.625f, 0.25f, 0.875f, 0.5f},
      More().Stages(kVertex).Textures({"0=2d:gradient:4x2", "1=1d:gradient:4x1"}));
  Add(c, "texture_cube_lod", "8.7 textureCubeLod", "uniform samplerCube t;\nuniform vec3 u;\n",
      "r = textureCubeLod(t, u, 0.0);", {"t=0", "u=-5,1,2"}, {2, 0, 0, 1},
      More().Stages(kVertex).MakeTextures(CubeFaces));
  Add(c, "shadow2d_lod", "8.7 shadow2DLod, texture3DLod",
      "uniform sampler2DShadow t;\nuniform sampler3D w;\nuniform vec3 u;\n",
      "r = vec4(shadow2DLod(t, u, 0.0).x, texture3DLod(w, u, 0.0).xyz);",
      {"t=0", "w=1", "u=0.6,0.2,0.3"}, {1, 0.75f, 0.25f, 0.25f},
      More().Stages(kVertex).Textures({"0=2d:depth-gradient-compare:4x2", "1=3d:gradient:2x2x2"}));
  // shadow1DProj: (1.2, -, 1, 2) / 2 = (.6, -, .5): depth .625 passes; r = 1.6 / 2 = .8 fails.
  Add(c, "shadow1d_proj", "8.7 shadow1DProj", "uniform sampler1DShadow t;\nuniform vec4 u;\n",
      "r = vec4(shadow1DProj(t, u).x, shadow1DProj(t, vec4(u.xy, 1.6, u.w)).x, 0.0, 0.0);",
      {"t=0", "u=1.2,0,1,2"}, {1, 0, 0, 0}, More().Textures({"0=1d:depth-gradient-compare:4x1"}));
  // The other Lod forms: 1.2 / 2 = .6 (texel 2 of 4); (1.4, .4, 1.6) / 2 = (.7, .2, .8);
  // depth .625 at s = .6 against r = .5; (1.2, .4, 1) / 2 = (.6, .2, .5).
  Add(c, "proj_lod_forms", "8.7 texture1DProjLod, texture3DProjLod, shadow1DLod, shadow2DProjLod",
      "uniform sampler1DShadow t1;\nuniform sampler2DShadow t2;\nuniform sampler1D w1;\n"
      "uniform sampler3D w3;\nuniform vec4 u;\n",
      "r = vec4(texture1DProjLod(w1, u.xw, 0.0).x,\n"
      "         texture3DProjLod(w3, vec4(1.4, u.y, 1.6, u.w), 0.0).x,\n"
      "         shadow1DLod(t1, vec3(0.6, 0.0, 0.5), 0.0).x, shadow2DProjLod(t2, u, 0.0).x);",
      {"t1=0", "t2=1", "w1=2", "w3=3", "u=1.2,0.4,1,2"}, {0.625f, 0.75f, 1, 1},
      More().Stages(kVertex).Textures({"0=1d:depth-gradient-compare:4x1",
                                       "1=2d:depth-gradient-compare:4x2", "2=1d:gradient:4x1",
                                       "3=3d:gradient:2x2x2"}));
  // Linear filtering: at s = .375 of a 2-texel row, u = s * 2 - .5 = .25 between texels 0
  // (.25) and 1 (.75): .75 * .25 + .25 * .75 = .375. GL 2.0 3.8.8 leaves the weights'
  // precision to the implementation (Relative).
  Add(c, "texture_linear", "8.7 texture2D, GL 2.0 3.8.8 LINEAR",
      "uniform sampler2D t;\nuniform vec2 u;\n", "r = texture2D(t, u);", {"t=0", "u=0.375,0.5"},
      {0.375f, 0.5f, 0.5f, 1}, Approx().Textures({"0=2d:gradient:2x1:linear:clamp"}));
}

// 5 Operators and expressions: arithmetic on representable values (Exact).
void Operators(std::vector<GlslCase>* c) {
  const std::string ab = "uniform vec4 a, b;\n";
  // a / b by -2: exact.
  Add(c, "arithmetic", "5.9 + - * /", ab, "r = vec4(a.x + b.x, a.y - b.y, a.z * b.z, a.w / b.w);",
      {"a=1.5,2,-3,8", "b=0.5,4,2,-2"}, {2, -2, -6, -4});
  Add(c, "unary", "5.9 unary - and +", ab, "r = -a + (+b);", {"a=1,-2,3,0.5", "b=4,4,4,4"},
      {3, 6, 1, 3.5f});
  // Integer division of positive operands drops the fraction (5.9); 1.20 ints are exact.
  Add(c, "int_arithmetic", "5.9 on int", "uniform ivec4 i, j;\n",
      "ivec4 k = ivec4(i.x + j.x, i.y - j.y, i.z * j.z, i.w / j.w);\nr = vec4(k);",
      {"i=7,-7,3,9", "j=2,2,-2,4"}, {9, -9, -6, 2});
  // Pre-increment yields the new value, post-increment the old one (5.9).
  Add(c, "increment_decrement", "5.9 ++ --", "uniform float s;\n",
      "float x = s;\nfloat y = x++;\nfloat z = ++x;\nfloat w = x--;\n--x;\n"
      "r = vec4(y, z, w, x);",
      {"s=1"}, {1, 3, 3, 1});
  Add(c, "increment_vector_int", "5.9 ++ -- on ivec and components", "uniform ivec2 i;\n",
      "ivec2 k = i;\nk++;\nvec4 q = vec4(1.0);\nq.y++;\n--q.zw;\nr = vec4(vec2(k), q.y, q.z);",
      {"i=4,-1"}, {5, 0, 2, 0});
  // Compound assignments: a op= b is a = a op b.
  Add(c, "compound_assignment", "5.8 += -= *= /=", ab,
      "vec4 x = a;\nx += b;\nx.y -= 1.0;\nx *= vec4(2.0, 1.0, 0.5, 1.0);\nx.w /= 4.0;\n"
      "r = x;",
      {"a=1,2,3,4", "b=1,1,1,4"}, {4, 2, 2, 2});
  // ?: with scalar and vector operands (1.20 allows vectors as the second and third).
  Add(c, "ternary", "5.10 ?:", ab,
      "r.x = a.x > 0.0 ? b.x : b.y;\nr.y = a.y > 0.0 ? b.x : (a.z > 0.0 ? b.z : b.w);\n"
      "r.zw = a.w < 0.0 ? b.zw : b.xy;",
      {"a=1,-1,-1,-2", "b=5,6,7,8"}, {5, 8, 7, 8}, More().Version("120"));
  // && || ^^ ! on bools.
  Add(c, "logical", "5.9 && || ^^ !", "uniform bool p, q;\n",
      "r = vec4(float(p && q), float(p || q), float(p ^^ q), float(!q));", {"p=1", "q=0"},
      {0, 1, 1, 1});
  // && and || do not evaluate their right operand when the left decides (5.9).
  Add(c, "short_circuit", "5.9 && || short-circuit",
      "uniform bool p, q;\nfloat calls = 0.0;\nbool Count() { calls += 1.0; return true; }\n",
      "bool x = q && Count();\nbool y = p || Count();\nbool z = p && Count();\n"
      "bool w = q || Count();\nr = vec4(float(x), float(y), float(z && w), calls);",
      {"p=1", "q=0"}, {0, 1, 1, 2});
  // Swizzles read any order and repeat (5.5); written ones must not repeat.
  Add(c, "swizzle_read", "5.5 swizzles", "uniform vec4 a;\n",
      "r = a.wzyx + a.xxyy * a.rgba - a.stpq.qqqq;", {"a=1,2,3,4"},
      {4 + 1 - 4, 3 + 2 - 4, 2 + 6 - 4, 1 + 8 - 4});
  Add(c, "swizzle_write", "5.5 swizzles as l-values", "uniform vec4 a;\n",
      "r.zx = a.xy;\nr.wy = a.zz * 2.0;\nr.x += a.w;", {"a=1,2,3,4"}, {6, 6, 1, 6});
  // Scalar relational and equality operators (5.9); == on vectors and structures compares
  // every component.
  Add(c, "comparison", "5.9 < <= > >= == !=", "uniform vec4 a;\n",
      "r = vec4(float(a.x < a.y) + float(a.y <= a.y) * 2.0,\n"
      "         float(a.z > a.w) + float(a.w >= a.z) * 2.0,\n"
      "         float(a.xy == vec2(1.0, 2.0)), float(a != vec4(1.0, 2.0, 3.0, 4.0)));",
      {"a=1,2,3,4"}, {3, 2, 1, 0});
  // Component-wise vector * vector, scalar * vector.
  Add(c, "componentwise", "5.9 vector op vector, scalar op vector", "uniform vec4 a, b;\n",
      "r = a * b + 2.0 * a - b / 4.0;", {"a=1,2,3,4", "b=4,8,-4,0"}, {5, 18, -5, 8});
  // The sequence operator yields its right operand after evaluating the left (5.9).
  Add(c, "sequence", "5.9 ,", "uniform float s;\n",
      "float x = s;\nfloat y = (x += 1.0, x * 2.0);\nr = vec4(x, y, 0.0, 0.0);", {"s=3"},
      {4, 8, 0, 0});
}

// 5.4 Constructors and conversions.
void Conversions(std::vector<GlslCase>* c) {
  // int(float) drops the fraction (toward 0); bool(x) is x != 0; float(bool) 0 or 1.
  Add(c, "float_to_int", "5.4.1 int(float)", "uniform vec4 a;\n",
      "r = vec4(float(int(a.x)), float(int(a.y)), vec2(ivec2(a.zw)));", {"a=-1.75,2.9,0.5,-3"},
      {-1, 2, 0, -3});
  Add(c, "bool_conversions", "5.4.1 bool(float), bool(int), float(bool), int(bool)",
      "uniform vec4 a;\nuniform int i;\n",
      "r = vec4(float(bool(a.x)), float(bool(a.y)), float(bool(i)), float(int(bool(a.z))));",
      {"a=0,-0.5,2,0", "i=3"}, {0, 1, 1, 1});
  Add(c, "int_to_float", "5.4.1 float(int), vec(ivec)", "uniform ivec4 i;\n",
      "r = vec4(i) * 0.5 + vec4(float(i.x));", {"i=3,-4,5,0"}, {4.5f, 1, 5.5f, 3});
  // Constructors fill in order, replicate a scalar, drop extra components (5.4.2).
  Add(c, "vector_constructors", "5.4.2 vector constructors", "uniform vec4 a;\n",
      "vec2 p = vec2(a);\nvec3 q = vec3(a.w);\nr = vec4(p, q.x, 1.0) + vec4(vec3(a.zw, a.y), "
      "0.0);",
      {"a=1,2,3,4"}, {1 + 3, 2 + 4, 4 + 2, 1});
  // Matrix constructors: from columns, from scalars column by column, s on the diagonal.
  Add(c, "matrix_constructors", "5.4.2 matrix constructors", "uniform vec4 a;\n",
      "mat2 m = mat2(a.xy, a.zw);\nmat2 n = mat2(a.x, a.y, a.z, a.w);\nmat2 d = mat2(a.w);\n"
      "r = vec4(m[1].x, n[0].y, d[0].x, d[0].y);",
      {"a=1,2,3,4"}, {3, 2, 4, 0});
  // 1.20 converts int to float implicitly (4.1.10): in initialisers, arithmetic, arguments.
  Add(c, "implicit_int_to_float", "4.1.10 implicit conversions (1.20)",
      "uniform int i;\nuniform ivec2 j;\nfloat Half(float x) { return x * 0.5; }\n",
      "float f = i;\nvec2 g = j;\nr = vec4(f, g + 0.5, Half(i) + 1.5 * i);", {"i=3", "j=1,-2"},
      {3, 1.5f, -1.5f, 6}, More().Version("120"));
}

// 6 Statements: control flow.
void ControlFlow(std::vector<GlslCase>* c) {
  Add(c, "if_else", "6.2 if else", "uniform vec4 a;\n",
      "if (a.x > 0.0) r.x = 1.0; else r.x = 2.0;\n"
      "if (a.y > 0.0) r.y = 1.0; else if (a.z > 0.0) r.y = 3.0; else r.y = 4.0;\n"
      "if (a.w > 0.0) { r.z = 5.0; r.w = 6.0; }",
      {"a=-1,-1,1,1"}, {2, 3, 5, 6});
  // 0 + 2 + 4 + 6, then i = 7 breaks; i = 1, 3, 5 continue.
  Add(c, "for_break_continue", "6.3 for, break, continue", "uniform int n;\n",
      "float sum = 0.0;\nfloat skipped = 0.0;\n"
      "for (int i = 0; i < n; ++i) {\n"
      "  if (i > 6) break;\n  if (i == 1 || i == 3 || i == 5) { skipped += 1.0; continue; }\n"
      "  sum += float(i);\n}\nr = vec4(sum, skipped, 0.0, 0.0);",
      {"n=10"}, {12, 3, 0, 0});
  // 3, 6, 12, ..., 192 (6 doublings).
  Add(c, "while", "6.3 while", "uniform float s;\n",
      "float x = s;\nfloat k = 0.0;\nwhile (x < 100.0) { x *= 2.0; k += 1.0; }\n"
      "r = vec4(x, k, 0.0, 0.0);",
      {"s=3"}, {192, 6, 0, 0});
  // The body runs before the test: 6, 3.5, 1, -1.5 (3 runs); and once when the test fails.
  Add(c, "do_while", "6.3 do while", "uniform float s;\n",
      "float x = s;\nfloat k = 0.0;\ndo { x -= 2.5; k += 1.0; } while (x > 0.0);\n"
      "float y = -s;\nfloat once = 0.0;\ndo { once += 1.0; } while (y > 0.0);\n"
      "r = vec4(x, k, once, 0.0);",
      {"s=6"}, {-1.5f, 3, 1, 0});
  // break leaves the inner loop only: i = 0..3, j = 0..i-1 and j < 2: 0 + 1 + 2 + 2.
  Add(c, "nested_loops", "6.3 nested loops, break", "uniform int n;\n",
      "float count = 0.0;\nfor (int i = 0; i < n; ++i) {\n"
      "  for (int j = 0; j < 10; ++j) {\n    if (j >= i || j >= 2) break;\n"
      "    count += 1.0;\n  }\n}\nr = vec4(count);",
      {"n=4"}, {5, 5, 5, 5});
  // return leaves a function early (6.4).
  Add(c, "early_return_function", "6.4 return",
      "uniform vec4 a;\nfloat F(float x) {\n  if (x < 0.0) return -1.0;\n"
      "  for (int i = 0; i < 4; ++i) { if (float(i) >= x) return float(i) * 10.0; }\n"
      "  return 99.0;\n}\n",
      "r = vec4(F(a.x), F(a.y), F(a.z), F(a.w));", {"a=-2,2.5,0,7"}, {-1, 30, 0, 99});
}

// 6.1 Function definitions: parameters and overloads.
void Functions(std::vector<GlslCase>* c) {
  // in copies in, out copies out (undefined until written), inout both.
  Add(c, "parameter_qualifiers", "6.1.1 in out inout",
      "uniform vec4 a;\n"
      "void F(in float x, out float y, inout float z) { x += 1.0; y = x * 2.0; z += y; }\n",
      "float x = a.x;\nfloat y = 0.0;\nfloat z = a.y;\nF(x, y, z);\nr = vec4(x, y, z, 0.0);",
      {"a=1,10,0,0"}, {1, 4, 14, 0});
  // An out argument may be a component or a swizzle.
  Add(c, "out_swizzle", "6.1.1 out to a swizzle",
      "uniform vec4 a;\nvoid Two(out vec2 p, float s) { p = vec2(s, s * 2.0); }\n",
      "Two(r.wy, a.x);\nTwo(r.zx, a.y);", {"a=3,5,0,0"}, {10, 6, 5, 3});
  // Overloads chosen by the argument types (6.1).
  Add(c, "overloads", "6.1 overloading",
      "uniform vec4 a;\nuniform int i;\nfloat F(float x) { return x + 1.0; }\n"
      "float F(vec2 x) { return x.x * x.y; }\nfloat F(int x) { return float(x) * 10.0; }\n"
      "float F(float x, float y) { return x - y; }\n",
      "r = vec4(F(a.x), F(a.zw), F(i), F(a.z, a.w));", {"a=1,0,3,4", "i=2"}, {2, 12, 20, -1});
  // const in parameters, and structures passed by value.
  Add(c, "struct_parameter", "6.1.1 structure parameters (by value)",
      "uniform vec4 a;\nstruct S { vec2 p; float k; };\n"
      "float Scale(S s) { s.k *= 2.0; return (s.p.x + s.p.y) * s.k; }\n"
      "S Make(const in float x) { return S(vec2(x, x + 1.0), 0.5); }\n",
      "S s = Make(a.x);\nr = vec4(Scale(s), s.k, s.p);", {"a=2,0,0,0"}, {5, 0.5f, 2, 3});
}

// 4.1.8 Structures, 4.1.9 arrays, 4.3.2 const.
void StructsAndArrays(std::vector<GlslCase>* c) {
  Add(c, "struct_nested", "4.1.8 nested structures, 5.4.3 structure constructors",
      "uniform vec4 a;\nstruct A { vec2 p; float k; };\nstruct B { A a; float w; };\n",
      "B b = B(A(a.xy, a.z), a.w);\nb.a.p.y += 10.0;\nr = vec4(b.a.p, b.a.k, b.w);", {"a=1,2,3,4"},
      {1, 12, 3, 4});
  // A structure uniform's members are uniforms of their own, set by name (GL 2.0 2.15.3).
  Add(c, "struct_uniform", "4.1.8 structure uniforms",
      "struct A { vec2 p; float k; };\nstruct B { A a; float w; };\nuniform B u;\n",
      "r = vec4(u.a.p * u.a.k, u.w, 1.0);", {"u.a.p=1,2", "u.a.k=3", "u.w=4"}, {3, 6, 4, 1});
  Add(c, "struct_array_uniform", "4.1.8, 4.1.9 an array of structures",
      "struct L { vec3 pos; float k; };\nuniform L lights[2];\n",
      "r = vec4(lights[1].pos * lights[0].k, lights[1].k);",
      {"lights[0].pos=9,9,9", "lights[0].k=2", "lights[1].pos=1,2,3", "lights[1].k=5"},
      {2, 4, 6, 5});
  // == on structures compares every member; assignment copies.
  Add(c, "struct_equality",
      "5.7 structure assignment and ==", "struct A { vec2 p; float k; };\nuniform A u;\n",
      "A x = u;\nA y = u;\ny.k += 1.0;\nr = vec4(float(x == u), float(y == u), float(y != u),"
      " y.k);",
      {"u.p=1,2", "u.k=3"}, {1, 0, 1, 4});
  Add(c, "uniform_array", "4.1.9 uniform arrays", "uniform float w[4];\nuniform int i;\n",
      "r = vec4(w[0] + w[3], w[1] * w[2], w[i], w[i + 1]);", {"w=1,2,3,4", "i=1"}, {5, 6, 2, 3});
  Add(c, "uniform_vec_array", "4.1.9 uniform vec arrays", "uniform vec2 ps[3];\n",
      "r = vec4(ps[2], ps[0] + ps[1]);", {"ps=1,2,3,4,5,6"}, {5, 6, 4, 6});
  // A local array, filled in a loop and read with a computed index.
  Add(c, "local_array", "4.1.9 local arrays", "uniform int i;\n",
      "float t[4];\nfor (int k = 0; k < 4; ++k) t[k] = float(k * k);\n"
      "r = vec4(t[i], t[3 - i], t[0], t[3]);",
      {"i=1"}, {1, 4, 0, 9});
  // 1.20: array constructors, .length(), whole-array assignment (a copy).
  Add(c, "array_constructor", "4.1.9 array constructors and length() (1.20)", "uniform vec4 a;\n",
      "float x[3] = float[3](a.x, a.y, a.z);\nfloat y[3] = x;\ny[0] = 9.0;\n"
      "float z[] = float[](a.w, a.w);\n"
      "r = vec4(x[0] + y[0], float(x.length()), float(z.length()), y[2]);",
      {"a=1,2,3,4"}, {10, 3, 2, 3}, More().Version("120"));
  // 1.20: arrays as parameters (sized) and return values.
  Add(c, "array_parameter", "6.1 arrays as parameters and results (1.20)",
      "uniform vec4 a;\nfloat Sum(float v[3]) { return v[0] + v[1] + v[2]; }\n"
      "float[2] Pair(float x) { return float[2](x, -x); }\n",
      "float w[3] = float[3](a.x, a.y, a.z);\nfloat p[2] = Pair(a.w);\n"
      "r = vec4(Sum(w), p[0], p[1], 0.0);",
      {"a=1,2,3,4"}, {6, 4, -4, 0}, More().Version("120"));
  // const variables and constant expressions, built-ins included (1.20 allows them in
  // constant expressions): the array size comes from a const int.
  Add(c, "const", "4.3.2 const, 4.3.3 constant expressions",
      "uniform vec4 a;\nconst int N = 3;\nconst vec2 K = vec2(abs(-2.0), floor(1.5));\n",
      "float t[N];\nt[N - 1] = a.x;\nr = vec4(K * a.y, t[2], float(N));", {"a=5,2,0,0"},
      {4, 2, 5, 3}, More().Version("120"));
}

// More expressions: indexing, globals, bvec constructors, while with continue.
void MoreExpressions(std::vector<GlslCase>* c) {
  // 8.9 noise: the spec fixes only properties, among them the range [-1, 1] (and the same
  // value for the same input); no value is defined, so only the range is checked. SPIR-V has
  // no noise: the Vulkan engine refuses it.
  Add(c, "noise", "8.9 noise1, noise2, noise3, noise4", "uniform vec4 a;\n",
      "r = vec4(float(abs(noise1(a.x)) <= 1.0),\n"
      "         float(all(lessThanEqual(abs(noise2(a.xy)), vec2(1.0)))),\n"
      "         float(all(lessThanEqual(abs(noise3(a.xyz)), vec3(1.0)))),\n"
      "         float(all(lessThanEqual(abs(noise4(a)), vec4(1.0)))));",
      {"a=0.3,1.7,-2.2,5.1"}, {1, 1, 1, 1}, More().Refused("noise1"));
  // An explicit #version 110 shader.
  Add(c, "version_110", "3.3 #version 110", "uniform vec4 a;\n", "r = a * 2.0 - 1.0;",
      {"a=1,0.5,0,-1"}, {1, 0, -1, -3}, More().Version("110"));
  // A vector or matrix indexed by a non-constant int (5.5, 5.6).
  Add(c, "dynamic_index", "5.5, 5.6 indexing with a variable",
      "uniform vec4 a;\nuniform mat2 m;\nuniform int i;\n", "r = vec4(a[i], a[i + 1], m[i - 1]);",
      {"a=1,2,3,4", "m=5,6,7,8", "i=2"}, {3, 4, 7, 8});
  // A global variable, initialised by a constant and changed by a function.
  Add(c, "global_variable", "4.3 global variables",
      "uniform float s;\nfloat g = 2.0;\nvoid Bump(float x) { g *= x; }\n",
      "float before = g;\nBump(s);\nBump(s);\nr = vec4(before, g, 0.0, 0.0);", {"s=3"},
      {2, 18, 0, 0});
  // bvec constructors from floats and ints: != 0.
  Add(c, "bvec_constructor", "5.4.1 bvec from vec and ivec", "uniform vec2 u;\nuniform ivec2 i;\n",
      "bvec2 b = bvec2(u);\nbvec2 c = bvec2(i);\nr = vec4(vec2(b), vec2(c));", {"u=0,-2", "i=5,0"},
      {0, 1, 1, 0});
  // continue in a while loop jumps to the test: 1 + 2 + 4 + 5 (3 skipped).
  Add(c, "while_continue", "6.3 while, continue", "uniform int n;\n",
      "int i = 0;\nfloat sum = 0.0;\nwhile (i < n) {\n  ++i;\n  if (i == 3) continue;\n"
      "  sum += float(i);\n}\nr = vec4(sum, float(i), 0.0, 0.0);",
      {"n=5"}, {12, 5, 0, 0});
}

Expr StateExpr(std::string name, std::string spec, std::string body, std::vector<std::string> state,
               V want) {
  Expr e;
  e.name = std::move(name);
  e.spec = std::move(spec);
  e.body = std::move(body);
  e.more.state = std::move(state);
  e.want = std::move(want);
  return e;
}

// Rows of --state matrices (row-major, as the ARB exec takes them).
const char* const kTranslate123 = "1,0,0,1, 0,1,0,2, 0,0,1,3, 0,0,0,1";
const char* const kScale234 = "2,0,0,0, 0,3,0,0, 0,0,4,0, 0,0,0,1";

// 7.5 Built-in uniform state, read in both stages. Left out: gl_LightSource[n].halfVector,
// which 7.5 names derived state without giving its formula. GL state is given as `arbiter exec
// --state` takes it; lights, planes and positions in eye space (as GL holds them).
void BuiltinState(std::vector<GlslCase>* c) {
  // Column 3 of a translation is (1, 2, 3, 1); M (1,1,1,1) = (2, 3, 4, 1).
  Add(c, StateExpr("modelview_matrix", "7.5 gl_ModelViewMatrix",
                   "r = gl_ModelViewMatrix * vec4(1.0) + gl_ModelViewMatrix[3];",
                   {std::string("state.matrix.modelview=") + kTranslate123}, {3, 5, 7, 2}));
  Add(c, StateExpr("projection_matrix", "7.5 gl_ProjectionMatrix",
                   "mat4 p = gl_ProjectionMatrix;\nr = vec4(p[0].x, p[1].y, p[2].z, p[3].w);",
                   {std::string("state.matrix.projection=") + kScale234}, {2, 3, 4, 1}));
  // projection * modelview: (1,1,1,1) -> (2,3,4,1) -> (4,9,16,1).
  Add(c, StateExpr("modelview_projection_matrix", "7.5 gl_ModelViewProjectionMatrix",
                   "r = gl_ModelViewProjectionMatrix * vec4(1.0);",
                   {std::string("state.matrix.modelview=") + kTranslate123,
                    std::string("state.matrix.projection=") + kScale234},
                   {4, 9, 16, 1}));
  // The transpose of the inverse of the upper 3x3 of diag(2, 4, 8): diag(.5, .25, .125).
  Add(c, StateExpr("normal_matrix", "7.5 gl_NormalMatrix",
                   "r = vec4(gl_NormalMatrix * vec3(1.0), 0.0);",
                   {"state.matrix.modelview=2,0,0,0, 0,4,0,0, 0,0,8,0, 0,0,0,1"},
                   {0.5f, 0.25f, 0.125f, 0}));
  // x' = 2x + 1, y' = 4y + 2, z' = 8z + 3: the inverse maps (1, 2, 5, 1) to (0, 0, .25, 1);
  // the transpose's column 0 is row 0, (2, 0, 0, 1).
  const std::string scale_translate = "state.matrix.modelview=2,0,0,1, 0,4,0,2, 0,0,8,3, 0,0,0,1";
  Add(c, StateExpr("modelview_inverse", "7.5 gl_ModelViewMatrixInverse",
                   "r = gl_ModelViewMatrixInverse * vec4(1.0, 2.0, 5.0, 1.0);", {scale_translate},
                   {0, 0, 0.25f, 1}));
  Add(c, StateExpr("modelview_transpose", "7.5 gl_ModelViewMatrixTranspose",
                   "r = gl_ModelViewMatrixTranspose[0];", {scale_translate}, {2, 0, 0, 1}));
  // gl_TextureMatrix[1] (1, 2, 3, 1): x' = 2x + 1, y' = 2y, z' = 2z.
  Add(c, StateExpr("texture_matrix", "7.5 gl_TextureMatrix[n]",
                   "r = gl_TextureMatrix[1] * vec4(1.0, 2.0, 3.0, 1.0);",
                   {"state.matrix.texture[1]=2,0,0,1, 0,2,0,0, 0,0,2,0, 0,0,0,1"}, {3, 4, 6, 1}));
  // a + 2 d + 4 s.
  Add(c, StateExpr("light_colours", "7.5 gl_LightSource[n] ambient, diffuse, specular",
                   "gl_LightSourceParameters l = gl_LightSource[0];\n"
                   "r = l.ambient + 2.0 * l.diffuse + 4.0 * l.specular;",
                   {"state.light[0].ambient=0.25,0.5,0.75,1", "state.light[0].diffuse=1,0.5,0.25,1",
                    "state.light[0].specular=0.125,0.25,0.5,1"},
                   {2.75f, 2.5f, 3.25f, 7}));
  Add(c, StateExpr("light_position", "7.5 gl_LightSource[n] position, spotExponent",
                   "r = vec4(gl_LightSource[1].position.xyz, gl_LightSource[1].spotExponent);",
                   {"state.light[1].position=1,2,3,1", "state.light[1].spot.exponent=2"},
                   {1, 2, 3, 2}));
  Add(c, StateExpr("light_spot", "7.5 gl_LightSource[n] spotDirection, spotCutoff",
                   "r = vec4(gl_LightSource[1].spotDirection, gl_LightSource[1].spotCutoff);",
                   {"state.light[1].spot.direction=0,0.5,-1", "state.light[1].spot.cutoff=45"},
                   {0, 0.5f, -1, 45}));
  {
    // spotCosCutoff = cos(spotCutoff): cos(60 degrees) = .5, a cosine (kTrigBound).
    Expr e = StateExpr("light_spot_cos_cutoff", "7.5 gl_LightSource[n] spotCosCutoff",
                       "r = vec4(gl_LightSource[3].spotCosCutoff, 0.0, 0.0, 0.0);",
                       {"state.light[3].spot.cutoff=60"}, {0.5f, 0, 0, 0});
    e.more.tolerance = Tolerance::Absolute;
    e.more.bound = kTrigBound;
    Add(c, e);
  }
  Add(c, StateExpr("light_attenuation", "7.5 gl_LightSource[n] attenuations",
                   "gl_LightSourceParameters l = gl_LightSource[2];\n"
                   "r = vec4(l.constantAttenuation, l.linearAttenuation, l.quadraticAttenuation,"
                   " 0.0);",
                   {"state.light[2].attenuation=1,0.5,0.25"}, {1, 0.5f, 0.25f, 0}));
  // GL 2.0 table 2.10: light 0's diffuse is (1,1,1,1), the others' (0,0,0,1).
  Add(c, StateExpr("light_defaults", "7.5 gl_LightSource, GL 2.0 table 2.10",
                   "r = gl_LightSource[0].diffuse + 2.0 * gl_LightSource[1].diffuse;", {},
                   {1, 1, 1, 3}));
  Add(c,
      StateExpr("front_material", "7.5 gl_FrontMaterial emission, shininess",
                "r = vec4(gl_FrontMaterial.emission.xyz, gl_FrontMaterial.shininess);",
                {"state.material.front.emission=0.25,0,0.5,1", "state.material.front.shininess=16"},
                {0.25f, 0, 0.5f, 16}));
  Add(c,
      StateExpr("front_material_colours", "7.5 gl_FrontMaterial ambient, diffuse, specular",
                "r = gl_FrontMaterial.ambient + 2.0 * gl_FrontMaterial.diffuse +\n"
                "    4.0 * gl_FrontMaterial.specular;",
                {"state.material.front.ambient=0.5,0,0,1", "state.material.front.diffuse=0,0.5,0,1",
                 "state.material.front.specular=0,0,0.5,1"},
                {0.5f, 1, 2, 7}));
  Add(c, StateExpr("back_material", "7.5 gl_BackMaterial", "r = gl_BackMaterial.diffuse;",
                   {"state.material.back.diffuse=0.25,0.5,0.75,0.5"}, {0.25f, 0.5f, 0.75f, 0.5f}));
  Add(c, StateExpr("light_model", "7.5 gl_LightModel.ambient", "r = gl_LightModel.ambient;",
                   {"state.lightmodel.ambient=0.5,0.25,0.125,1"}, {0.5f, 0.25f, 0.125f, 1}));
  // sceneColor = Ecm + Acm * Acs: (.25 + .5 .5, 0 + .5 .25, 0 + .5 1); alpha 0 + 1 1. (GL's
  // lighting takes the scene colour's alpha from the diffuse material, 1 here too.)
  Add(c, StateExpr("light_model_product", "7.5 gl_FrontLightModelProduct.sceneColor",
                   "r = gl_FrontLightModelProduct.sceneColor;",
                   {"state.material.front.emission=0.25,0,0,0",
                    "state.material.front.ambient=0.5,0.5,0.5,1",
                    "state.lightmodel.ambient=0.5,0.25,1,1"},
                   {0.5f, 0.125f, 0.5f, 1}));
  // Acm Acli = (.5,.5,.5,1)(.5,.25,1,1) = (.25,.125,.5,1); Dcm Dcli = (1,.5,.25,1)(.5,.5,.5,1)
  // = (.5,.25,.125,1); Scm Scli = (.25,.25,.25,1)(1,.5,0,1) = (.25,.125,0,1); a + 2 d + 4 s.
  Add(c, StateExpr("light_product", "7.5 gl_FrontLightProduct[n]",
                   "gl_LightProducts p = gl_FrontLightProduct[0];\n"
                   "r = p.ambient + 2.0 * p.diffuse + 4.0 * p.specular;",
                   {"state.material.front.ambient=0.5,0.5,0.5,1",
                    "state.material.front.diffuse=1,0.5,0.25,1",
                    "state.material.front.specular=0.25,0.25,0.25,1",
                    "state.light[0].ambient=0.5,0.25,1,1", "state.light[0].diffuse=0.5,0.5,0.5,1",
                    "state.light[0].specular=1,0.5,0,1"},
                   {0.25f + 1 + 1, 0.125f + 0.5f + 0.5f, 0.5f + 0.25f + 0, 7}));
  // scale = 1 / (end - start) = 1 / 4.
  Add(c, StateExpr("fog", "7.5 gl_Fog density, start, end, scale",
                   "r = vec4(gl_Fog.density, gl_Fog.start, gl_Fog.end, gl_Fog.scale);",
                   {"state.fog.density=0.5", "state.fog.start=1", "state.fog.end=5"},
                   {0.5f, 1, 5, 0.25f}));
  Add(c, StateExpr("fog_color", "7.5 gl_Fog.color", "r = gl_Fog.color;",
                   {"state.fog.color=0.25,0.5,0.75,1"}, {0.25f, 0.5f, 0.75f, 1}));
  Add(c, StateExpr(
             "point", "7.5 gl_Point size, sizeMin, sizeMax, fadeThresholdSize",
             "r = vec4(gl_Point.size, gl_Point.sizeMin, gl_Point.sizeMax,"
             " gl_Point.fadeThresholdSize);",
             {"state.point.size=4", "state.point.min=1", "state.point.max=8", "state.point.fade=2"},
             {4, 1, 8, 2}));
  Add(c, StateExpr("point_attenuation", "7.5 gl_Point distance attenuations",
                   "r = vec4(gl_Point.distanceConstantAttenuation,"
                   " gl_Point.distanceLinearAttenuation,\n"
                   "         gl_Point.distanceQuadraticAttenuation, 0.0);",
                   {"state.point.attenuation=1,0.5,0.25"}, {1, 0.5f, 0.25f, 0}));
  // diff = far - near.
  Add(c, StateExpr("depth_range", "7.5 gl_DepthRange",
                   "r = vec4(gl_DepthRange.near, gl_DepthRange.far, gl_DepthRange.diff, 0.0);",
                   {"state.depth.range=0.25,0.75"}, {0.25f, 0.75f, 0.5f, 0}));
  Add(c, StateExpr("clip_plane", "7.5 gl_ClipPlane[n]", "r = gl_ClipPlane[2];",
                   {"state.clip[2].plane=1,2,-3,4"}, {1, 2, -3, 4}));
  Add(c, StateExpr("texture_env_color", "7.5 gl_TextureEnvColor[n]", "r = gl_TextureEnvColor[1];",
                   {"state.texenv[1].color=0.25,0.5,0.75,1"}, {0.25f, 0.5f, 0.75f, 1}));
  Add(c, StateExpr("texgen_planes", "7.5 gl_EyePlaneS[n], gl_ObjectPlaneT[n]",
                   "r = gl_EyePlaneS[0] + 2.0 * gl_ObjectPlaneT[1];",
                   {"state.texgen[0].eye.s=1,2,3,4", "state.texgen[1].object.t=5,6,7,8"},
                   {11, 14, 17, 20}));
  // 7.4: the implementation's limits are at least the spec's minimums.
  // projection diag(2, 4, 8), texture[0] diag(4, 4, 4), modelview a translation by (1, 2, 3):
  // MVP rows (2,0,0,2) (0,4,0,8) (0,0,8,24) (0,0,0,1), whose inverse has column 3
  // (-1, -2, -3, 1) and whose transpose has column 0 = row 0.
  Add(c, StateExpr("matrix_inverse_transpose", "7.5 gl_*MatrixInverse, gl_*MatrixTranspose",
                   "r = vec4(gl_ProjectionMatrixInverse[1].y, gl_TextureMatrixInverse[0][2].z,\n"
                   "         gl_ModelViewProjectionMatrixTranspose[0].w,\n"
                   "         gl_ModelViewProjectionMatrixInverse[3].x);",
                   {"state.matrix.projection=2,0,0,0, 0,4,0,0, 0,0,8,0, 0,0,0,1",
                    "state.matrix.texture[0]=4,0,0,0, 0,4,0,0, 0,0,4,0, 0,0,0,1",
                    std::string("state.matrix.modelview=") + kTranslate123},
                   {0.25f, 0.25f, 2, -1}));
  {
    // GL 2.0 2.11.3: f = 1 / sqrt(m31^2 + m32^2 + m33^2) of the inverse modelview's upper
    // 3x3: diag(.5) gives 2. A square root (Relative).
    Expr e = StateExpr("normal_scale", "7.5 gl_NormalScale, GL 2.0 2.11.3",
                       "r = vec4(gl_NormalScale, 0.0, 0.0, 0.0);",
                       {"state.matrix.modelview=2,0,0,0, 0,2,0,0, 0,0,2,0, 0,0,0,1"}, {2, 0, 0, 0});
    e.more.tolerance = Tolerance::Relative;
    e.more.bound = kGlPrecision;
    Add(c, e);
  }
  // GL 2.0's initial values: material ambient (.2,.2,.2,1), diffuse (.8,.8,.8,1), specular
  // and emission (0,0,0,1) (table 2.10); fog density 1, start 0, end 1, so scale 1 (3.10);
  // depth range [0, 1] (2.11.1).
  Add(c, StateExpr("material_defaults", "7.5 gl_FrontMaterial, GL 2.0 table 2.10",
                   "r = vec4(gl_FrontMaterial.ambient.x, gl_FrontMaterial.diffuse.y,\n"
                   "         gl_FrontMaterial.specular.z, gl_FrontMaterial.emission.w);",
                   {}, {0.2f, 0.8f, 0, 1}));
  Add(c, StateExpr("fog_depth_defaults", "7.5 gl_Fog, gl_DepthRange, GL 2.0 3.10, 2.11.1",
                   "r = vec4(gl_Fog.density, gl_Fog.start + gl_Fog.end, gl_Fog.scale,\n"
                   "         gl_DepthRange.far - gl_DepthRange.near + gl_DepthRange.diff);",
                   {}, {1, 1, 1, 2}));
  // The back face's products: Dcm Dcli with the back material, (.5,.5,.5,1)(1,.5,.25,1).
  Add(c,
      StateExpr(
          "back_light_product", "7.5 gl_BackLightProduct[n]", "r = gl_BackLightProduct[1].diffuse;",
          {"state.material.back.diffuse=0.5,0.5,0.5,1", "state.light[1].diffuse=1,0.5,0.25,1"},
          {0.5f, 0.25f, 0.125f, 1}));
  Add(c, StateExpr("builtin_constants", "7.4 built-in constants (minimums)",
                   "r = vec4(float(gl_MaxLights >= 8), float(gl_MaxClipPlanes >= 6),\n"
                   "         float(gl_MaxTextureCoords >= 2), float(gl_MaxDrawBuffers >= 1));",
                   {}, {1, 1, 1, 1}));
}

GlslCase Vs(std::string name, std::string spec, std::string shader) {
  GlslCase c;
  c.name = std::move(name);
  c.spec = std::move(spec);
  c.vertex = std::move(shader);
  return c;
}
GlslCase Fs(std::string name, std::string spec, std::string shader) {
  GlslCase c;
  c.name = std::move(name);
  c.spec = std::move(spec);
  c.fragment = std::move(shader);
  return c;
}

// 7.1 Vertex shader special variables and built-in attributes (7.3) and varyings (7.6),
// read back as written (before any clamping).
void VertexOutputs(std::vector<GlslCase>* out) {
  {
    // gl_TexCoord redeclared with a size may be indexed by a variable (7.6).
    GlslCase c = Vs("texcoord_redeclared", "7.6 gl_TexCoord redeclared with a size",
                    "varying vec4 gl_TexCoord[3];\nuniform int i;\n"
                    "void main() {\n  gl_Position = gl_Vertex;\n"
                    "  gl_TexCoord[i] = vec4(1.0, 2.0, 3.0, 4.0) * float(i);\n}\n");
    c.uniforms = {"i=2"};
    c.expects = {Eq("gl_TexCoord[2]", {2, 4, 6, 8})};
    out->push_back(c);
  }
  {
    // ftransform() = gl_ModelViewProjectionMatrix * gl_Vertex.
    GlslCase c = Vs("ftransform", "8.4 ftransform, 7.1 gl_Position",
                    "void main() { gl_Position = ftransform(); }\n");
    c.state = {std::string("state.matrix.modelview=") + kTranslate123,
               std::string("state.matrix.projection=") + kScale234};
    c.sets = {{"gl_Vertex=1,1,1,1"}};
    c.expects = {Eq("gl_Position", {4, 9, 16, 1})};
    out->push_back(c);
  }
  {
    // gl_Vertex given 2 components: (x, y, 0, 1) (GL 2.0 2.7).
    GlslCase c = Vs("vertex_fill", "7.3 gl_Vertex, GL 2.0 2.7 Vertex2",
                    "void main() { gl_Position = gl_Vertex; }\n");
    c.sets = {{"gl_Vertex=1,2"}};
    c.expects = {Eq("gl_Position", {1, 2, 0, 1})};
    out->push_back(c);
  }
  {
    GlslCase c = Vs("point_size_clip_vertex", "7.1 gl_PointSize, gl_ClipVertex",
                    "void main() {\n  gl_Position = gl_Vertex;\n"
                    "  gl_PointSize = gl_Vertex.x * 2.0;\n  gl_ClipVertex = gl_Vertex * 3.0;\n}\n");
    c.sets = {{"gl_Vertex=1,2,3,1"}};
    c.expects = {Eq("gl_PointSize", {2}), Eq("gl_ClipVertex", {3, 6, 9, 3})};
    out->push_back(c);
  }
  {
    // gl_SecondaryColor given 3 components has alpha 1.
    GlslCase c = Vs("colours", "7.6 gl_FrontColor, gl_BackColor, gl_Front/BackSecondaryColor",
                    "void main() {\n  gl_Position = gl_Vertex;\n  gl_FrontColor = gl_Color;\n"
                    "  gl_BackColor = gl_Color * 2.0;\n"
                    "  gl_FrontSecondaryColor = gl_SecondaryColor;\n"
                    "  gl_BackSecondaryColor = -gl_SecondaryColor;\n}\n");
    c.sets = {{"gl_Color=0.5,0.25,2,1", "gl_SecondaryColor=1,2,3"}};
    c.expects = {Eq("gl_FrontColor", {0.5f, 0.25f, 2, 1}), Eq("gl_BackColor", {1, 0.5f, 4, 2}),
                 Eq("gl_FrontSecondaryColor", {1, 2, 3, 1}),
                 Eq("gl_BackSecondaryColor", {-1, -2, -3, -1})};
    out->push_back(c);
  }
  {
    GlslCase c = Vs("texcoords_fog", "7.6 gl_TexCoord[n], gl_FogFragCoord; 7.3 attributes",
                    "void main() {\n  gl_Position = gl_Vertex;\n"
                    "  gl_TexCoord[0] = gl_MultiTexCoord0;\n"
                    "  gl_TexCoord[3] = gl_MultiTexCoord3 * 2.0;\n"
                    "  gl_FogFragCoord = gl_FogCoord * 4.0;\n}\n");
    c.sets = {{"gl_MultiTexCoord0=1,2", "gl_MultiTexCoord3=1,2,3,4", "gl_FogCoord=0.5"}};
    c.expects = {Eq("gl_TexCoord[0]", {1, 2, 0, 1}), Eq("gl_TexCoord[3]", {2, 4, 6, 8}),
                 Eq("gl_FogFragCoord", {2})};
    out->push_back(c);
  }
  {
    // Vector 1 leaves gl_Normal at GL's initial (0, 0, 1) (GL 2.0 2.7).
    GlslCase c = Vs("normal", "7.3 gl_Normal",
                    "varying vec4 v;\nvoid main() { gl_Position = gl_Vertex; v = vec4(gl_Normal,"
                    " 1.0); }\n");
    c.vectors = 2;
    c.sets = {{"gl_Normal=0,0.5,-1"}, {}};
    c.expects = {Eq("v", {0, 0.5f, -1, 1}), Eq("v", {0, 0, 1, 1}, 1)};
    out->push_back(c);
  }
  {
    GlslCase c = Vs("user_attributes", "4.3.3 attribute (float, vec3, mat2)",
                    "attribute vec3 tangent;\nattribute float w;\nattribute mat2 m;\n"
                    "varying vec4 v;\n"
                    "void main() { gl_Position = gl_Vertex; v = vec4(tangent * w, m[1][0]); }\n");
    c.sets = {{"tangent=1,2,3", "w=2", "m=1,2,3,4"}};
    c.expects = {Eq("v", {2, 4, 6, 3})};
    out->push_back(c);
  }
  {
    // Varyings of every shape: float, vec2, an array (element by element), a matrix.
    GlslCase c = Vs("user_varyings", "4.3.6 varying (float, vec2, float[3], mat2)",
                    "uniform vec4 a;\nvarying float f;\nvarying vec2 p;\nvarying float arr[3];\n"
                    "varying mat2 m;\n"
                    "void main() {\n  gl_Position = gl_Vertex;\n  f = a.x;\n  p = a.yz;\n"
                    "  for (int i = 0; i < 3; ++i) arr[i] = a.w * float(i);\n"
                    "  m = mat2(a.x, a.y, a.z, a.w);\n}\n");
    c.uniforms = {"a=1,2,3,4"};
    c.expects = {Eq("f", {1}),      Eq("p", {2, 3}),   Eq("arr[0]", {0}),
                 Eq("arr[1]", {4}), Eq("arr[2]", {8}), Eq("m", {1, 2, 3, 4})};
    out->push_back(c);
  }
  {
    // 1.20 matrix varyings: outerProduct into a mat2x3 (columns c * r[i]), a transpose.
    GlslCase c = Vs("matrix_varyings", "8.5 outerProduct, transpose into mat varyings (1.20)",
                    "#version 120\nuniform vec3 u;\nuniform vec2 w;\nuniform mat3 n;\n"
                    "varying mat2x3 o;\nvarying mat3 t;\n"
                    "void main() {\n  gl_Position = gl_Vertex;\n  o = outerProduct(u, w);\n"
                    "  t = transpose(n);\n}\n");
    c.uniforms = {"u=1,2,3", "w=4,5", "n=1,2,3,4,5,6,7,8,9"};
    c.expects = {Eq("o", {4, 8, 12, 5, 10, 15}), Eq("t", {1, 4, 7, 2, 5, 8, 3, 6, 9})};
    out->push_back(c);
  }
  {
    // One result per vector.
    GlslCase c = Vs("vectors", "7.1, several input vectors",
                    "varying float v;\nvoid main() { gl_Position = gl_Vertex; v = gl_Vertex.x *"
                    " gl_Vertex.y; }\n");
    c.vectors = 3;
    c.sets = {{"gl_Vertex=1,2"}, {"gl_Vertex=3,4"}, {"gl_Vertex=-5,6"}};
    c.expects = {Eq("v", {2}), Eq("v", {12}, 1), Eq("v", {-30}, 2)};
    out->push_back(c);
  }
  {
    // return in main ends the shader; what it wrote stays (6.4).
    GlslCase c = Vs("return_from_main", "6.4 return in main",
                    "varying float v;\nvoid main() {\n  gl_Position = gl_Vertex;\n  v = 1.0;\n"
                    "  if (gl_Vertex.x > 0.0) return;\n  v = 2.0;\n}\n");
    c.vectors = 2;
    c.sets = {{"gl_Vertex=1,0"}, {"gl_Vertex=-1,0"}};
    c.expects = {Eq("v", {1}), Eq("v", {2}, 1)};
    out->push_back(c);
  }
}

// 7.2 Fragment shader special variables and inputs (7.6); fragment shaders alone, fed with
// what a vertex stage hands them. Vector i is drawn at pixel (i, 0). Left out: gl_PointCoord
// (1.20), defined only for point sprites (GL 2.1 3.3), which the engines do not enable.
void FragmentShaders(std::vector<GlslCase>* out) {
  {
    // gl_FragData indexed by a loop variable.
    GlslCase c = Fs("frag_data_loop", "7.2 gl_FragData[n] indexed by a variable",
                    "void main() {\n  for (int i = 0; i < 2; ++i) gl_FragData[i] = vec4(float(i) +"
                    " 0.5);\n}\n");
    c.expects = {Eq("gl_FragData[0]", {0.5f, 0.5f, 0.5f, 0.5f}),
                 Eq("gl_FragData[1]", {1.5f, 1.5f, 1.5f, 1.5f})};
    out->push_back(c);
  }
  {
    GlslCase c = Fs("frag_data", "7.2 gl_FragData[n]",
                    "varying float f;\nvoid main() {\n  gl_FragData[0] = gl_Color;\n"
                    "  gl_FragData[1] = gl_TexCoord[1];\n  gl_FragData[2] = vec4(f, 0.0, 0.0,"
                    " 1.0);\n}\n");
    c.sets = {{"gl_Color=0.25,0.5,0.75,1", "gl_TexCoord[1]=1,2,3,4", "f=-2"}};
    c.expects = {Eq("gl_FragData[0]", {0.25f, 0.5f, 0.75f, 1}), Eq("gl_FragData[1]", {1, 2, 3, 4}),
                 Eq("gl_FragData[2]", {-2, 0, 0, 1})};
    out->push_back(c);
  }
  {
    // The depth written is clamped to [0, 1] (GL 2.0 3.11.2, "Shader Outputs").
    GlslCase c = Fs("frag_depth", "7.2 gl_FragDepth",
                    "varying float d;\nvoid main() { gl_FragColor = vec4(d); gl_FragDepth = d;"
                    " }\n");
    c.vectors = 3;
    c.sets = {{"d=0.25"}, {"d=1.5"}, {"d=-1"}};
    c.expects = {Eq("gl_FragDepth", {0.25f}), Eq("gl_FragDepth", {1}, 1),
                 Eq("gl_FragDepth", {0}, 2)};
    out->push_back(c);
  }
  {
    // (x + .5, y + .5, z, 1 / w): the window position of pixel (i, 0), its depth, w = 1.
    GlslCase c =
        Fs("frag_coord", "7.2 gl_FragCoord", "void main() { gl_FragColor = gl_FragCoord; }\n");
    c.vectors = 3;
    c.sets = {{"gl_FragCoord.z=0.25"}, {"gl_FragCoord.z=0.5"}, {"gl_FragCoord.z=0.75"}};
    c.expects = {Eq("gl_FragColor", {0.5f, 0.5f, 0.25f, 1}),
                 Eq("gl_FragColor", {1.5f, 0.5f, 0.5f, 1}, 1),
                 Eq("gl_FragColor", {2.5f, 0.5f, 0.75f, 1}, 2)};
    out->push_back(c);
  }
  {
    // Points are front facing (GL 2.0 3.11.2: fragments of points count as front facing).
    GlslCase c = Fs("front_facing", "7.2 gl_FrontFacing",
                    "void main() { gl_FragColor = vec4(float(gl_FrontFacing), 0.0, 0.0, 1.0); }\n");
    c.expects = {Eq("gl_FragColor", {1, 0, 0, 1})};
    out->push_back(c);
  }
  {
    GlslCase c = Fs("discard", "6.4 discard",
                    "varying float k;\nvoid main() {\n  if (k < 0.0) discard;\n"
                    "  gl_FragColor = vec4(k);\n}\n");
    c.vectors = 3;
    c.sets = {{"k=1"}, {"k=-1"}, {"k=2"}};
    c.discarded = {1};
    c.expects = {Eq("gl_FragColor", {1, 1, 1, 1}), Eq("gl_FragColor", {2, 2, 2, 2}, 2)};
    out->push_back(c);
  }
  {
    // discard in a function called from main, inside a loop.
    GlslCase c = Fs("discard_in_function", "6.4 discard in a function",
                    "varying float k;\nvoid Check(float x) { if (x > 2.0) discard; }\n"
                    "void main() {\n  for (int i = 0; i < 3; ++i) Check(k + float(i));\n"
                    "  gl_FragColor = vec4(k, 0.0, 0.0, 1.0);\n}\n");
    c.vectors = 2;
    c.sets = {{"k=0.5"}, {"k=0"}};
    c.discarded = {0};
    c.expects = {Eq("gl_FragColor", {0, 0, 0, 1}, 1)};
    out->push_back(c);
  }
  {
    GlslCase c = Fs("fragment_inputs", "7.6 gl_SecondaryColor, gl_FogFragCoord, gl_TexCoord[7]",
                    "void main() {\n  gl_FragColor = vec4(gl_SecondaryColor.xy, gl_FogFragCoord,"
                    " gl_TexCoord[7].w);\n}\n");
    c.sets = {{"gl_SecondaryColor=0.5,0.25,1", "gl_FogFragCoord=3", "gl_TexCoord[7]=0,0,0,9"}};
    c.expects = {Eq("gl_FragColor", {0.5f, 0.25f, 3, 9})};
    out->push_back(c);
  }
  {
    GlslCase c = Fs("fragment_varyings", "4.3.6 varying arrays and matrices in a fragment shader",
                    "varying float k[2];\nvarying mat2 m;\n"
                    "void main() { gl_FragColor = vec4(k[0], k[1], m[1]); }\n");
    c.sets = {{"k[0]=2", "k[1]=5", "m=1,2,3,4"}};
    c.expects = {Eq("gl_FragColor", {2, 5, 3, 4})};
    out->push_back(c);
  }
  {
    // Derivatives of functions linear in the window position: 3x has dFdx 3 and dFdy 0
    // whichever local differencing (forward, backward, central) is used (8.8), exactly for
    // these small values. fwidth = |dFdx| + |dFdy|; a varying that is constant over the
    // point has derivative 0.
    GlslCase c = Fs("derivatives", "8.8 dFdx, dFdy",
                    "void main() {\n  float x = gl_FragCoord.x * 3.0;\n"
                    "  float y = gl_FragCoord.y * 2.0;\n"
                    "  gl_FragColor = vec4(dFdx(x), dFdy(y), dFdx(y), dFdy(x));\n}\n");
    c.expects = {Eq("gl_FragColor", {3, 2, 0, 0})};
    out->push_back(c);
  }
  {
    GlslCase c = Fs("fwidth", "8.8 fwidth",
                    "varying float k;\nvoid main() {\n"
                    "  float f = gl_FragCoord.x * 3.0 - gl_FragCoord.y;\n"
                    "  gl_FragColor = vec4(fwidth(f), dFdx(k), dFdy(k), fwidth(k));\n}\n");
    c.sets = {{"k=5"}};
    c.expects = {Eq("gl_FragColor", {4, 0, 0, 0})};
    out->push_back(c);
  }
}

// Vertex + fragment pairs: the varyings flow from one stage to the other.
void Pairs(std::vector<GlslCase>* out) {
  {
    // A varying is the same over the whole point (one vertex), so its derivatives are 0 (8.8).
    GlslCase c = Vs("pair_derivatives", "8.8 dFdx, dFdy, fwidth of a varying in a pair",
                    "varying float k;\nvoid main() { gl_Position = gl_Vertex; k = gl_Vertex.x *"
                    " 5.0; }\n");
    c.fragment =
        "varying float k;\n"
        "void main() { gl_FragColor = vec4(dFdx(k), dFdy(k), fwidth(k), k); }\n";
    c.sets = {{"gl_Vertex=1,0"}};
    c.expects = {Eq("k", {5}), Eq("gl_FragColor", {0, 0, 0, 5})};
    out->push_back(c);
  }
  {
    // Vertex colours are clamped to [0, 1] on the way (GL 2.0 2.14.6); user varyings not.
    GlslCase c = Vs("pair_colour_clamp", "GL 2.0 2.14.6 colour clamping, 4.3.6 varyings",
                    "varying float k;\nvoid main() {\n  gl_Position = gl_Vertex;\n"
                    "  gl_FrontColor = vec4(2.0, -1.0, 0.5, 1.0) * gl_Vertex.y;\n"
                    "  k = gl_Vertex.x * 3.0;\n}\n");
    c.fragment = "varying float k;\nvoid main() { gl_FragColor = vec4(gl_Color.xyz, k); }\n";
    c.sets = {{"gl_Vertex=0.5,1,0,1"}};
    c.expects = {Eq("gl_FrontColor", {2, -1, 0.5f, 1}), Eq("k", {1.5f}),
                 Eq("gl_FragColor", {1, 0, 0.5f, 1.5f})};
    out->push_back(c);
  }
  {
    // Texture coordinates are not clamped; a point is front facing, so gl_Color is the front
    // colour.
    GlslCase c = Vs("pair_texcoord_front", "7.6 gl_TexCoord, GL 2.0 2.14.1 front colour",
                    "void main() {\n  gl_Position = gl_Vertex;\n"
                    "  gl_TexCoord[2] = vec4(4.0, -3.0, 0.5, 2.0) * gl_Vertex.w;\n"
                    "  gl_FrontColor = vec4(0.25);\n  gl_BackColor = vec4(0.75);\n}\n");
    c.fragment =
        "void main() { gl_FragColor = gl_TexCoord[2] + vec4(gl_Color.x, 0.0, 0.0, 0.0); }\n";
    c.expects = {Eq("gl_FragColor", {4.25f, -3, 0.5f, 2})};
    out->push_back(c);
  }
  {
    // A uniform declared in both stages is one uniform.
    GlslCase c = Vs("pair_shared_uniform", "4.3.5 uniforms shared by the stages",
                    "uniform float s;\nvarying float k;\n"
                    "void main() { gl_Position = gl_Vertex; k = s * 2.0; }\n");
    c.fragment =
        "uniform float s;\nvarying float k;\n"
        "void main() { gl_FragColor = vec4(k, s, k + s, 1.0); }\n";
    c.uniforms = {"s=1.5"};
    c.expects = {Eq("k", {3}), Eq("gl_FragColor", {3, 1.5f, 4.5f, 1})};
    out->push_back(c);
  }
  {
    // The fragment shader discards by a varying from the vertex shader.
    GlslCase c =
        Vs("pair_discard", "6.4 discard in a pair",
           "varying float k;\nvoid main() { gl_Position = gl_Vertex; k = gl_Vertex.x; }\n");
    c.fragment =
        "varying float k;\nvoid main() {\n  if (k > 0.0) discard;\n"
        "  gl_FragColor = vec4(k);\n}\n";
    c.vectors = 2;
    c.sets = {{"gl_Vertex=1,0"}, {"gl_Vertex=-2,0"}};
    c.discarded = {0};
    c.expects = {Eq("k", {1}), Eq("k", {-2}, 1), Eq("gl_FragColor", {-2, -2, -2, -2}, 1)};
    out->push_back(c);
  }
}

// The plumbing of every input and output type: uniforms, attributes and varyings of the less
// common shapes (GL 2.0 2.15.3: a uniform structure's members and an array's elements are
// set one by one; matrices column by column).
void Plumbing(std::vector<GlslCase>* out) {
  {
    // mat3x2: 3 columns of 2; mat4x3: 4 columns of 3 (1.20).
    Expr e;
    e.name = "uniform_nonsquare_matrices";
    e.spec = "4.1.6 mat3x2, mat4x3 uniforms (1.20)";
    e.decls = "uniform mat3x2 p;\nuniform mat4x3 q;\n";
    e.body = "r = vec4(p[2], q[3].z, q[0].x);";
    e.uniforms = {"p=1,2,3,4,5,6", "q=1,2,3,4,5,6,7,8,9,10,11,12"};
    e.want = {5, 6, 12, 1};
    e.more.version = "120";
    Add(out, e);
  }
  {
    Expr e;
    e.name = "uniform_int_bool_arrays";
    e.spec = "4.1.9 ivec and bool uniform arrays";
    e.decls = "uniform ivec2 n[2];\nuniform bool f[3];\n";
    e.body = "r = vec4(vec2(n[1]), float(f[1]), float(f[2]));";
    e.uniforms = {"n=1,2,3,4", "f=1,0,1"};
    e.want = {3, 4, 0, 1};
    Add(out, e);
  }
  {
    // A structure with an array member and a nested structure array.
    Expr e;
    e.name = "uniform_struct_with_arrays";
    e.spec = "4.1.8 structure uniforms with array members";
    e.decls = "struct M { float k; };\nstruct S { float w[2]; M m[2]; };\nuniform S s;\n";
    e.body = "r = vec4(s.w[0], s.w[1], s.m[0].k, s.m[1].k);";
    e.uniforms = {"s.w=1,2", "s.m[0].k=3", "s.m[1].k=4"};
    e.want = {1, 2, 3, 4};
    Add(out, e);
  }
  {
    GlslCase c = Vs("matrix_attributes", "4.3.3 mat3 and mat4 attributes, vec2 attributes",
                    "attribute mat3 m3;\nattribute mat4 m4;\nattribute vec2 uv;\n"
                    "varying vec4 v;\nvarying vec4 w;\n"
                    "void main() {\n  gl_Position = gl_Vertex;\n"
                    "  v = vec4(m3[2], uv.y);\n  w = m4[3] + vec4(m4[0].x);\n}\n");
    c.sets = {{"m3=1,2,3,4,5,6,7,8,9", "m4=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16", "uv=0.5,0.25"}};
    c.expects = {Eq("v", {7, 8, 9, 0.25f}), Eq("w", {14, 15, 16, 17})};
    out->push_back(c);
  }
  {
    // gl_MultiTexCoord7 and the last texture coordinate set.
    GlslCase c =
        Vs("texcoord_7", "7.3 gl_MultiTexCoord7, 7.6 gl_TexCoord[7]",
           "void main() { gl_Position = gl_Vertex; gl_TexCoord[7] = gl_MultiTexCoord7; }\n");
    c.sets = {{"gl_MultiTexCoord7=1,2,3"}};
    c.expects = {Eq("gl_TexCoord[7]", {1, 2, 3, 1})};
    out->push_back(c);
  }
  {
    // vec3 array and mat3x4 varyings (1.20), element by element.
    GlslCase c = Vs("varying_vec3_array_mat3x4", "4.3.6 vec3[2] and mat3x4 varyings (1.20)",
                    "#version 120\nuniform vec4 a;\nvarying vec3 n[2];\nvarying mat3x4 m;\n"
                    "void main() {\n  gl_Position = gl_Vertex;\n  n[0] = a.xyz;\n"
                    "  n[1] = a.wzy;\n  m = mat3x4(a, a * 2.0, a * 3.0);\n}\n");
    c.uniforms = {"a=1,2,3,4"};
    c.expects = {Eq("n[0]", {1, 2, 3}), Eq("n[1]", {4, 3, 2}),
                 Eq("m", {1, 2, 3, 4, 2, 4, 6, 8, 3, 6, 9, 12})};
    out->push_back(c);
  }
  {
    // A fragment shader alone fed a vec3 array varying, by element.
    GlslCase c =
        Fs("fragment_vec3_array_input", "4.3.6 a vec3[2] varying read by a fragment shader",
           "varying vec3 uv[2];\nvoid main() { gl_FragColor = vec4(uv[1], uv[0].x); }\n");
    c.sets = {{"uv[0]=9,8,7", "uv[1]=1,2,3"}};
    c.expects = {Eq("gl_FragColor", {1, 2, 3, 9})};
    out->push_back(c);
  }
  {
    // In a pair: the secondary colour is clamped as the primary is (GL 2.0 2.14.6); the fog
    // coordinate and user arrays and matrices are not.
    GlslCase c =
        Vs("pair_secondary_fog_arrays", "GL 2.0 2.14.6; 4.3.6 varyings in a pair",
           "varying float k[2];\nvarying mat2 m;\nvoid main() {\n"
           "  gl_Position = gl_Vertex;\n  gl_FrontSecondaryColor = vec4(-1.0, 0.5, 3.0, 1.0);\n"
           "  gl_FogFragCoord = 7.0 * gl_Vertex.w;\n  k[0] = -2.0;\n  k[1] = 9.0;\n"
           "  m = mat2(1.0, 2.0, 3.0, 4.0) * gl_Vertex.w;\n}\n");
    c.fragment =
        "varying float k[2];\nvarying mat2 m;\nvoid main() {\n"
        "  gl_FragData[0] = vec4(gl_SecondaryColor.xyz, gl_FogFragCoord);\n"
        "  gl_FragData[1] = vec4(k[0], k[1], m[1]);\n}\n";
    c.expects = {Eq("gl_FragData[0]", {0, 0.5f, 1, 7}), Eq("gl_FragData[1]", {-2, 9, 3, 4})};
    out->push_back(c);
  }
}

}  // namespace

const std::vector<GlslCase>& AllGlslCases() {
  static const std::vector<GlslCase> cases = [] {
    std::vector<GlslCase> c;
    AngleAndTrigonometry(&c);
    Exponential(&c);
    Common(&c);
    Geometric(&c);
    Matrices(&c);
    Relational(&c);
    Textures(&c);
    Operators(&c);
    Conversions(&c);
    ControlFlow(&c);
    Functions(&c);
    StructsAndArrays(&c);
    MoreExpressions(&c);
    BuiltinState(&c);
    VertexOutputs(&c);
    FragmentShaders(&c);
    Pairs(&c);
    Plumbing(&c);
    return c;
  }();
  return cases;
}

}  // namespace arbiter::glsl_cases
