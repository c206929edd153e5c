// Prints the value of each uniform named on the command line (an ARB spelling from a binding
// map: "state.light[1].half", "state.matrix.mvp.inverse", "program.env[3]") for the GL state
// an engine set up below. Exit 1 for a spelling the library does not know.
#include <arbiter/glstate/uniforms.h>

#include <cstdio>

namespace gs = arbiter::glstate;

int main(int argc, char** argv) {
  gs::GlState state;  // GL's initial state
  // glLoadMatrixf(GL_PROJECTION): a frustum; the modelview moves the scene 4 units away.
  state.projection[2][2] = -1.0f;
  state.projection[3][2] = -2.0f;
  state.projection[2][3] = -1.0f;
  state.projection[3][3] = 0.0f;
  state.modelview[3][2] = -4.0f;
  // glLightfv(GL_LIGHT1, GL_POSITION, (0, 3, 0, -1)) under the identity modelview: eye space.
  state.light[1].position = {0.0f, 3.0f, 0.0f, -1.0f};
  state.light[1].diffuse = {0.5f, 1.0f, 2.0f, 1.0f};
  state.light[1].spot_cutoff = 60.0f;
  state.material[0].diffuse = {0.5f, 0.5f, 0.5f, 0.25f};
  state.fog_start = 2.0f;
  state.fog_end = 6.0f;
  gs::ProgramParameters vertex_params;  // glProgramEnvParameter4fARB(GL_VERTEX_PROGRAM_ARB, ...)
  vertex_params.env[3] = {1.0f, 2.0f, 3.0f, 4.0f};

  for (int i = 1; i < argc; ++i) {
    gs::UniformData value;
    if (!gs::UniformValue(state, vertex_params, argv[i], &value)) {
      std::printf("%s: not a uniform the host library knows\n", argv[i]);
      return 1;
    }
    const bool matrix = value.type == gs::UniformType::Matrix;
    std::printf("%s =", argv[i]);
    for (int k = 0; k < (matrix ? 16 : 4); ++k) {
      std::printf(" %g", static_cast<double>(value.data[static_cast<size_t>(k)]));
    }
    std::printf("\n");
  }
  return 0;
}
