#version 120
// ARB vertex program translated to GLSL 1.20 by arbiter.

void main() {
  vec4 n = vec4(0.0);
  vec4 d = vec4(0.0);
  gl_Position = ftransform();  // OPTION ARB_position_invariant
  gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex;

  // DP3 n.x, mvit[0], iNrm;
  n.x = dot(gl_ModelViewMatrixInverse[0].xyz, gl_Normal);
  // DP3 n.y, mvit[1], iNrm;
  n.y = dot(gl_ModelViewMatrixInverse[1].xyz, gl_Normal);
  // DP3 n.z, mvit[2], iNrm;
  n.z = dot(gl_ModelViewMatrixInverse[2].xyz, gl_Normal);
  // DP3 d.x, n, L;
  d.x = dot(n.xyz, gl_LightSource[0].position.xyz);
  // MAX d.x, d.x, 0.0;
  d.x = max(d.x, 0.0);
  // MAD result.color, dif, d.x, amb;
  gl_FrontColor = vec4(gl_FrontLightProduct[0].diffuse.rgb, gl_FrontMaterial.diffuse.a) * d.xxxx + vec4(gl_FrontLightProduct[0].ambient.rgb, gl_FrontMaterial.ambient.a);
  // MOV result.texcoord[0], vertex.texcoord[0];
  gl_TexCoord[0] = gl_MultiTexCoord0;
}
