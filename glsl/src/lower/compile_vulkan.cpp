// CompileLoweredPair: lowered shaders to SPIR-V with glslang's relaxed Vulkan rules, and the
// layout of each stage's default uniform block from glslang's reflection. See lower_vulkan.h.
#include <fmt/format.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <memory>

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
  for (int b = 0; b < program.getNumUniformBlocks(); ++b) {
    const glslang::TObjectReflection& block = program.getUniformBlock(b);
    if (block.getBinding() == (fragment ? kFragmentUniformBinding : kVertexUniformBinding)) {
      (fragment ? out->fragment_block_size : out->vertex_block_size) = block.size;
    }
  }
  for (int i = 0; i < program.getNumUniformVariables(); ++i) {
    const glslang::TObjectReflection& u = program.getUniform(i);
    const glslang::TType* type = u.getType();
    // The engine's storage buffers are no uniforms.
    if (type == nullptr || type->getQualifier().storage == glslang::EvqBuffer) continue;
    CompiledUniform c;
    c.name = u.name;
    c.type = TypeName(*type);
    c.fragment = fragment;
    if (type->getBasicType() == glslang::EbtSampler) {
      c.binding = u.getBinding();
      c.array_size = std::max(u.size, 1);
    } else {
      c.offset = u.offset;
      c.array_size = std::max(u.size, 1);
      // std140 (glslang's reflection gives arrays of scalars their packed stride): every
      // element of an array of scalars or vectors takes 16 bytes, of matrices 16 per column.
      c.array_stride = 16 * (type->isMatrix() ? type->getMatrixCols() : 1);
    }
    out->uniforms.push_back(std::move(c));
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
