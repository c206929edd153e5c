// Texture sampling for TEX, TXP and TXB: GL 2.0 sections 3.8.6-3.8.9 and 3.8.14 as
// ARBfp 3.11.6 and ARB_fragment_program_shadow use them.
#pragma once

#include <map>
#include <string>

#include "arbiter/arbvp/exec.h"
#include "arbiter/arbvp/ir.h"

namespace arbiter::arbvp::exec {

struct Sample {
  Vec4 value{0.0f, 0.0f, 0.0f, 1.0f};
  std::string undefined;   // why the specs leave the value undefined; empty when defined
  bool cube_edge = false;  // a linear cube lookup whose footprint crosses a face edge
  // A linear MIRRORED_REPEAT lookup at a texel centre of a mirrored period.
  bool mirror_centre = false;
};

// Samples unit `unit` with `target` at (s, t, r) (TXP has already divided by q). The model
// has one mipmap level, so the LOD (and TXB's bias) never changes the result. An unbound
// unit, a texture of another dimension or an inconsistent one is incomplete: (0,0,0,1).
Sample SampleTexture(const std::map<int, Texture>& textures, int unit, TexTarget target, float s,
                     float t, float r, bool shadow_option);

}  // namespace arbiter::arbvp::exec
