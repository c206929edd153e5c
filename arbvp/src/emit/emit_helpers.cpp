// Helper functions the translation defines before main(): LIT, EXP, LOG and the light half
// vector written out as the specs' pseudo-code, and bounds-checked relative-address readers.
#include <fmt/format.h>

#include <limits>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {
namespace {

// The largest float below 128: the spec clamps the LIT exponent to (-128, 128) exclusive,
// "128 - epsilon".
constexpr float kLitLimit = 127.99999237060546875f;

std::string LitText(const Context& ctx) {
  std::string limit = ctx.Mutated(Mutation::LitExponentClamp180) ? "180.0" : FormatFloat(kLitLimit);
  std::string y = ctx.Mutated(Mutation::LitNoYClamp) ? "s.y" : "s.y < 0.0 ? 0.0 : s.y";
  std::string z = ctx.Mutated(Mutation::LitNoZeroPowZero)
                      ? "x > 0.0 ? pow(y, w) : 0.0"
                      : "x > 0.0 ? (w == 0.0 ? 1.0 : pow(y, w)) : 0.0";
  return fmt::format(
      "// LIT (ARBvp 2.14.5.13): x and y clamped at 0, w to [-(128 - eps), 128 - eps] with\n"
      "// 128 - eps = {0} (the largest float below 128); z = x > 0 ? y^w : 0 with 0^0 = 1.\n"
      "vec4 arb_lit(vec4 s) {{\n"
      "  float x = s.x < 0.0 ? 0.0 : s.x;\n"
      "  float y = {1};\n"
      "  float w = s.w < -{0} ? -{0} : (s.w > {0} ? {0} : s.w);\n"
      "  float z = {2};\n"
      "  return vec4(1.0, x, z, 1.0);\n"
      "}}\n",
      limit, y, z);
}

std::string ExpText(const Context& ctx) {
  std::string frac = ctx.Mutated(Mutation::ExpFraction) ? "t - float(int(t))" : "t - f";
  return fmt::format(
      "// EXP (ARBvp 2.14.5.9): (2^floor(t), t - floor(t), 2^t, 1).\n"
      "vec4 arb_exp(float t) {{\n"
      "  float f = floor(t);\n"
      "  return vec4(exp2(f), {}, exp2(t), 1.0);\n"
      "}}\n",
      frac);
}

std::string LogText(const Context& ctx) {
  std::string a = ctx.Mutated(Mutation::LogNoAbs) ? "t" : "abs(t)";
  return fmt::format(
      "// LOG (ARBvp 2.14.5.14): (floor(log2|t|), |t| / 2^floor(log2|t|), log2|t|, 1). The\n"
      "// exponent is corrected where log2 rounds across an integer: the mantissa is in [1, 2).\n"
      "vec4 arb_log(float t) {{\n"
      "  float a = {};\n"
      "  float e = floor(log2(a));\n"
      "  float m = a / exp2(e);\n"
      "  if (m >= 2.0) {{\n"
      "    e += 1.0;\n"
      "    m *= 0.5;\n"
      "  }}\n"
      "  if (m < 1.0) {{\n"
      "    e -= 1.0;\n"
      "    m *= 2.0;\n"
      "  }}\n"
      "  return vec4(e, m, log2(a), 1.0);\n"
      "}}\n",
      a);
}

const char* kHalfText =
    "// state.light[n].half (ARBvp table X.3.3): (normalize(P + (0, 0, 1)), 1) with P the unit\n"
    "// vector from the eye to the light (xyz / w for a local light).\n"
    "vec4 arb_half(vec4 p) {\n"
    "  vec3 d = p.w != 0.0 ? p.xyz / p.w : p.xyz;\n"
    "  return vec4(normalize(normalize(d) + vec3(0.0, 0.0, 1.0)), 1.0);\n"
    "}\n";

// The vec2, vec3 and vec4 forms of a float function, component by component.
std::string VectorForms(const std::string& type, const std::string& name) {
  std::string out;
  for (int n = 2; n <= 4; ++n) {
    std::string parts;
    for (int c = 0; c < n; ++c) parts += fmt::format("{}{}(v.{})", c ? ", " : "", name, "xyzw"[c]);
    out += fmt::format("{0}{1} {2}(vec{1} v) {{ return {0}{1}({3}); }}\n", type, n, name, parts);
  }
  return out;
}

// fp16 rounding, exact in float32: every step scales by a power of two. NaN is tested with
// x != x (GLSL's isnan idiom, which compilers keep; they may rewrite !(a > 0) as a <= 0).
std::string Fp16Text() {
  return "// fp16 (NV_fragment_program 3.11.4.1-2): the nearest half float, ties to even, with\n"
         "// fp16 denormals (steps of 2^-24 below 2^-14); |x| >= 65520 rounds to infinity;\n"
         "// NaN, infinities and zeros are unchanged. Exact: every scaling is by a power of 2.\n"
         "float arb_fp16(float x) {\n"
         "  float a = abs(x);\n"
         "  if (x != x || a == 0.0) return x;\n"
         "  if (a >= 65520.0) return x * 1.0e30 * 1.0e30;\n"
         "  float ulp = 1.0 / 16777216.0;\n"
         "  float scale = 16777216.0;\n"
         "  float limit = 1.0 / 8192.0;\n"
         "  for (int i = 0; i < 29; ++i) {\n"
         "    if (a >= limit) {\n"
         "      ulp *= 2.0;\n"
         "      scale *= 0.5;\n"
         "      limit *= 2.0;\n"
         "    }\n"
         "  }\n"
         "  float q = a * scale;\n"
         "  float f = floor(q);\n"
         "  float d = q - f;\n"
         "  if (d > 0.5 || (d == 0.5 && fract(f * 0.5) != 0.0)) f += 1.0;\n"
         "  return (x < 0.0 ? -f : f) * ulp;\n"
         "}\n" +
         VectorForms("vec", "arb_fp16");
}

std::string Fx12Text(bool clamp) {
  std::string out =
      "// fx12 (NV_fragment_program 3.11.4.2): s1.10 fixed point. Values below -2048/1024 and\n"
      "// above +2047/1024 (infinities too) become those, NaN becomes 0, and the rest the\n"
      "// nearest multiple of 1/1024, a tie to the even one.\n"
      "float arb_fx12(float x) {\n"
      "  if (x != x) return 0.0;\n";
  if (clamp) {
    out +=
        "  if (x < -2.0) return -2.0;\n"
        "  if (x > 1.9990234375) return 1.9990234375;\n";
  }
  return out +
         "  return arb_round_even(x * 1024.0) * 0.0009765625;\n"
         "}\n" +
         VectorForms("vec", "arb_fx12");
}

std::string RoundEvenText() {
  return "// ARR (NV_vertex_program2_option 2.14.5.29): the nearest integer, a tie to the even "
         "one.\n"
         "float arb_round_even(float x) {\n"
         "  float f = floor(x);\n"
         "  float d = x - f;\n"
         "  return d > 0.5 || (d == 0.5 && fract(f * 0.5) != 0.0) ? f + 1.0 : f;\n"
         "}\n" +
         VectorForms("vec", "arb_round_even");
}

// 2^-64 and 2^64, exactly.
constexpr float kRccMin = 5.42101086242752217e-20f;
constexpr float kRccMax = 1.8446744073709552e19f;

// The positive branch is taken for every finite positive x: 1/x below 2^-126 is a denormal,
// which GPUs flush to 0. NaN is tested last, outside any select a compiler could turn into
// min and max (which drop NaN).
std::string RccText() {
  return fmt::format(
      "// RCC (NV_vertex_program2_option 2.14.5.33): 1/x clamped to [2^-64, 2^64] when it is\n"
      "// positive, else to [-2^64, -2^-64]; NaN stays NaN.\n"
      "float arb_rcc(float x) {{\n"
      "  float r = 1.0 / x;\n"
      "  if (r > 0.0 || (x > 0.0 && x <= {2})) return clamp(r, {0}, {1});\n"
      "  if (r <= 0.0) return clamp(r, -{1}, -{0});\n"
      "  return r;\n"
      "}}\n",
      FormatFloat(kRccMin), FormatFloat(kRccMax), FormatFloat(std::numeric_limits<float>::max()));
}

// NaN is tested first, with x != x (GLSL's isnan idiom, which compilers keep): Mesa rewrites
// -|a| < 0 into a != 0, which NaN passes.
std::string SsgText(const Context& ctx) {
  return fmt::format(
      "// SSG (NV_vertex_program2_option 2.14.5.41): 1, 0 or -1 as x is above, at or below 0;\n"
      "// NaN stays NaN (GLSL's sign() leaves it undefined).\n"
      "float arb_ssg(float x) {{ return x != x ? x : (x {} 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0)); "
      "}}\n",
      ctx.Mutated(Mutation::SsgZeroPositive) ? ">=" : ">");
}

std::string RflText(const Context& ctx) {
  return fmt::format(
      "// RFL (NV_fragment_program_option 3.11.5.36): the reflection of d about the axis a,\n"
      "// 2 (a . d) / (a . a) * a - d, in the specification's order of operations.\n"
      "vec3 arb_rfl(vec3 a, vec3 d) {{\n"
      "  float k = {}dot(a, d) / dot(a, a);\n"
      "  return k * a - d;\n"
      "}}\n",
      ctx.Mutated(Mutation::RflNoDouble) ? "" : "2.0 * ");
}

// The PK* and UP* conversions (NV_fragment_program_option 3.11.5), with GLSL 3.30's bit
// operations: fp16 with round-to-nearest-even (a conversion that is not exact may take either
// neighbour, and verify does not compare it), integer fields rounded from their scaled value.
constexpr const char* kPackText =
    "// PK2H / UP2H: a float's fp16 bits, rounded to nearest even (overflow to infinity);\n"
    "// the float of fp16 bits.\n"
    "uint arb_half_bits(float f) {\n"
    "  uint b = floatBitsToUint(f);\n"
    "  uint sign = (b >> 16) & 0x8000u;\n"
    "  uint m = b & 0x7FFFFFu;\n"
    "  int e = int((b >> 23) & 0xFFu);\n"
    "  if (e == 255) return sign | 0x7C00u | (m != 0u ? 0x200u : 0u);\n"
    "  int h = e - 112;  // the fp16 exponent\n"
    "  if (h >= 31) return sign | 0x7C00u;\n"
    "  uint shift = 13u;\n"
    "  uint bits = (uint(max(h, 0)) << 10) | (m >> 13);\n"
    "  if (h <= 0) {  // below fp16's normal range: the implicit 1 joins the fraction\n"
    "    if (h < -10) return sign;\n"
    "    m |= 0x800000u;\n"
    "    shift = uint(14 - h);\n"
    "    bits = m >> shift;\n"
    "  }\n"
    "  uint rest = m & ((1u << shift) - 1u);\n"
    "  uint half_way = 1u << (shift - 1u);\n"
    "  if (rest > half_way || (rest == half_way && (bits & 1u) != 0u)) bits += 1u;\n"
    "  return sign | bits;\n"
    "}\n"
    "float arb_half_value(uint h) {\n"
    "  uint e = (h >> 10) & 0x1Fu;\n"
    "  uint m = h & 0x3FFu;\n"
    "  float v = e == 0u ? float(m) * exp2(-24.0)\n"
    "                    : uintBitsToFloat(((e == 31u ? 255u : e + 112u) << 23) | (m << 13));\n"
    "  return (h & 0x8000u) != 0u ? -v : v;\n"
    "}\n"
    "// PK2US, PK4B, PK4UB: round(scale * clamp(v, lo, hi) + offset).\n"
    "uint arb_pack_field(float v, float lo, float hi, float scale, float offset) {\n"
    "  return uint(floor(scale * clamp(v, lo, hi) + offset + 0.5));\n"
    "}\n"
    "// UP2US, UP4B, UP4UB: field n of `width` bits, (field + offset) / divisor.\n"
    "float arb_unpack_field(uint bits, uint n, uint width, float offset, float divisor) {\n"
    "  uint field = (bits >> (n * width)) & ((1u << width) - 1u);\n"
    "  return (float(field) + offset) / divisor;\n"
    "}\n";

}  // namespace

std::string HelperText(const Context& ctx, Helper helper) {
  switch (helper) {
    case Helper::Lit:
      return LitText(ctx);
    case Helper::Exp:
      return ExpText(ctx);
    case Helper::Log:
      return LogText(ctx);
    case Helper::Half:
      return kHalfText;
    case Helper::Fp16:
      return Fp16Text();
    case Helper::Fx12:
      return Fx12Text(!ctx.Mutated(Mutation::Fx12ClampDropped));
    case Helper::RoundEven:
      return RoundEvenText();
    case Helper::Rcc:
      return RccText();
    case Helper::Rfl:
      return RflText(ctx);
    case Helper::Ssg:
      return SsgText(ctx) + VectorForms("vec", "arb_ssg");
    case Helper::Pack:
      return kPackText;
  }
  return "";
}

std::string RelativeReaderName(const Context& ctx, int var) {
  return "arb_read_" + ctx.var_names[static_cast<size_t>(var)];
}

// ARB leaves an out-of-range relative read undefined; the translation defines it as
// vec4(0.0) (what Mesa's drivers read), and the binding map says so.
std::string RelativeReaderText(const Context& ctx, int var) {
  std::string name = ctx.var_names[static_cast<size_t>(var)];
  int size = static_cast<int>(ctx.program.vars[static_cast<size_t>(var)].bindings.size());
  // An array of consecutive program.env or program.local entries is a stretch of their
  // uniform array, which an ES 1.00 vertex shader may index by any expression (Appendix A.5).
  const std::vector<Binding>& bindings = ctx.program.vars[static_cast<size_t>(var)].bindings;
  const BindingKind kind = bindings.front().kind;
  bool stretch =
      ctx.IsVertex() && (kind == BindingKind::ProgramEnv || kind == BindingKind::ProgramLocal);
  for (size_t i = 0; stretch && i < bindings.size(); ++i) {
    stretch = bindings[i].kind == kind &&
              bindings[i].index == bindings.front().index + static_cast<int32_t>(i);
  }
  if (ctx.target.id == EmitTarget::Es100 && stretch) {
    return fmt::format(
        "// {0}[A0.x + k]: program.{3}[{4} + A0.x + k]; a read outside {0}[0..{2}] gives\n"
        "// vec4(0.0) (undefined in ARB).\n"
        "vec4 {1}(int arb_i) {{\n"
        "  if (arb_i < 0 || arb_i > {2}) return vec4(0.0);\n"
        "  return {5}[{4} + arb_i];\n"
        "}}\n",
        name, RelativeReaderName(ctx, var), size - 1,
        kind == BindingKind::ProgramEnv ? "env" : "local", bindings.front().index,
        EnvName(ctx, kind == BindingKind::ProgramLocal));
  }
  if (ctx.target.id == EmitTarget::Es100) {
    // ES 1.00 indexes arrays other than uniforms by constant index expressions only
    // (Appendix A.5): one test per element.
    std::string tests;
    for (int i = 0; i < size; ++i) {
      tests += fmt::format("  if (arb_i == {0}) return {1}[{0}];\n", i, name);
    }
    return fmt::format(
        "// {0}[A0.x + k]: a read outside {0}[0..{2}] gives vec4(0.0) (undefined in ARB).\n"
        "vec4 {1}(int arb_i) {{\n{3}  return vec4(0.0);\n}}\n",
        name, RelativeReaderName(ctx, var), size - 1, tests);
  }
  return fmt::format(
      "// {0}[A0.x + k]: a read outside {0}[0..{2}] gives vec4(0.0) (undefined in ARB).\n"
      "vec4 {1}(int arb_i) {{\n"
      "  if (arb_i < 0 || arb_i > {2}) return vec4(0.0);\n"
      "  return {0}[arb_i];\n"
      "}}\n",
      name, RelativeReaderName(ctx, var), size - 1);
}

}  // namespace arbiter::arbvp::emit
