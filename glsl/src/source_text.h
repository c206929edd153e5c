// The text glslang is given: the user's source rewritten where glslang 12 reads GLSL 1.10
// differently, keeping every line and column of the user's tokens.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace arbiter::glsl {

// The source as glslang must see it: vertical tab and form feed blanked (1.10 3.1 counts
// them as white space), a lone carriage return made a line feed (3.1 ends lines at either),
// words that 1.10 does not reserve but glslang 12 does renamed (3.6), function bodies
// that redeclare a parameter nested one scope deeper (4.2), names longer than glslang
// takes shortened, and the qualifier of a varying or attribute structure declaration that
// declares no variable dropped.
std::string PrepareForGlslang(std::string_view text);
// The start of the name a name too long for glslang gets (then a hash, then blanks).
inline constexpr std::string_view kLongNamePrefix = "arbiter_long_name_";

// A name glslang is given in place of the user's, as long as it (function_names.h).
struct Rename {
  std::string glslang;
  std::string user;
};

// The user's spelling of glslang's text (a message, a symbol name): undoes the renaming, and
// the `renames` of one shader.
std::string RestoreSpelling(std::string_view text, std::span<const Rename> renames = {});

}  // namespace arbiter::glsl
