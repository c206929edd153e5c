// SPIR-V: validated with SPIRV-Tools, translated to HLSL and MSL with SPIRV-Cross's C API.
#include <spirv_cross_c.h>

#include <spirv-tools/libspirv.hpp>
#include <string>

#include "arbiter/targets/targets.h"
#include "messages.h"

namespace arbiter::targets {
namespace {

// HLSL shader model 5.0: what fxc and Direct3D 11 (feature level 11_0) take; ARB programs need
// nothing of 5.1 or 6.x (resource spaces, wave operations, 16-bit types).
constexpr unsigned kHlslShaderModel = 50;

void AddCrossError(std::vector<Message>* messages, const char* error) {
  std::string text = error != nullptr ? error : "unknown error";
  // SPIRV-Cross names the built-in by its number.
  if (text == "Unsupported builtin in HLSL: 1") text += " (PointSize: Direct3D 11 has none)";
  AddMessage(messages, Message::Severity::Error, "spirv-cross", 0, std::move(text));
}

void CrossErrorCallback(void* user, const char* error) {
  AddCrossError(static_cast<std::vector<Message>*>(user), error);
}

// The context of one translation, destroyed with everything SPIRV-Cross allocated.
class CrossContext {
 public:
  explicit CrossContext(std::vector<Message>* messages) : messages_(messages) {
    if (spvc_context_create(&context_) != SPVC_SUCCESS) {
      context_ = nullptr;
      AddCrossError(messages_, "cannot create a context");
      return;
    }
    spvc_context_set_error_callback(context_, CrossErrorCallback, messages_);
  }
  ~CrossContext() {
    if (context_ != nullptr) spvc_context_destroy(context_);
  }
  CrossContext(const CrossContext&) = delete;
  CrossContext& operator=(const CrossContext&) = delete;

  // A compiler of `backend` for `spirv` with its options object, or false (the error added).
  bool Create(std::span<const uint32_t> spirv, spvc_backend backend) {
    if (context_ == nullptr) return false;
    spvc_parsed_ir ir = nullptr;
    return spvc_context_parse_spirv(context_, spirv.data(), spirv.size(), &ir) == SPVC_SUCCESS &&
           spvc_context_create_compiler(context_, backend, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                        &compiler_) == SPVC_SUCCESS &&
           spvc_compiler_create_compiler_options(compiler_, &options_) == SPVC_SUCCESS;
  }

  spvc_compiler compiler() const { return compiler_; }
  spvc_compiler_options options() const { return options_; }

  // Installs the options and compiles into `out`.
  bool Compile(std::string* out) {
    const char* source = nullptr;
    if (spvc_compiler_install_compiler_options(compiler_, options_) != SPVC_SUCCESS ||
        spvc_compiler_compile(compiler_, &source) != SPVC_SUCCESS) {
      return false;
    }
    *out = source;
    return true;
  }

 private:
  std::vector<Message>* messages_;
  spvc_context context_ = nullptr;
  spvc_compiler compiler_ = nullptr;
  spvc_compiler_options options_ = nullptr;
};

// MSL resource indices: buffer, texture and sampler B for the Vulkan binding B of every uniform
// block and sampler (their descriptor set kept), push constants at kMslPushConstantBuffer.
bool BindMslResources(spvc_compiler compiler) {
  spvc_resources resources = nullptr;
  if (spvc_compiler_create_shader_resources(compiler, &resources) != SPVC_SUCCESS) return false;
  SpvExecutionModel model = spvc_compiler_get_execution_model(compiler);
  for (spvc_resource_type type :
       {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, SPVC_RESOURCE_TYPE_STORAGE_BUFFER,
        SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, SPVC_RESOURCE_TYPE_SEPARATE_IMAGE,
        SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS}) {
    const spvc_reflected_resource* list = nullptr;
    size_t count = 0;
    if (spvc_resources_get_resource_list_for_type(resources, type, &list, &count) != SPVC_SUCCESS) {
      return false;
    }
    for (size_t i = 0; i < count; ++i) {
      spvc_msl_resource_binding binding;
      spvc_msl_resource_binding_init(&binding);
      binding.stage = model;
      binding.desc_set =
          spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
      binding.binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
      binding.msl_buffer = binding.msl_texture = binding.msl_sampler = binding.binding;
      if (spvc_compiler_msl_add_resource_binding(compiler, &binding) != SPVC_SUCCESS) return false;
    }
  }
  spvc_msl_resource_binding push;
  spvc_msl_resource_binding_init(&push);
  push.stage = model;
  push.desc_set = SPVC_MSL_PUSH_CONSTANT_DESC_SET;
  push.binding = SPVC_MSL_PUSH_CONSTANT_BINDING;
  push.msl_buffer = kMslPushConstantBuffer;
  return spvc_compiler_msl_add_resource_binding(compiler, &push) == SPVC_SUCCESS;
}

}  // namespace

bool ValidateSpirv(std::span<const uint32_t> spirv, std::vector<Message>* messages) {
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_0);
  tools.SetMessageConsumer([messages](spv_message_level_t level, const char*,
                                      const spv_position_t& position, const char* text) {
    bool error =
        level == SPV_MSG_FATAL || level == SPV_MSG_INTERNAL_ERROR || level == SPV_MSG_ERROR;
    AddMessage(messages, error ? Message::Severity::Error : Message::Severity::Warning, "spirv-val",
               0, "instruction " + std::to_string(position.index) + ": " + (text ? text : ""));
  });
  if (spirv.empty()) {
    AddMessage(messages, Message::Severity::Error, "spirv-val", 0, "the module is empty");
    return false;
  }
  return tools.Validate(spirv.data(), spirv.size(), spvtools::ValidatorOptions());
}

bool SpirvToHlsl(std::span<const uint32_t> spirv, std::string* hlsl,
                 std::vector<Message>* messages) {
  if (!ValidateSpirv(spirv, messages)) return false;
  CrossContext cross(messages);
  if (!cross.Create(spirv, SPVC_BACKEND_HLSL)) return false;
  spvc_compiler_options_set_uint(cross.options(), SPVC_COMPILER_OPTION_HLSL_SHADER_MODEL,
                                 kHlslShaderModel);
  // Push constants: a constant buffer at a fixed register (SPIRV-Cross leaves it unbound).
  spvc_hlsl_resource_binding push;
  spvc_hlsl_resource_binding_init(&push);
  push.stage = spvc_compiler_get_execution_model(cross.compiler());
  push.desc_set = SPVC_HLSL_PUSH_CONSTANT_DESC_SET;
  push.binding = SPVC_HLSL_PUSH_CONSTANT_BINDING;
  push.cbv.register_binding = kHlslPushConstantRegister;
  return spvc_compiler_hlsl_add_resource_binding(cross.compiler(), &push) == SPVC_SUCCESS &&
         cross.Compile(hlsl);
}

bool SpirvToMsl(std::span<const uint32_t> spirv, std::string* msl, std::vector<Message>* messages) {
  if (!ValidateSpirv(spirv, messages)) return false;
  CrossContext cross(messages);
  if (!cross.Create(spirv, SPVC_BACKEND_MSL)) return false;
  spvc_compiler_options_set_uint(cross.options(), SPVC_COMPILER_OPTION_MSL_VERSION,
                                 SPVC_MAKE_MSL_VERSION(2, 0, 0));
  spvc_compiler_options_set_uint(cross.options(), SPVC_COMPILER_OPTION_MSL_PLATFORM,
                                 SPVC_MSL_PLATFORM_MACOS);
  return BindMslResources(cross.compiler()) && cross.Compile(msl);
}

}  // namespace arbiter::targets
