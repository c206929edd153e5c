// Helper functions the translation defines before main(): LIT, EXP, LOG and the light half
// vector written out as the specs' pseudo-code, and bounds-checked relative-address readers.
#include <fmt/format.h>

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
  return fmt::format(
      "// {0}[A0.x + k]: a read outside {0}[0..{2}] gives vec4(0.0) (undefined in ARB).\n"
      "vec4 {1}(int arb_i) {{\n"
      "  if (arb_i < 0 || arb_i > {2}) return vec4(0.0);\n"
      "  return {0}[arb_i];\n"
      "}}\n",
      name, RelativeReaderName(ctx, var), size - 1);
}

}  // namespace arbiter::arbvp::emit
