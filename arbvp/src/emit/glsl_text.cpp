// Literals and small expression builders for the emitted GLSL 1.10.
#include <fmt/format.h>

#include <cmath>

#include "emit/emit_context.h"

namespace arbiter::arbvp::emit {

// Enough digits to round-trip a float32, always with a '.' or an exponent (GLSL 1.10 has no
// 'f' suffix, and "1" would be an int). ARB source constants are finite (the parser rounds
// them to float32); an infinity could only come from an overflowing literal, which GLSL
// could not spell either, so it is written as the largest finite float.
std::string FormatFloat(float value) {
  if (std::isnan(value)) return "0.0";
  if (std::isinf(value)) return value > 0 ? "3.40282347e+38" : "-3.40282347e+38";
  // fmt's shortest representation that reads back as the same float32 ("0.7", not
  // "0.699999988"); at most 9 significant digits.
  std::string s = fmt::format("{}", value);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string VecType(int width) { return width == 1 ? "float" : fmt::format("vec{}", width); }

std::string Letters(const Comps& comps) {
  std::string out;
  for (int c : comps) out += "xyzw"[c];
  return out;
}

Comps AllComps() { return {0, 1, 2, 3}; }

Expr Select(const Expr& e4, const Comps& comps) {
  if (comps == AllComps() && e4.width == 4) return e4;
  std::string base = e4.atomic ? e4.text : "(" + e4.text + ")";
  return {base + "." + Letters(comps), static_cast<int>(comps.size()), true};
}

Expr Replicate(const Expr& scalar, int width) {
  if (width == 1) return scalar;
  return {fmt::format("{}({})", VecType(width), scalar.text), width, true};
}

Expr Construct(const std::vector<std::string>& components) {
  if (components.size() == 1) return {components[0], 1, false};
  std::string args;
  for (const std::string& c : components) args += (args.empty() ? "" : ", ") + c;
  int width = static_cast<int>(components.size());
  return {fmt::format("{}({})", VecType(width), args), width, true};
}

}  // namespace arbiter::arbvp::emit
