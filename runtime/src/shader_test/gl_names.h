// GL enum names as shader tests spell them ("GL_DEPTH_TEST", "GL_TRIANGLE_FAN"): one table
// for every command that takes an enum.
#pragma once

#include <GL/gl.h>

#include <string_view>

namespace arbiter::runtime::shader_test {

// The value of a GL enum name; false when the table does not know it.
bool GlEnumByName(std::string_view name, GLenum* value);

}  // namespace arbiter::runtime::shader_test
