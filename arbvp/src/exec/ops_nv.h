// The instructions the NV program options add (opcodes.def rows with Nv / Nv2): their
// semantics, one function each, as ops.cpp has them for the ARB instructions. Flow
// instructions (BRA, CAL, RET, BRK, IF, ELSE, ENDIF, LOOP, REP, ENDLOOP, ENDREP) and the
// address stack (PUSHA, POPA) change the machine, not a register: the interpreter runs them
// (nv_flow.h), and their functions here are never called.
#pragma once

#include "exec/machine.h"

namespace arbiter::arbvp::exec {

Reg OpARA(OpContext& c);
Reg OpARR(OpContext& c);
Reg OpBRA(OpContext& c);
Reg OpBRK(OpContext& c);
Reg OpCAL(OpContext& c);
Reg OpDDX(OpContext& c);
Reg OpDDY(OpContext& c);
Reg OpDIV(OpContext& c);
Reg OpDP2(OpContext& c);
Reg OpDP2A(OpContext& c);
Reg OpELSE(OpContext& c);
Reg OpENDIF(OpContext& c);
Reg OpENDLOOP(OpContext& c);
Reg OpENDREP(OpContext& c);
Reg OpIF(OpContext& c);
Reg OpLOOP(OpContext& c);
Reg OpNRM(OpContext& c);
Reg OpPK2H(OpContext& c);
Reg OpPK2US(OpContext& c);
Reg OpPK4B(OpContext& c);
Reg OpPK4UB(OpContext& c);
Reg OpPOPA(OpContext& c);
Reg OpPUSHA(OpContext& c);
Reg OpRCC(OpContext& c);
Reg OpREP(OpContext& c);
Reg OpRET(OpContext& c);
Reg OpRFL(OpContext& c);
Reg OpSEQ(OpContext& c);
Reg OpSFL(OpContext& c);
Reg OpSGT(OpContext& c);
Reg OpSLE(OpContext& c);
Reg OpSNE(OpContext& c);
Reg OpSSG(OpContext& c);
Reg OpSTR(OpContext& c);
Reg OpTXD(OpContext& c);
Reg OpTXL(OpContext& c);
Reg OpUP2H(OpContext& c);
Reg OpUP2US(OpContext& c);
Reg OpUP4B(OpContext& c);
Reg OpUP4UB(OpContext& c);
Reg OpX2D(OpContext& c);

// ARL under NV_vertex_program2: the component-wise floor of a vector operand, clamped to the
// address registers' [-512, +511] (NV_vertex_program2 2.14.3.4).
Reg OpArlNv(OpContext& c);

}  // namespace arbiter::arbvp::exec
