#version 120
// ARB vertex program translated to GLSL 1.20 by arbiter.

varying vec4 gl_TexCoord[3];
attribute vec4 arb_attrib7;  // vertex.attrib[7], location 7
uniform mat4 arb_matrix_program1;  // state.matrix.program[1]

void main() {
  vec4 p = vec4(0.0);

  // DP4 p.x, mvp[0], iPos;
  p.x = dot(gl_ModelViewProjectionMatrixTranspose[0], gl_Vertex);
  // DP4 p.y, mvp[1], iPos;
  p.y = dot(gl_ModelViewProjectionMatrixTranspose[1], gl_Vertex);
  // DP4 p.z, mvp[2], iPos;
  p.z = dot(gl_ModelViewProjectionMatrixTranspose[2], gl_Vertex);
  // DP4 p.w, mvp[3], iPos;
  p.w = dot(gl_ModelViewProjectionMatrixTranspose[3], gl_Vertex);
  // MOV result.position, p;
  gl_Position = p;
  // MOV result.texcoord[0], vertex.texcoord[0];
  gl_TexCoord[0] = gl_MultiTexCoord0;
  // MUL result.texcoord[2], vertex.attrib[7], mv2;
  gl_TexCoord[2] = arb_attrib7 * vec4(arb_matrix_program1[0][2], arb_matrix_program1[1][2], arb_matrix_program1[2][2], arb_matrix_program1[3][2]);
  // MOV result.fogcoord.x, p.z;
  gl_FogFragCoord = p.z;
  // MOV result.color, vertex.color;
  gl_FrontColor = gl_Color;
}
