// The GLSL of the NV instructions (emit_nv.h).
#include "emit/emit_nv.h"

#include <fmt/format.h>

namespace arbiter::arbvp::emit {
namespace {

// Not translated yet: a line GLSL rejects, so no translation passes for a working one.
std::string NotTranslated(std::string_view name) {
  return fmt::format("#error {} is not translated yet\n", name);
}

}  // namespace

std::string ARA(Context&, const Instruction&) { return NotTranslated("ARA"); }
std::string ARR(Context&, const Instruction&) { return NotTranslated("ARR"); }
std::string BRA(Context&, const Instruction&) { return NotTranslated("BRA"); }
std::string BRK(Context&, const Instruction&) { return NotTranslated("BRK"); }
std::string CAL(Context&, const Instruction&) { return NotTranslated("CAL"); }
std::string DDX(Context&, const Instruction&) { return NotTranslated("DDX"); }
std::string DDY(Context&, const Instruction&) { return NotTranslated("DDY"); }
std::string DIV(Context&, const Instruction&) { return NotTranslated("DIV"); }
std::string DP2(Context&, const Instruction&) { return NotTranslated("DP2"); }
std::string DP2A(Context&, const Instruction&) { return NotTranslated("DP2A"); }
std::string ELSE(Context&, const Instruction&) { return NotTranslated("ELSE"); }
std::string ENDIF(Context&, const Instruction&) { return NotTranslated("ENDIF"); }
std::string ENDLOOP(Context&, const Instruction&) { return NotTranslated("ENDLOOP"); }
std::string ENDREP(Context&, const Instruction&) { return NotTranslated("ENDREP"); }
std::string IF(Context&, const Instruction&) { return NotTranslated("IF"); }
std::string LOOP(Context&, const Instruction&) { return NotTranslated("LOOP"); }
std::string NRM(Context&, const Instruction&) { return NotTranslated("NRM"); }
std::string PK2H(Context&, const Instruction&) { return NotTranslated("PK2H"); }
std::string PK2US(Context&, const Instruction&) { return NotTranslated("PK2US"); }
std::string PK4B(Context&, const Instruction&) { return NotTranslated("PK4B"); }
std::string PK4UB(Context&, const Instruction&) { return NotTranslated("PK4UB"); }
std::string POPA(Context&, const Instruction&) { return NotTranslated("POPA"); }
std::string PUSHA(Context&, const Instruction&) { return NotTranslated("PUSHA"); }
std::string RCC(Context&, const Instruction&) { return NotTranslated("RCC"); }
std::string REP(Context&, const Instruction&) { return NotTranslated("REP"); }
std::string RET(Context&, const Instruction&) { return NotTranslated("RET"); }
std::string RFL(Context&, const Instruction&) { return NotTranslated("RFL"); }
std::string SEQ(Context&, const Instruction&) { return NotTranslated("SEQ"); }
std::string SFL(Context&, const Instruction&) { return NotTranslated("SFL"); }
std::string SGT(Context&, const Instruction&) { return NotTranslated("SGT"); }
std::string SLE(Context&, const Instruction&) { return NotTranslated("SLE"); }
std::string SNE(Context&, const Instruction&) { return NotTranslated("SNE"); }
std::string SSG(Context&, const Instruction&) { return NotTranslated("SSG"); }
std::string STR(Context&, const Instruction&) { return NotTranslated("STR"); }
std::string TXD(Context&, const Instruction&) { return NotTranslated("TXD"); }
std::string TXL(Context&, const Instruction&) { return NotTranslated("TXL"); }
std::string UP2H(Context&, const Instruction&) { return NotTranslated("UP2H"); }
std::string UP2US(Context&, const Instruction&) { return NotTranslated("UP2US"); }
std::string UP4B(Context&, const Instruction&) { return NotTranslated("UP4B"); }
std::string UP4UB(Context&, const Instruction&) { return NotTranslated("UP4UB"); }
std::string X2D(Context&, const Instruction&) { return NotTranslated("X2D"); }

}  // namespace arbiter::arbvp::emit
