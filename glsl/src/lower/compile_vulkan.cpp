// CompileLoweredPair: lowered shaders to SPIR-V with glslang's relaxed Vulkan rules, and the
// layout of each stage's default uniform block from glslang's reflection. See lower_vulkan.h.
#include <fmt/format.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "arbiter/glsl/lower_vulkan.h"
#include "prepare.h"

namespace arbiter::glsl {
namespace {

// Samplers of the fragment stage are mapped from this binding on, past the vertex stage's.
constexpr unsigned kFragmentSamplerBase = 16;

std::string TypeName(const glslang::TType& t) {
  if (t.getBasicType() == glslang::EbtSampler) return "sampler";
  if (t.isMatrix()) return fmt::format("mat{}x{}", t.getMatrixCols(), t.getMatrixRows());
  const char* prefix = t.getBasicType() == glslang::EbtInt    ? "i"
                       : t.getBasicType() == glslang::EbtBool ? "b"
                                                              : "";
  if (t.getVectorSize() <= 1) {
    return t.getBasicType() == glslang::EbtInt    ? "int"
           : t.getBasicType() == glslang::EbtBool ? "bool"
                                                  : "float";
  }
  return fmt::format("{}vec{}", prefix, t.getVectorSize());
}

int RoundUp(int value, int to) { return (value + to - 1) / to * to; }

int Std140Align(const glslang::TType& t);
int Std140Size(const glslang::TType& t);

// The stride of an array of `element`s: its size, at a vec4's alignment at least.
int Std140Stride(const glslang::TType& element) {
  return RoundUp(Std140Size(element), RoundUp(Std140Align(element), 16));
}

int Std140Align(const glslang::TType& t) {
  if (t.isArray()) return RoundUp(Std140Align(glslang::TType(t, 0)), 16);
  if (t.isStruct()) {
    int align = 4;
    for (const glslang::TTypeLoc& m : *t.getStruct()) align = std::max(align, Std140Align(*m.type));
    return RoundUp(align, 16);
  }
  if (t.isMatrix()) return 16;  // columns as an array of vectors
  const int n = std::max(t.getVectorSize(), 1);
  return n == 1 ? 4 : n == 2 ? 8 : 16;
}

int Std140Size(const glslang::TType& t) {
  if (t.isArray()) return Std140Stride(glslang::TType(t, 0)) * t.getOuterArraySize();
  if (t.isStruct()) {
    int offset = 0;
    for (const glslang::TTypeLoc& m : *t.getStruct()) {
      offset = RoundUp(offset, Std140Align(*m.type)) + Std140Size(*m.type);
    }
    return RoundUp(offset, Std140Align(t));
  }
  if (t.isMatrix()) return 16 * t.getMatrixCols();
  return 4 * std::max(t.getVectorSize(), 1);
}

// The leaves of `t` at `offset` as GL names active uniforms: "w[0]" for an array of a basic
// type (with its size and stride), each element of an array of structures apart.
void Std140Members(const glslang::TType& t, const std::string& path, int offset, bool fragment,
                   std::vector<CompiledUniform>* out) {
  if (t.isStruct() && !t.isArray()) {
    int at = 0;
    for (const glslang::TTypeLoc& m : *t.getStruct()) {
      at = RoundUp(at, Std140Align(*m.type));
      std::string name(m.type->getFieldName().c_str());
      if (!path.empty()) name.insert(0, path + ".");
      Std140Members(*m.type, name, offset + at, fragment, out);
      at += Std140Size(*m.type);
    }
    return;
  }
  if (t.isArray()) {
    const glslang::TType element(t, 0);
    const int stride = Std140Stride(element);
    if (element.isStruct()) {
      for (int i = 0; i < t.getOuterArraySize(); ++i) {
        Std140Members(element, fmt::format("{}[{}]", path, i), offset + i * stride, fragment, out);
      }
      return;
    }
    CompiledUniform c;
    c.name = path + "[0]";
    c.type = TypeName(element);
    c.offset = offset;
    c.array_size = t.getOuterArraySize();
    c.array_stride = stride;
    c.fragment = fragment;
    out->push_back(std::move(c));
    return;
  }
  CompiledUniform c;
  c.name = path;
  c.type = TypeName(t);
  c.offset = offset;
  c.fragment = fragment;
  out->push_back(std::move(c));
}

// One stage compiled alone: its SPIR-V and its uniforms.
bool CompileStage(const std::string& text, bool fragment, CompiledPair* out, std::string* error) {
  const EShLanguage language = fragment ? EShLangFragment : EShLangVertex;
  glslang::TShader shader(language);
  const char* strings = text.c_str();
  const int length = static_cast<int>(text.size());
  shader.setStringsWithLengths(&strings, &length, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
  shader.setEnvInputVulkanRulesRelaxed();
  shader.setGlobalUniformBlockName(fragment ? "arb_fragment_uniforms" : "arb_vertex_uniforms");
  shader.setGlobalUniformSet(0);
  shader.setGlobalUniformBinding(fragment ? kFragmentUniformBinding : kVertexUniformBinding);
  shader.setAutoMapLocations(true);
  shader.setAutoMapBindings(true);
  if (fragment) {
    shader.setShiftBinding(glslang::EResSampler, kFragmentSamplerBase);
    shader.setShiftBinding(glslang::EResTexture, kFragmentSamplerBase);
  }
  const auto rules = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  const char* stage = fragment ? "fragment" : "vertex";
  if (!shader.parse(GetDefaultResources(), 450, ECoreProfile, false, false, rules)) {
    *error = fmt::format("glslang rejects the lowered {} shader: {}", stage, shader.getInfoLog());
    return false;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(rules) || !program.mapIO()) {
    *error =
        fmt::format("glslang cannot link the lowered {} shader: {}", stage, program.getInfoLog());
    return false;
  }
  if (!program.buildReflection(EShReflectionBasicArraySuffix | EShReflectionStrictArraySuffix |
                               EShReflectionAllBlockVariables)) {
    *error = fmt::format("glslang cannot reflect the lowered {} shader", stage);
    return false;
  }
  // glslang's reflection gives the default block's arrays of scalars packed offsets and
  // strides; the SPIR-V has std140's. The block's members are laid out here by std140 (GLSL
  // 4.50 7.6.2.2), and reflected where glslang reflects them as active.
  std::set<std::string> active;
  for (int i = 0; i < program.getNumUniformVariables(); ++i) {
    const glslang::TObjectReflection& u = program.getUniform(i);
    const glslang::TType* type = u.getType();
    // The engine's storage buffers are no uniforms.
    if (type == nullptr || type->getQualifier().storage == glslang::EvqBuffer) continue;
    if (type->getBasicType() != glslang::EbtSampler) {
      active.insert(u.name);
      continue;
    }
    CompiledUniform c;
    c.name = u.name;
    c.type = TypeName(*type);
    c.fragment = fragment;
    c.binding = u.getBinding();
    c.array_size = std::max(u.size, 1);
    out->uniforms.push_back(std::move(c));
  }
  const int binding = fragment ? kFragmentUniformBinding : kVertexUniformBinding;
  for (int b = 0; b < program.getNumUniformBlocks(); ++b) {
    const glslang::TObjectReflection& block = program.getUniformBlock(b);
    if (block.getBinding() != binding || block.getType() == nullptr) continue;
    (fragment ? out->fragment_block_size : out->vertex_block_size) = Std140Size(*block.getType());
    std::vector<CompiledUniform> members;
    Std140Members(*block.getType(), "", 0, fragment, &members);
    for (CompiledUniform& m : members) {
      if (active.count(m.name) > 0) out->uniforms.push_back(std::move(m));
    }
  }
  std::vector<uint32_t>& spirv = fragment ? out->fragment : out->vertex;
  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;
  options.validate = false;
  glslang::GlslangToSpv(*program.getIntermediate(language), spirv, &logger, &options);
  if (spirv.empty()) {
    *error = fmt::format("glslang made no SPIR-V of the lowered {} shader: {}", stage,
                         logger.getAllMessages());
    return false;
  }
  return true;
}

}  // namespace

bool CompileLoweredPair(const std::string& vertex, const std::string& fragment, CompiledPair* out,
                        std::string* error) {
  EnsureGlslang();
  *out = CompiledPair{};
  if (!vertex.empty() && !CompileStage(vertex, false, out, error)) return false;
  return fragment.empty() || CompileStage(fragment, true, out, error);
}

}  // namespace arbiter::glsl
