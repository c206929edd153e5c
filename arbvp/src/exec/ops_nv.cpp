// The NV instructions' semantics (ops_nv.h).
#include "exec/ops_nv.h"

#include <string>

namespace arbiter::arbvp::exec {
namespace {

// Not interpreted yet: every component undefined, with the reason named.
Reg NotInterpreted(OpContext& c, std::string_view name) {
  Reg r{};
  const int why = c.Undefined(std::string(name) + " is not interpreted yet");
  for (Val& v : r) v.why = why;
  return r;
}

}  // namespace

Reg OpARA(OpContext& c) { return NotInterpreted(c, "ARA"); }
Reg OpARR(OpContext& c) { return NotInterpreted(c, "ARR"); }
Reg OpBRA(OpContext& c) { return NotInterpreted(c, "BRA"); }
Reg OpBRK(OpContext& c) { return NotInterpreted(c, "BRK"); }
Reg OpCAL(OpContext& c) { return NotInterpreted(c, "CAL"); }
Reg OpDDX(OpContext& c) { return NotInterpreted(c, "DDX"); }
Reg OpDDY(OpContext& c) { return NotInterpreted(c, "DDY"); }
Reg OpDIV(OpContext& c) { return NotInterpreted(c, "DIV"); }
Reg OpDP2(OpContext& c) { return NotInterpreted(c, "DP2"); }
Reg OpDP2A(OpContext& c) { return NotInterpreted(c, "DP2A"); }
Reg OpELSE(OpContext& c) { return NotInterpreted(c, "ELSE"); }
Reg OpENDIF(OpContext& c) { return NotInterpreted(c, "ENDIF"); }
Reg OpENDLOOP(OpContext& c) { return NotInterpreted(c, "ENDLOOP"); }
Reg OpENDREP(OpContext& c) { return NotInterpreted(c, "ENDREP"); }
Reg OpIF(OpContext& c) { return NotInterpreted(c, "IF"); }
Reg OpLOOP(OpContext& c) { return NotInterpreted(c, "LOOP"); }
Reg OpNRM(OpContext& c) { return NotInterpreted(c, "NRM"); }
Reg OpPK2H(OpContext& c) { return NotInterpreted(c, "PK2H"); }
Reg OpPK2US(OpContext& c) { return NotInterpreted(c, "PK2US"); }
Reg OpPK4B(OpContext& c) { return NotInterpreted(c, "PK4B"); }
Reg OpPK4UB(OpContext& c) { return NotInterpreted(c, "PK4UB"); }
Reg OpPOPA(OpContext& c) { return NotInterpreted(c, "POPA"); }
Reg OpPUSHA(OpContext& c) { return NotInterpreted(c, "PUSHA"); }
Reg OpRCC(OpContext& c) { return NotInterpreted(c, "RCC"); }
Reg OpREP(OpContext& c) { return NotInterpreted(c, "REP"); }
Reg OpRET(OpContext& c) { return NotInterpreted(c, "RET"); }
Reg OpRFL(OpContext& c) { return NotInterpreted(c, "RFL"); }
Reg OpSEQ(OpContext& c) { return NotInterpreted(c, "SEQ"); }
Reg OpSFL(OpContext& c) { return NotInterpreted(c, "SFL"); }
Reg OpSGT(OpContext& c) { return NotInterpreted(c, "SGT"); }
Reg OpSLE(OpContext& c) { return NotInterpreted(c, "SLE"); }
Reg OpSNE(OpContext& c) { return NotInterpreted(c, "SNE"); }
Reg OpSSG(OpContext& c) { return NotInterpreted(c, "SSG"); }
Reg OpSTR(OpContext& c) { return NotInterpreted(c, "STR"); }
Reg OpTXD(OpContext& c) { return NotInterpreted(c, "TXD"); }
Reg OpTXL(OpContext& c) { return NotInterpreted(c, "TXL"); }
Reg OpUP2H(OpContext& c) { return NotInterpreted(c, "UP2H"); }
Reg OpUP2US(OpContext& c) { return NotInterpreted(c, "UP2US"); }
Reg OpUP4B(OpContext& c) { return NotInterpreted(c, "UP4B"); }
Reg OpUP4UB(OpContext& c) { return NotInterpreted(c, "UP4UB"); }
Reg OpX2D(OpContext& c) { return NotInterpreted(c, "X2D"); }

}  // namespace arbiter::arbvp::exec
