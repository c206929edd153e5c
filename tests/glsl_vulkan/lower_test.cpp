// The lowering of GLSL 1.10/1.20 to Vulkan GLSL 4.50 (glsl/lower_vulkan.h): the produced text
// of whole shaders, the renamed identifiers, the refusals, and that glslang compiles it.
#include <gtest/gtest.h>

#include "arbiter/glsl/lower_vulkan.h"

namespace arbiter::glsl {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The built-in state becomes uniforms of renamed types, attributes and varyings plain
// globals, ftransform() the product, main arb_main; reserved names get arb_u_; a
// redeclaration of a built-in ("invariant gl_Position;") is dropped.
TEST(LowerVulkanTest, VertexShaderText) {
  const LoweredShader l =
      LowerForVulkan(Stage::Vertex,
                     "#version 120\n"
                     "attribute vec4 texture;\n"
                     "varying vec3 n;\n"
                     "uniform float sample[2];\n"
                     "invariant gl_Position;\n"
                     "void main() {\n"
                     "  gl_Position = ftransform();\n"
                     "  n = gl_NormalMatrix * gl_Normal * sample[1] + texture.xyz;\n"
                     "  gl_FrontColor = gl_LightSource[1].diffuse;\n"
                     "}\n");
  ASSERT_EQ(l.not_applicable, "");
  EXPECT_TRUE(
      l.text.starts_with("#version 450\nstruct arb_gl_LightSourceParameters { vec4 "
                         "ambient; vec4 diffuse; vec4 specular; vec4 position; vec4 "
                         "halfVector; vec3 spotDirection; float spotExponent;"))
      << l.text;
  EXPECT_TRUE(Contains(l.text,
                       "uniform arb_gl_LightSourceParameters arb_gl_LightSource[8];\n"
                       "uniform mat4 arb_gl_ModelViewProjectionMatrix;\n"
                       "uniform mat3 arb_gl_NormalMatrix;\n"
                       "vec4 arb_gl_Vertex;\nvec3 arb_gl_Normal;\n"))
      << l.text;
  EXPECT_TRUE(Contains(l.text, "const int arb_gl_MaxLights = 8;\n")) << l.text;
  EXPECT_TRUE(l.text.ends_with(
      " vec4 arb_u_texture;\n"
      " vec3 n;\n"
      "uniform float arb_u_sample[2];\n"
      " \n"
      "void arb_main(){\n"
      "  arb_gl_Position = (arb_gl_ModelViewProjectionMatrix * arb_gl_Vertex);\n"
      "  n = arb_gl_NormalMatrix * arb_gl_Normal * arb_u_sample[1]+ arb_u_texture . xyz;\n"
      "  arb_gl_FrontColor = arb_gl_LightSource[1]. diffuse;\n"
      "}\n"))
      << l.text;
  EXPECT_EQ(l.state, (std::vector<std::string>{"gl_LightSource", "gl_ModelViewProjectionMatrix",
                                               "gl_NormalMatrix"}));
  CompiledPair compiled;
  std::string error;
  ASSERT_TRUE(CompileLoweredPair(l.text + "void main() { arb_main(); }\n", "", &compiled, &error))
      << error;
  EXPECT_FALSE(compiled.vertex.empty());
  bool sample = false;
  for (const CompiledUniform& u : compiled.uniforms) {
    if (u.name != "arb_u_sample[0]") continue;
    sample = true;
    EXPECT_EQ(u.array_size, 2);
    EXPECT_EQ(u.array_stride, 16);  // std140
  }
  EXPECT_TRUE(sample);
}

// A shadow lookup returns vec4 by the sampler's depth mode selector; a variable named like a
// built-in function, and a word 4.50 reserves, are renamed; gl_FragCoord is the main's.
TEST(LowerVulkanTest, FragmentShaderText) {
  const LoweredShader l =
      LowerForVulkan(Stage::Fragment,
                     "uniform sampler2DShadow s;\n"
                     "varying vec4 filter;\n"
                     "void main() {\n"
                     "  float sin = 2.0;\n"
                     "  if (filter.x > sin) discard;\n"
                     "  gl_FragColor = shadow2DProj(s, filter) + gl_FragCoord;\n"
                     "}\n");
  ASSERT_EQ(l.not_applicable, "");
  EXPECT_EQ(l.shadow_samplers, (std::vector<std::string>{"s"}));
  EXPECT_TRUE(Contains(l.text, "uniform vec4 arb_depthmode_s;\n")) << l.text;
  EXPECT_TRUE(l.text.ends_with(
      "uniform sampler2DShadow s;\n"
      " vec4 arb_u_filter;\n"
      "void arb_main(){\n"
      "  float arb_u_sin = 2.0;\n"
      "  if(arb_u_filter . x > arb_u_sin)discard;\n"
      "  arb_gl_FragColor = arb_shadow(textureProj(s, arb_u_filter), arb_depthmode_s)+ "
      "arb_gl_FragCoord;\n"
      "}\n"))
      << l.text;
  CompiledPair compiled;
  std::string error;
  EXPECT_TRUE(CompileLoweredPair("", l.text + "void main() { arb_main(); }\n", &compiled, &error))
      << error;
}

TEST(LowerVulkanTest, Refusals) {
  const std::pair<const char*, const char*> cases[] = {
      {"#version 120\nuniform float k = 2.0;\nvoid main() { gl_FragColor = vec4(k); }\n",
       "not applicable: a uniform initializer (GLSL 1.20 4.3.5)"},
      {"float abs(float x) { return x; }\nvoid main() { gl_FragColor = vec4(abs(-1.0)); }\n",
       "not applicable: a redefinition of the built-in function abs"},
      {"struct A { struct B { struct C { float x; } c; } b; };\nuniform A a;\n"
       "void main() { gl_FragColor = vec4(a.b.c.x); }\n",
       "not applicable: a structure defined inside a structure inside a structure"},
      {"uniform vec4 c[];\nuniform vec4 c[4];\nvoid main() { gl_FragColor = c[1]; }\n",
       "not applicable: a uniform array declared without a size"},
      {"void main() { gl_FragColor = vec4(float(gl_MaxTextureImageUnits)); }\n",
       "not applicable: gl_MaxTextureImageUnits"},
      {"#extension GL_ARB_fragment_coord_conventions : enable\n"
       "layout(origin_upper_left) in vec4 gl_FragCoord;\nvoid main() { gl_FragColor = "
       "gl_FragCoord; }\n",
       "not applicable: #extension GL_ARB_fragment_coord_conventions"},
  };
  for (const auto& [text, reason] : cases) {
    const LoweredShader l = LowerForVulkan(Stage::Fragment, text);
    EXPECT_EQ(l.not_applicable, reason) << text;
    EXPECT_EQ(l.text, "");
  }
}

// GLSL 1.10 4.1.9: an array declared without a size takes the largest constant index used,
// plus one; 4.50 sizes no uniform implicitly, so the lowering writes that size.
TEST(LowerVulkanTest, ImplicitlySizedUniformArray) {
  const LoweredShader l = LowerForVulkan(
      Stage::Fragment, "uniform vec4 c[];\nvoid main() { gl_FragColor = c[0] + c[2]; }\n");
  ASSERT_EQ(l.not_applicable, "");
  EXPECT_TRUE(Contains(l.text, "uniform vec4 c[3];\n")) << l.text;
}

// 4.50 nests no structure definition: the inner one (named or not) moves before the outer.
TEST(LowerVulkanTest, NestedStructureDefinitions) {
  const LoweredShader l =
      LowerForVulkan(Stage::Fragment,
                     "struct A { struct B { float x; } b; struct { vec2 y; } n; };\n"
                     "uniform A a;\n"
                     "void main() { gl_FragColor = vec4(a.b.x, a.n.y, 1.0); }\n");
  ASSERT_EQ(l.not_applicable, "");
  EXPECT_TRUE(Contains(l.text,
                       "struct B { float x;};\nstruct arb_s_0 { vec2 y;};\n"
                       "struct A { B b;arb_s_0 n;};\n"))
      << l.text;
  CompiledPair compiled;
  std::string error;
  EXPECT_TRUE(CompileLoweredPair("", l.text + "void main() { arb_main(); }\n", &compiled, &error))
      << error;
}

TEST(LowerVulkanTest, LoweredIdentifier) {
  EXPECT_EQ(LoweredIdentifier("texture"), "arb_u_texture");
  EXPECT_EQ(LoweredIdentifier("sample"), "arb_u_sample");
  EXPECT_EQ(LoweredIdentifier("arb_x"), "arb_u_arb_x");
  EXPECT_EQ(LoweredIdentifier("gl_Color"), "arb_gl_Color");
  EXPECT_EQ(LoweredIdentifier("light"), "light");
  EXPECT_EQ(LoweredIdentifier("dot"), "dot");
}

}  // namespace
}  // namespace arbiter::glsl
