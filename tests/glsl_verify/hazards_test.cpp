// glsl::FindHazards: each kind of operation GLSL leaves undefined for some operands, found at
// its operator or function name, in source order; atan of one argument and constant-index
// accesses are not hazards.
#include "arbiter/glsl/hazards.h"

#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "arbiter/compiler/diagnostic.h"

namespace arbiter::glsl {
namespace {

struct Found {
  HazardKind kind;
  uint32_t line;
  uint32_t column;
  std::string text;  // the range's text
  int size = 0;

  bool operator==(const Found&) const = default;
};
void PrintTo(const Found& f, std::ostream* out) {
  *out << GetHazardInfo(f.kind).name << " " << f.line << ":" << f.column << " '" << f.text << "' "
       << f.size;
}

std::vector<Found> Hazards(Stage stage, const std::string& text) {
  compiler::SourceFile file("h.vert", text);
  compiler::DiagnosticSink sink(0);
  EXPECT_TRUE(CheckShader(stage, {&file}, {}, &sink).ok);
  std::vector<Found> out;
  for (const Hazard& h : FindHazards(stage, {&file})) {
    EXPECT_EQ(h.file, &file);
    if (h.file == nullptr) continue;
    const compiler::LineCol lc = file.Locate(h.range.begin);
    out.push_back({h.kind, lc.line, lc.column,
                   file.text().substr(h.range.begin, h.range.end - h.range.begin), h.size});
  }
  return out;
}

TEST(GlslHazards, EveryKindAtItsPlace) {
  const std::string text =
      "#version 120\n"
      "uniform float a, b;\n"
      "uniform vec3 v;\n"
      "uniform int i;\n"
      "uniform float w[3];\n"
      "void main() {\n"
      "  float x = a / b;\n"                                                     // 7
      "  x /= b;\n"                                                              // 8
      "  x += mod(a, b) + pow(a, b) + log(a) + log2(b);\n"                       // 9
      "  x += sqrt(a) + inversesqrt(b) + asin(a) + acos(b);\n"                   // 10
      "  x += atan(a, b) + atan(a) + normalize(v).x;\n"                          // 11
      "  x += clamp(a, b, 1.0) + smoothstep(a, b, 0.5) + w[i] + w[1] + v[i];\n"  // 12
      "  gl_Position = vec4(x);\n"
      "}\n";
  using K = HazardKind;
  const std::vector<Found> want = {
      {K::Division, 7, 15, "/"},     {K::Division, 8, 5, "/="},
      {K::Mod, 9, 8, "mod"},         {K::Pow, 9, 20, "pow"},
      {K::Log, 9, 32, "log"},        {K::Log, 9, 41, "log2"},
      {K::Sqrt, 10, 8, "sqrt"},      {K::InverseSqrt, 10, 18, "inversesqrt"},
      {K::AsinAcos, 10, 35, "asin"}, {K::AsinAcos, 10, 45, "acos"},
      {K::Atan, 11, 8, "atan"},      {K::Normalize, 11, 31, "normalize"},
      {K::Clamp, 12, 8, "clamp"},    {K::Smoothstep, 12, 27, "smoothstep"},
      {K::Index, 12, 52, "[", 3},    {K::Index, 12, 66, "[", 3},
  };
  EXPECT_EQ(Hazards(Stage::Vertex, text), want);
}

TEST(GlslHazards, NestedCallsAreEachFound) {
  const std::string text =
      "void main() {\n"
      "  gl_FragColor = vec4(pow(sqrt(gl_Color.x), log(gl_Color.y)));\n"
      "}\n";
  using K = HazardKind;
  const std::vector<Found> want = {
      {K::Pow, 2, 23, "pow"}, {K::Sqrt, 2, 27, "sqrt"}, {K::Log, 2, 45, "log"}};
  EXPECT_EQ(Hazards(Stage::Fragment, text), want);
}

TEST(GlslHazards, LookupsWithUndefinedCoordinates) {
  const std::string text =
      "uniform sampler2D s;\n"
      "uniform samplerCube c;\n"
      "void main() {\n"
      "  gl_FragColor = texture2DProj(s, gl_TexCoord[0]) + textureCube(c, gl_TexCoord[1].xyz)\n"
      "      + texture2D(s, gl_TexCoord[2].xy);\n"
      "}\n";
  using K = HazardKind;
  const std::vector<Found> want = {{K::Projection, 4, 18, "texture2DProj"},
                                   {K::CubeFace, 4, 53, "textureCube"}};
  EXPECT_EQ(Hazards(Stage::Fragment, text), want);
}

TEST(GlslHazards, InfoNamesTheSpecification) {
  for (const HazardInfo& info : AllHazards()) {
    EXPECT_EQ(&GetHazardInfo(info.kind), &info);
    EXPECT_TRUE(info.spec.starts_with("GLSL") || info.spec.starts_with("OpenGL")) << info.name;
    EXPECT_FALSE(info.what.empty());
  }
}

}  // namespace
}  // namespace arbiter::glsl
