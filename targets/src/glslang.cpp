// glslang's front ends: GLSL of each dialect and HLSL checked, GLSL 4.50 compiled to SPIR-V.
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <climits>
#include <memory>
#include <optional>
#include <string>

#include "arbiter/targets/targets.h"
#include "messages.h"

namespace arbiter::targets {
namespace {

// The version and profile each dialect is, and whether it is parsed with Vulkan semantics;
// in GlslDialect's order.
struct DialectInfo {
  GlslDialect dialect;
  std::string_view name;  // arbiter translate's --target spelling
  int version;
  EProfile profile;
  bool vulkan;
  const char* directive;  // the #version line it takes, for the message when it differs
};

constexpr DialectInfo kDialects[] = {
    {GlslDialect::Glsl110, "glsl110", 110, ENoProfile, false, "#version 110"},
    {GlslDialect::Glsl120, "glsl120", 120, ENoProfile, false, "#version 120"},
    {GlslDialect::Glsl330Core, "glsl330", 330, ECoreProfile, false, "#version 330 core"},
    {GlslDialect::Es100, "es100", 100, EEsProfile, false, "#version 100"},
    {GlslDialect::Es300, "es300", 300, EEsProfile, false, "#version 300 es"},
    {GlslDialect::Vulkan450, "vk450", 450, ECoreProfile, true, "#version 450"},
};

const DialectInfo& Info(GlslDialect dialect) {
  for (const DialectInfo& d : kDialects) {
    if (d.dialect == dialect) return d;
  }
  return kDialects[0];
}

EShLanguage Language(Stage stage) {
  return stage == Stage::Vertex ? EShLangVertex : EShLangFragment;
}

// A shader parsed and linked alone; `program` is null when either step failed.
struct Parsed {
  std::unique_ptr<glslang::TShader> shader;
  std::unique_ptr<glslang::TProgram> program;  // declared after: destroyed first
};

// A shader of `language` over `text` (which must outlive its parse), for Vulkan 1.0 and SPIR-V
// 1.0 when `vulkan` names the source language; null (the error added) when the text is too long
// for glslang's int lengths.
std::unique_ptr<glslang::TShader> NewShader(const char* const* text, const int* length,
                                            EShLanguage language,
                                            std::optional<glslang::EShSource> vulkan,
                                            std::vector<Message>* messages) {
  EnsureGlslang();
  if (*length < 0) {
    AddMessage(messages, Message::Severity::Error, "glslang", 0, "the text is over 2 GiB");
    return nullptr;
  }
  auto shader = std::make_unique<glslang::TShader>(language);
  shader->setStringsWithLengths(text, length, 1);
  if (vulkan.has_value()) {
    shader->setEnvInput(*vulkan, language, glslang::EShClientVulkan, 100);
    shader->setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  }
  return shader;
}

int Length(std::string_view text) {
  return text.size() < INT_MAX ? static_cast<int>(text.size()) : -1;
}

// Parses and links `shader` (its strings and environment set); adds glslang's logs.
Parsed ParseAndLink(std::unique_ptr<glslang::TShader> shader, int default_version,
                    EShMessages rules, std::vector<Message>* messages) {
  Parsed out;
  bool parsed =
      shader->parse(GetDefaultResources(), default_version, ENoProfile, false, false, rules);
  AddGlslangLog(shader->getInfoLog(), messages);
  out.shader = std::move(shader);
  if (!parsed) return out;
  auto program = std::make_unique<glslang::TProgram>();
  program->addShader(out.shader.get());
  bool linked = program->link(rules);
  AddGlslangLog(program->getInfoLog(), messages);
  if (linked) out.program = std::move(program);
  return out;
}

// GLSL of `dialect`, parsed and linked, its #version checked against the dialect's.
Parsed ParseGlsl(std::string_view glsl, Stage stage, GlslDialect dialect,
                 std::vector<Message>* messages) {
  DialectInfo info = Info(dialect);
  EShLanguage language = Language(stage);
  const char* text = glsl.data();
  int length = Length(glsl);
  auto shader =
      NewShader(&text, &length, language,
                info.vulkan ? std::optional(glslang::EShSourceGlsl) : std::nullopt, messages);
  if (shader == nullptr) return {};
  EShMessages rules =
      info.vulkan ? static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules) : EShMsgDefault;
  // Without #version glslang takes 1.10 (ES: 1.00), as GL does.
  int default_version = info.profile == EEsProfile ? 100 : 110;
  Parsed out = ParseAndLink(std::move(shader), default_version, rules, messages);
  if (out.program != nullptr) {
    const glslang::TIntermediate* ir = out.program->getIntermediate(language);
    // Below 1.50 glslang's desktop profile is ENoProfile; from 1.50 on "core" is the default.
    if (ir->getVersion() != info.version || ir->getProfile() != info.profile) {
      AddMessage(messages, Message::Severity::Error, "glslang", 0,
                 std::string("the shader is not ") + info.directive + " (its #version is " +
                     std::to_string(ir->getVersion()) +
                     (ir->getProfile() == EEsProfile              ? " es"
                      : ir->getProfile() == ECompatibilityProfile ? " compatibility"
                                                                  : "") +
                     ")");
      out.program.reset();
    }
  }
  return out;
}

}  // namespace

std::optional<GlslDialect> GlslDialectNamed(std::string_view name) {
  for (const DialectInfo& d : kDialects) {
    if (d.name == name) return d.dialect;
  }
  return std::nullopt;
}

bool ValidateGlsl(std::string_view glsl, Stage stage, GlslDialect dialect,
                  std::vector<Message>* messages) {
  return ParseGlsl(glsl, stage, dialect, messages).program != nullptr;
}

bool CompileGlslToSpirv(std::string_view glsl, Stage stage, std::vector<uint32_t>* spirv,
                        std::vector<Message>* messages) {
  Parsed parsed = ParseGlsl(glsl, stage, GlslDialect::Vulkan450, messages);
  if (parsed.program == nullptr) return false;
  std::vector<uint32_t> words;
  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;
  options.generateDebugInfo = false;
  options.disableOptimizer = true;
  options.validate = false;  // ValidateSpirv below, with its messages
  glslang::GlslangToSpv(*parsed.program->getIntermediate(Language(stage)), words, &logger,
                        &options);
  std::string log = logger.getAllMessages();
  if (!log.empty()) AddMessage(messages, Message::Severity::Warning, "glslang", 0, log);
  if (!ValidateSpirv(words, messages)) return false;
  *spirv = std::move(words);
  return true;
}

bool ValidateHlsl(std::string_view hlsl, Stage stage, std::vector<Message>* messages) {
  EShLanguage language = Language(stage);
  const char* text = hlsl.data();
  int length = Length(hlsl);
  auto shader = NewShader(&text, &length, language, glslang::EShSourceHlsl, messages);
  if (shader == nullptr) return false;
  shader->setEntryPoint("main");
  auto rules = static_cast<EShMessages>(EShMsgReadHlsl | EShMsgSpvRules | EShMsgVulkanRules);
  Parsed parsed = ParseAndLink(std::move(shader), 100, rules, messages);
  if (parsed.program == nullptr) return false;
  // glslang's HLSL link only warns when the entry point is missing.
  if (parsed.program->getIntermediate(language)->getNumEntryPoints() == 0) {
    AddMessage(messages, Message::Severity::Error, "glslang", 0, "no entry point main");
    return false;
  }
  return true;
}

}  // namespace arbiter::targets
