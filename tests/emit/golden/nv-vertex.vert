#version 110
// ARB vertex program translated to GLSL 1.10 by arbiter.

uniform vec4 arb_vp_env[4];  // program.env[0..3]
uniform sampler2D arb_texture0;  // texture[0], 2D
varying float arb_clip_distance0;  // result.clip[0]: GLSL 1.10 has no clip distances
vec4 c[4];  // PARAM c, read with relative addressing

// c[A0.x + k]: a read outside c[0..3] gives vec4(0.0) (undefined in ARB).
vec4 arb_read_c(int arb_i) {
  if (arb_i < 0 || arb_i > 3) return vec4(0.0);
  return c[arb_i];
}

void main() {
  ivec4 A0 = ivec4(0);
  vec4 t = vec4(0.0);
  vec4 n = vec4(0.0);
  vec4 arb_cc0 = vec4(0.0);  // condition code CC0: EQ everywhere
  vec4 arb_cc1 = vec4(0.0);  // condition code CC1: EQ everywhere
  int arb_pc = 0;  // the next instruction
  ivec4 arb_saved[4];  // address registers PUSHA saved
  int arb_sp = 0;  // call stack depth
  int arb_stack[4];  // return addresses; -1: a PUSHA entry
  vec4 arb_t = vec4(0.0);  // an NV result before its write
  arb_clip_distance0 = 0.0;  // result.clip[0] starts at 0
  c[0] = arb_vp_env[0];
  c[1] = arb_vp_env[1];
  c[2] = arb_vp_env[2];
  c[3] = arb_vp_env[3];

  for (int arb_step = 0; arb_step < 65536; ++arb_step) {  // MAX_PROGRAM_EXEC_INSTRUCTIONS_NV
    if (arb_pc >= 15) break;
    if (arb_pc < 7) {
      if (arb_pc < 3) {
        if (arb_pc < 1) {
          // MOVC t, vertex.position;
          arb_t = gl_Vertex;
          t = arb_t;
          arb_cc0 = arb_t;
          arb_pc = 1;
        } else {
          if (arb_pc < 2) {
            // ARL A0.xy, vertex.color;
            A0.xy = ivec2(clamp(floor(gl_Color.xy), -512.0, 511.0));
            arb_pc = 2;
          } else {
            // PUSHA A0;
            if (arb_sp == 4) {
              arb_pc = 15;  // call stack overflow: the end
            } else {
              if (arb_sp == 0) arb_stack[0] = -1;
              else if (arb_sp == 1) arb_stack[1] = -1;
              else if (arb_sp == 2) arb_stack[2] = -1;
              else arb_stack[3] = -1;
              if (arb_sp == 0) arb_saved[0] = A0;
              else if (arb_sp == 1) arb_saved[1] = A0;
              else if (arb_sp == 2) arb_saved[2] = A0;
              else arb_saved[3] = A0;
              arb_sp += 1;
              arb_pc = 3;
            }
          }
        }
      } else {
        if (arb_pc < 5) {
          if (arb_pc < 4) {
            // CAL light (GT.x);
            arb_pc = 4;
            if (arb_cc0.x > 0.0) {
              if (arb_sp == 4) {
                arb_pc = 15;  // call stack overflow: the end
              } else {
                if (arb_sp == 0) arb_stack[0] = 4;
                else if (arb_sp == 1) arb_stack[1] = 4;
                else if (arb_sp == 2) arb_stack[2] = 4;
                else arb_stack[3] = 4;
                arb_sp += 1;
                arb_pc = 11;
              }
            }
          } else {
            // POPA A0;
            if (arb_sp == 0 || arb_stack[arb_sp - 1] >= 0) {
              arb_pc = 15;  // no address register on the stack: the end
            } else {
              arb_sp -= 1;
              A0 = arb_saved[arb_sp];
              arb_pc = 5;
            }
          }
        } else {
          if (arb_pc < 6) {
            // MOV n, c[A0.y + 1];
            n = arb_read_c(A0.y + 1);
            arb_pc = 6;
          } else {
            // TEX n.w, vertex.texcoord[0], texture[0], 2D;
            n.w = texture2DLod(arb_texture0, gl_MultiTexCoord0.xy, 0.0).w;
            arb_pc = 7;
          }
        }
      }
    } else {
      if (arb_pc < 11) {
        if (arb_pc < 9) {
          if (arb_pc < 8) {
            // ADD_SAT result.color, n, -|t.zzzz|;
            gl_FrontColor = clamp(n + -abs(t.zzzz), 0.0, 1.0);
            arb_pc = 8;
          } else {
            // MOV result.position, t;
            gl_Position = t;
            arb_pc = 9;
          }
        } else {
          if (arb_pc < 10) {
            // MOV result.clip[0].x, t.z;
            arb_clip_distance0 = t.z;
            arb_pc = 10;
          } else {
            // RET;
            arb_pc = 11;
            if (arb_sp == 0) {
              arb_pc = 15;  // empty call stack: the end
            } else {
              arb_sp -= 1;
              arb_pc = arb_stack[arb_sp];
              if (arb_pc < 0) arb_pc = 15;  // an address register: the end
            }
          }
        }
      } else {
        if (arb_pc < 13) {
          if (arb_pc < 12) {
            // DP3C1 n.x, vertex.normal, c[0];
            arb_t.x = dot(gl_Normal, arb_vp_env[0].xyz);
            n.x = arb_t.x;
            arb_cc1.x = arb_t.x;
            arb_pc = 12;
          } else {
            // RET (LE1.x);
            arb_pc = 13;
            if (arb_cc1.x <= 0.0) {
              if (arb_sp == 0) {
                arb_pc = 15;  // empty call stack: the end
              } else {
                arb_sp -= 1;
                arb_pc = arb_stack[arb_sp];
                if (arb_pc < 0) arb_pc = 15;  // an address register: the end
              }
            }
          }
        } else {
          if (arb_pc < 14) {
            // MUL t.xyz (GT.xyzz), t, n.x;
            arb_t.xyz = t.xyz * n.xxx;
            if (arb_cc0.x > 0.0) t.x = arb_t.x;
            if (arb_cc0.y > 0.0) t.y = arb_t.y;
            if (arb_cc0.z > 0.0) t.z = arb_t.z;
            arb_pc = 14;
          } else {
            // RET;
            arb_pc = 15;
            if (arb_sp == 0) {
              arb_pc = 15;  // empty call stack: the end
            } else {
              arb_sp -= 1;
              arb_pc = arb_stack[arb_sp];
              if (arb_pc < 0) arb_pc = 15;  // an address register: the end
            }
          }
        }
      }
    }
  }
}
