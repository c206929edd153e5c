// The reference interpreter: ARB vertex and fragment programs executed in float32 with the
// exact semantics of ARB_vertex_program 2.14.5 and ARB_fragment_program 3.11.5 (the
// specification, executable). Components that depend on behaviour the specs leave undefined
// are tagged in OutputRegister::undefined.
#pragma once

#include <vector>

#include "arbiter/arbvp/exec.h"
#include "arbiter/arbvp/ir.h"
#include "arbiter/compiler/source.h"

namespace arbiter::arbvp {

// Runs `program` (one that checked without errors) on every vector of `inputs`; the result
// has one entry per vector. `source` (optional) is the program's text, used to name
// instructions by line:column in the undefined tags.
std::vector<VectorResult> Interpret(const Program& program, const ExecInputs& inputs,
                                    const compiler::SourceFile* source = nullptr);

// Runs a vertex program and a fragment program as GL does for one point per vector: the
// vertex program's front primary/secondary colours, texture coordinates and fog coordinate
// (x) become the fragment inputs (points are front-facing). The point is placed at the
// vector's pixel whatever the vertex program's result.position, so fragment.position is
// (x + 0.5, y + 0.5, FragmentInput::depth, 1) as for a fragment program run alone. The
// colours are clamped to [0, 1] on the way (GL 2.0 section 2.14.6 colour clamping, which
// ARBvp 2.14.4.4 keeps; GL's default CLAMP_VERTEX_COLOR); texture and fog coordinates are
// not. A fragment input whose vertex output was never written is undefined (tagged). The
// result holds the fragment program's outputs.
std::vector<VectorResult> InterpretPair(const Program& vertex, const Program& fragment,
                                        const ExecInputs& inputs,
                                        const compiler::SourceFile* vertex_source = nullptr,
                                        const compiler::SourceFile* fragment_source = nullptr);

}  // namespace arbiter::arbvp
