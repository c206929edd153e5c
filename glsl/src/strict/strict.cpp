// Runs the strictness checks in chapter order.
#include "strict.h"

namespace arbiter::glsl {

void RunStrictChecks(const StrictContext& ctx) {
  CheckPreprocessor(ctx);
  CheckQualifiers(ctx);
  CheckConstInitializers(ctx);
  CheckBuiltinVariables(ctx);
}

}  // namespace arbiter::glsl
