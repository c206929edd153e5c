// Fuzz target: the GLSL translator, with the property "every program the checker accepts
// translates to GLSL that glslang accepts" as the oracle (as `arbiter translate` checks it).
#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "accept_arb.h"
#include "arbiter/arbvp/emit.h"
#include "arbiter/runtime/translate.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace arbiter;
  fuzz::AcceptedProgram accepted;
  if (!fuzz::AcceptArbProgram(data, size, &accepted)) return -1;
  const arbvp::Program* program = accepted.checked.program.get();
  const bool vertex = accepted.vertex;
  const compiler::SourceFile* source = accepted.source.get();
  runtime::CheckedTranslation t = runtime::TranslateChecked(
      vertex ? program : nullptr, vertex ? nullptr : program, arbvp::EmitOptions{},
      vertex ? source : nullptr, vertex ? nullptr : source);
  // A refusal names a construct GLSL 1.10 cannot express: not a translator bug.
  if (!t.ok && !t.refused) {
    std::fprintf(stderr,
                 "fuzz_translate: an accepted program's translation is not valid GLSL 1.10: %s\n"
                 "---- program ----\n%s\n---- translation ----\n%s\n",
                 t.error.c_str(), source->text().c_str(),
                 vertex ? t.vertex.c_str() : t.fragment.c_str());
    __builtin_trap();
  }
  return 0;
}
