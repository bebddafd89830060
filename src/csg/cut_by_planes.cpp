// A formula intersected with half-spaces (cut_by_planes.hpp).
#include "csg/cut_by_planes.hpp"

#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

#include <cstdint>
#include <memory>

#include "expr/tape.hpp"

namespace isopatch {

SurfacePtr cut_by_planes(const Surface& f, const ConvexRegion& planes, const Box& box) {
  using expr::Instruction;
  using expr::Op;
  const Expression* formula = f.expression();
  if (formula == nullptr) return nullptr;
  expr::Tape tape = formula->tape();
  const auto next = [&tape] { return tape.registers++; };
  for (const HalfSpace& h : planes) {
    const std::uint32_t ax = next(), by = next(), sum = next(), cz = next(), all = next(), value = next(),
                        out = next();
    tape.code.push_back(Instruction{Op::MulC, ax, 0, 0, h.a});
    tape.code.push_back(Instruction{Op::MulC, by, 1, 1, h.b});
    tape.code.push_back(Instruction{Op::Add, sum, ax, by, 0.0});
    tape.code.push_back(Instruction{Op::MulC, cz, 2, 2, h.c});
    tape.code.push_back(Instruction{Op::Add, all, sum, cz, 0.0});
    tape.code.push_back(Instruction{Op::AddC, value, all, all, h.d});
    tape.code.push_back(Instruction{Op::Max, out, tape.result, value, 0.0});
    tape.result = out;
  }
  return expression_surface(Expression(std::make_shared<const expr::Tape>(std::move(tape))), box,
                            "the shape cut by the planes");
}

}  // namespace isopatch
