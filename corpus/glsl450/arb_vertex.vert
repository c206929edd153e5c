#version 450
// Shaped like the Vulkan translation of an ARB vertex program: the GL state it reads in a
// uniform block, program.local in push constants, vertex attributes and results at locations.
layout(std140, set = 0, binding = 0) uniform ArbVertexState {
  mat4 mvp;                 // state.matrix.mvp
  mat4 modelview_invtrans;  // state.matrix.modelview.invtrans
  vec4 light0_position;     // state.light[0].position
  vec4 light0_diffuse;      // state.lightprod[0].diffuse
  vec4 env[4];              // program.env[0..3]
} state;
layout(push_constant) uniform ArbVertexLocal {
  vec4 local[2];            // program.local[0..1]
} local;

layout(location = 0) in vec4 vertex_position;   // vertex.position
layout(location = 2) in vec4 vertex_normal;     // vertex.normal
layout(location = 3) in vec4 vertex_color;      // vertex.color
layout(location = 8) in vec4 vertex_texcoord0;  // vertex.texcoord[0]

layout(location = 0) out vec4 result_color;      // result.color
layout(location = 1) out vec4 result_texcoord0;  // result.texcoord[0]

void main() {
  vec4 R0, R1;
  // DP4 result.position.x, state.matrix.mvp.row[0], vertex.position; (and .y .z .w)
  gl_Position = vertex_position * state.mvp;
  // DP3 R0.x, state.matrix.modelview.invtrans.row[0], vertex.normal; (and .y .z)
  R0.xyz = (vertex_normal * state.modelview_invtrans).xyz;
  // DP3 R1.x, R0, state.light[0].position;
  R1.x = dot(R0.xyz, state.light0_position.xyz);
  // MAX R1.x, R1.x, 0; MAD result.color, R1.x, lightprod, vertex.color;
  R1.x = max(R1.x, 0.0);
  result_color = R1.xxxx * state.light0_diffuse + vertex_color;
  // MAD result.texcoord[0], vertex.texcoord[0], program.local[0], program.env[1];
  result_texcoord0 = vertex_texcoord0 * local.local[0] + state.env[1];
}
