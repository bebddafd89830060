// libFuzzer target: the .ipatch reader (parse_ipatch). The input is the file's text. It must either
// build a closed composite or throw InputError with a one-line message that starts with the source
// name; a built composite passes check_composite_closed and every patch's function (and each of its
// region's bounds) is finite, with a finite gradient and Hessian, at its corners and at points of its
// boundary curves.
#include <isopatch/error.hpp>

#include "composite_model/composite_checks.hpp"
#include "composite_model/ipatch_file.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

void check_finite(const isopatch::Surface& s, const isopatch::Vec3& x) {
  const isopatch::SecondOrder o = s.second_order(x);
  check(std::isfinite(o.value) && o.gradient.allFinite() && o.hessian.allFinite());
  check(std::isfinite(s.value(x)));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const isopatch::Composite c = isopatch::parse_ipatch(text, "fuzz.ipatch");
    isopatch::check_composite_closed(c);
    check(c.box.valid());
    for (const isopatch::CompositePatch& p : c.patches) {
      for (const isopatch::PatchSide& s : p.sides) {
        for (double t : {0.0, 0.37, 1.0}) {
          const isopatch::Vec3 x = c.curves[s.curve].point(t);
          check_finite(*p.surface, x);
          for (const auto& b : p.bounds) check_finite(*b, x);
        }
      }
    }
  } catch (const isopatch::InputError& e) {
    const std::string message = e.what();
    check(message.rfind("fuzz.ipatch", 0) == 0 && message.find('\n') == std::string::npos);
  }
  return 0;
}
