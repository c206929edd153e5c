// The data types of NV_fragment_program (3.11.4.1-3.11.4.2) that the "H" and "X" precision
// suffixes and SHORT variables use: fp16 (s.e5.m10, with denorms) and fx12 (two's
// complement, 10 fraction bits), and the conversions into them.
#pragma once

#include <cstdint>

#include "arbiter/arbvp/ir.h"
#include "exec/machine.h"

namespace arbiter::arbvp::exec {

// The fp16 bits of x: round to nearest even, |x| >= 2^16 (and what rounds past 65504) to
// +/-INF; NaN to a quiet NaN.
uint16_t HalfBits(float x);
// The value of fp16 bits (exact in float32).
float HalfValue(uint16_t bits);

// The type conversions of 3.11.4.2 as the reference computes them (to nearest, ties to
// even): fp16 overflows to +/-INF; fx12 clamps to [-2048/1024, +2047/1024] and NaN becomes 0.
float ToHalf(float x);
float ToFixed(float x);

// v converted to `precision` (R: unchanged). Where the result is not exact, the bound grows
// by the type's step: the specs let a conversion take either neighbour ("round or
// truncate"), and the precision suffixes name a minimum precision, so a more precise value
// conforms too. A box that reaches an overflow is unstable.
Val ConvertVal(const Val& v, Precision precision);

// The result of ALU instruction `op` carried out at `precision` (H or X) when `full` is its
// result at fp32: the operands converted, the operation, the result converted
// (NV_fragment_program 3.11.4.2-3.11.4.4). The bound also admits `full`, as the precision is
// a minimum ("carried out at no less than", NV_fragment_program_option 3.11.4.X).
Reg AtPrecision(Opcode op, const OpContext& ctx, Precision precision, const Reg& full);

}  // namespace arbiter::arbvp::exec
