// The tables of the Vulkan lowering (lower_vulkan.h): what each built-in variable, constant,
// structure type and lookup function of GLSL 1.10/1.20 becomes in Vulkan GLSL 4.50, and the
// words 4.50 takes that a 1.10/1.20 shader may use as names.
#pragma once

#include <cstdint>
#include <string_view>

namespace arbiter::glsl::lower {

enum class BuiltinRole : uint8_t {
  Global,  // a private global the generated main feeds or reads ("vec4 arb_gl_Vertex;")
  State,   // built-in uniform state: a uniform of the default block
  Const,   // a built-in constant of Mesa's value
  Keep,    // 4.50 has it with the same meaning (gl_FrontFacing)
};

enum StageMask : uint8_t { Vertex = 1, Fragment = 2, BothStages = 3 };

struct BuiltinVariable {
  std::string_view name;  // "gl_LightSource"
  uint8_t stages;         // StageMask
  BuiltinRole role;
  std::string_view type;       // "vec4", "arb_gl_LightSourceParameters"; Const: "int"
  int array_size;              // 0: not an array
  std::string_view type_name;  // a structure type it needs ("gl_LightSourceParameters"), or ""
  int value;                   // Const: the value (Mesa's)
};

// By name; nullptr for a name the lowering does not handle (refused) or not a built-in.
const BuiltinVariable* FindBuiltinVariable(std::string_view name);

// The built-in structure types and their members in 4.50 syntax, by 1.10 name.
struct BuiltinStruct {
  std::string_view name;     // "gl_FogParameters"
  std::string_view members;  // "vec4 color; float density; ..."
};
const BuiltinStruct* FindBuiltinStruct(std::string_view name);

// A 1.10/1.20 lookup function and its 4.50 replacement.
struct LookupFunction {
  std::string_view name;         // "texture2DProj", "shadow2D"
  std::string_view replacement;  // "textureProj"
  bool shadow;                   // returns vec4 by the depth texture mode
};
const LookupFunction* FindLookupFunction(std::string_view name);

// Words of Vulkan GLSL 4.50 (keywords, reserved words, built-in functions) that are neither
// keywords nor built-in functions of GLSL 1.20: a shader's names that must be renamed.
bool IsReservedIn450(std::string_view word);

// A built-in function of GLSL 1.10 or 1.20 (chapter 8).
bool IsBuiltinFunction(std::string_view name);

// A keyword of GLSL 1.20 that 1.10 does not reserve ("centroid", "invariant", "mat2x3").
bool IsKeywordFrom120(std::string_view word);

}  // namespace arbiter::glsl::lower
