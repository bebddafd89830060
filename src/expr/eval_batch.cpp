// The batch evaluator. Points go through the tape in blocks of kBlock held in structure-of-arrays
// registers: one switch per instruction and block, then a tight loop over the block that the
// compiler vectorizes (arithmetic) or pipelines (libm calls). Each loop computes exactly what
// scalar.hpp's apply() computes, so batch and single-point values agree bit for bit.
#include "expr/evaluate.hpp"
#include "expr/scalar.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <vector>

namespace isopatch::expr {
namespace {

using Row = double* __restrict;
using ConstRow = const double* __restrict;

// A full block loops over the compile-time kBlock (no remainder code, unrolled); the last, partial
// block over n rounded up to a multiple of kLanes, so a small batch does not pay for a whole block.
// Lanes past the last point compute on stale values and are never read.
constexpr std::size_t kLanes = 8;
static_assert(kBlock % kLanes == 0);

template <class F>
inline void map1(Row o, ConstRow a, std::size_t n, F f) {
#pragma GCC unroll 8
  for (std::size_t i = 0; i < n; ++i) o[i] = f(a[i]);
}

template <class F>
inline void map2(Row o, ConstRow a, ConstRow b, std::size_t n, F f) {
#pragma GCC unroll 8
  for (std::size_t i = 0; i < n; ++i) o[i] = f(a[i], b[i]);
}

/// ipow over a block, with the multiplications in the order of ipow().
void block_ipow(Row o, ConstRow a, unsigned e, std::size_t n) {
  if (e == 3) return map1(o, a, n, [](double v) { return v * (v * v); });
  double base[kBlock];
  for (std::size_t i = 0; i < n; ++i) {
    o[i] = 1.0;
    base[i] = a[i];
  }
  while (e != 0) {
    if (e & 1u)
      for (std::size_t i = 0; i < n; ++i) o[i] *= base[i];
    e >>= 1u;
    if (e != 0)
      for (std::size_t i = 0; i < n; ++i) base[i] *= base[i];
  }
}

template <bool Full>
void run_instruction(const Instruction& in, double* regs, std::size_t partial) {
  const std::size_t n = Full ? kBlock : partial;
  Row o = regs + in.out * kBlock;
  ConstRow a = regs + in.a * kBlock;
  ConstRow b = regs + in.b * kBlock;
  const double c = in.imm;
  switch (in.op) {
    case Op::Var:
    case Op::Const:
      break;  // never on the tape
    case Op::Neg:
      return map1(o, a, n, [](double v) { return -v; });
    case Op::Square:
      return map1(o, a, n, [](double v) { return v * v; });
    case Op::Powi:
      return block_ipow(o, a, static_cast<unsigned>(c), n);
    case Op::PowC:
      return map1(o, a, n, [c](double v) { return strict_pow(v, c); });
    case Op::AddC:
      return map1(o, a, n, [c](double v) { return v + c; });
    case Op::MulC:
      return map1(o, a, n, [c](double v) { return v * c; });
    case Op::RSubC:
      return map1(o, a, n, [c](double v) { return c - v; });
    case Op::DivC:
      return map1(o, a, n, [c](double v) { return v / c; });
    case Op::RDivC:
      return map1(o, a, n, [c](double v) { return c / v; });
    case Op::Sqrt:
      return map1(o, a, n, [](double v) { return std::sqrt(v); });
    case Op::Exp:
      return map1(o, a, n, [](double v) { return std::exp(v); });
    case Op::Log:
      return map1(o, a, n, [](double v) { return std::log(v); });
    case Op::Sin:
      return map1(o, a, n, [](double v) { return std::sin(v); });
    case Op::Cos:
      return map1(o, a, n, [](double v) { return std::cos(v); });
    case Op::Tan:
      return map1(o, a, n, [](double v) { return std::tan(v); });
    case Op::Asin:
      return map1(o, a, n, [](double v) { return std::asin(v); });
    case Op::Acos:
      return map1(o, a, n, [](double v) { return std::acos(v); });
    case Op::Atan:
      return map1(o, a, n, [](double v) { return std::atan(v); });
    case Op::Sinh:
      return map1(o, a, n, [](double v) { return std::sinh(v); });
    case Op::Cosh:
      return map1(o, a, n, [](double v) { return std::cosh(v); });
    case Op::Tanh:
      return map1(o, a, n, [](double v) { return std::tanh(v); });
    case Op::Abs:
      return map1(o, a, n, [](double v) { return std::fabs(v); });
    case Op::Add:
      return map2(o, a, b, n, [](double u, double v) { return u + v; });
    case Op::Sub:
      return map2(o, a, b, n, [](double u, double v) { return u - v; });
    case Op::Mul:
      return map2(o, a, b, n, [](double u, double v) { return u * v; });
    case Op::Div:
      return map2(o, a, b, n, [](double u, double v) { return u / v; });
    case Op::Pow:
      return map2(o, a, b, n, [](double u, double v) { return strict_pow(u, v); });
    case Op::Atan2:
      return map2(o, a, b, n, [](double u, double v) { return std::atan2(u, v); });
    case Op::Hypot:
      return map2(o, a, b, n, [](double u, double v) { return strict_hypot(u, v); });
    case Op::Min:
      return map2(o, a, b, n, [](double u, double v) { return (v < u || v != v) ? v : u; });
    case Op::Max:
      return map2(o, a, b, n, [](double u, double v) { return (u < v || v != v) ? v : u; });
  }
}

/// The register file of this thread, kBlock doubles per register, constants filled in.
double* registers_for(const Tape& tape) {
  thread_local std::vector<double> storage;
  const std::size_t size = static_cast<std::size_t>(tape.registers) * kBlock;
  if (storage.size() < size) storage.resize(size);
  double* regs = storage.data();
  for (const ConstantRegister& c : tape.constants) std::fill_n(regs + c.reg * kBlock, kBlock, c.value);
  return regs;
}

void run_block(const Tape& tape, double* regs, std::size_t n) {
  if (n == kBlock) {
    for (const Instruction& in : tape.code) run_instruction<true>(in, regs, kBlock);
  } else {
    const std::size_t lanes = (n + kLanes - 1) / kLanes * kLanes;
    for (const Instruction& in : tape.code) run_instruction<false>(in, regs, lanes);
  }
}

}  // namespace

void evaluate_batch(const Tape& tape, const double* x, const double* y, const double* z, double* out,
                    std::size_t n) {
  double* regs = registers_for(tape);
  const double* result = regs + tape.result * kBlock;
  for (std::size_t start = 0; start < n; start += kBlock) {
    const std::size_t m = std::min(kBlock, n - start);
    std::memcpy(regs, x + start, m * sizeof(double));
    std::memcpy(regs + kBlock, y + start, m * sizeof(double));
    std::memcpy(regs + 2 * kBlock, z + start, m * sizeof(double));
    run_block(tape, regs, m);
    std::memcpy(out + start, result, m * sizeof(double));
  }
}

void evaluate_batch(const Tape& tape, std::span<const Vec3> points, std::span<double> out) {
  assert(out.size() == points.size());
  double* regs = registers_for(tape);
  const double* result = regs + tape.result * kBlock;
  const std::size_t n = points.size();
  for (std::size_t start = 0; start < n; start += kBlock) {
    const std::size_t m = std::min(kBlock, n - start);
    const Vec3* p = points.data() + start;
    for (std::size_t i = 0; i < m; ++i) {
      regs[i] = p[i].x();
      regs[kBlock + i] = p[i].y();
      regs[2 * kBlock + i] = p[i].z();
    }
    run_block(tape, regs, m);
    std::memcpy(out.data() + start, result, m * sizeof(double));
  }
}

}  // namespace isopatch::expr
