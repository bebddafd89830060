// libFuzzer target: the text of --region (parse_region) and --frame (parse_frame). Parsing must either
// succeed or throw InputError with a one-line message. Parsed planes cut a box (intersect_half_spaces,
// src/partition/convex_cell.cpp): the result is a closed convex cell inside the box, with every vertex
// inside every face plane, or an InputError for an empty intersection.
#include <isopatch/convex_region.hpp>
#include <isopatch/error.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "partition/convex_cell.hpp"

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

void one_line(const isopatch::Error& e) {
  check(std::string(e.what()).find('\n') == std::string::npos);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)isopatch::parse_frame(text);
  } catch (const isopatch::InputError& e) {
    one_line(e);
  }
  isopatch::ConvexRegion region;
  try {
    region = isopatch::parse_region(text);
  } catch (const isopatch::InputError& e) {
    one_line(e);
    return 0;
  }
  if (region.size() > 64) region.resize(64);
  std::vector<isopatch::CellPlane> planes;
  for (const isopatch::HalfSpace& h : region) planes.push_back(isopatch::make_cell_plane(h.a, h.b, h.c, h.d));
  const isopatch::Box box{isopatch::Vec3(-1, -2, -0.5), isopatch::Vec3(1.5, 1, 2)};
  try {
    const isopatch::ConvexCell cell = isopatch::intersect_half_spaces(box, planes);
    check(!cell.empty());
    check(cell.volume() > 0.0 && cell.volume() <= 1.0001 * box.size().prod());
    const double margin = 1e-9 * box.diagonal();
    for (const isopatch::Vec3& p : cell.vertices()) {
      check(box.contains(p, margin));
      for (const isopatch::ConvexCell::Face& f : cell.faces())
        check(cell.planes()[f.plane].distance(p) <= margin);
    }
    check(cell.contains(cell.centroid(), margin));
  } catch (const isopatch::InputError& e) {
    one_line(e);
  }
  return 0;
}
