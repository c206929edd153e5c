#version 450
// Shaped like the Vulkan translation of an ARB vertex program with relative addressing
// (ARL, program.env[A0.x + 2]), a matrix palette, fog and clip-distance results.
layout(std140, set = 0, binding = 0) uniform ArbVertexState {
  mat4 mvp;                // state.matrix.mvp
  mat4 modelview;          // state.matrix.modelview
  vec4 clip_plane0;        // state.clip[0].plane
  vec4 env[16];            // program.env[0..15]
  mat4 palette[4];         // state.matrix.palette[0..3]
} state;

layout(location = 0) in vec4 vertex_position;  // vertex.position
layout(location = 1) in vec4 vertex_weight;    // vertex.weight
layout(location = 6) in vec4 vertex_attrib6;   // vertex.attrib[6]

layout(location = 0) out vec4 result_color;          // result.color
layout(location = 1) out vec4 result_color_back;     // result.color.back
layout(location = 2) out float result_fogcoord;      // result.fogcoord
layout(location = 3) out vec4 result_texcoord[2];    // result.texcoord[0..1]

out gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[1];
};

void main() {
  vec4 R0;
  ivec4 A0;
  // ARL A0.x, vertex.attrib[6].x; (floor, as ARB_vertex_program says)
  A0.x = int(floor(vertex_attrib6.x));
  // MOV R0, program.env[A0.x + 2]; (out of range reads (0,0,0,0))
  int index = A0.x + 2;
  R0 = index >= 0 && index < 16 ? state.env[index] : vec4(0.0);
  // DP4 over the palette matrix the weight selects
  int bone = clamp(int(vertex_weight.x), 0, 3);
  vec4 skinned = state.palette[bone] * vertex_position;
  gl_Position = state.mvp * skinned;
  vec4 eye = state.modelview * skinned;
  gl_ClipDistance[0] = dot(eye, state.clip_plane0);
  result_fogcoord = abs(eye.z);
  // LIT R0, R0;
  vec4 lit = vec4(1.0, max(R0.x, 0.0), 0.0, 1.0);
  if (R0.x > 0.0) lit.z = exp2(clamp(R0.w, -128.0, 128.0) * log2(max(R0.y, 0.0)));
  result_color = lit;
  result_color_back = lit.zyxw;
  result_texcoord[0] = vertex_attrib6;
  result_texcoord[1] = fract(vertex_attrib6 * 0.5);
}
