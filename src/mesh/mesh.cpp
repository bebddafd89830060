// Mesh container helpers: attributes and structural validation.
#include <isopatch/error.hpp>
#include <isopatch/mesh.hpp>

#include <Eigen/Geometry>

#include <limits>

namespace isopatch {
namespace {

bool is_identifier(const std::string& name) {
  if (name.empty()) return false;
  auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!alpha(name[0])) return false;
  for (char c : name)
    if (!alpha(c) && !(c >= '0' && c <= '9')) return false;
  return true;
}

}  // namespace

void Mesh::set_attribute(const std::string& name, std::vector<float> values) {
  if (!is_identifier(name)) throw InputError("attribute name '" + name + "' is not an identifier");
  if (values.size() != positions.size())
    throw InputError("attribute '" + name + "' has " + std::to_string(values.size()) + " values for " +
                     std::to_string(positions.size()) + " vertices");
  for (VertexAttribute& a : attributes)
    if (a.name == name) {
      a.values = std::move(values);
      return;
    }
  attributes.push_back({name, std::move(values)});
}

const std::vector<float>* Mesh::find_attribute(const std::string& name) const {
  for (const VertexAttribute& a : attributes)
    if (a.name == name) return &a.values;
  return nullptr;
}

void Mesh::validate() const {
  const std::size_t n = positions.size();
  if (n > std::numeric_limits<std::uint32_t>::max()) throw InputError("mesh has too many vertices");
  for (std::size_t v = 0; v < n; ++v)
    if (!positions[v].allFinite()) throw InputError("vertex " + std::to_string(v) + " is not finite");
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (std::uint32_t i : tri)
      if (i >= n)
        throw InputError("triangle " + std::to_string(t) + " refers to vertex " + std::to_string(i) + " of " +
                         std::to_string(n));
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      throw InputError("triangle " + std::to_string(t) + " repeats a vertex");
  }
  for (const VertexAttribute& a : attributes)
    if (a.values.size() != n)
      throw InputError("attribute '" + a.name + "' has " + std::to_string(a.values.size()) + " values for " +
                       std::to_string(n) + " vertices");
}

Box bounding_box(const Mesh& mesh) {
  if (mesh.positions.empty()) return Box{};
  Box box{mesh.positions.front(), mesh.positions.front()};
  for (const Vec3& p : mesh.positions) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  return box;
}

std::vector<Vec3> vertex_normals(const Mesh& mesh) {
  std::vector<Vec3> normals(mesh.vertex_count(), Vec3::Zero());
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.positions[t[0]];
    // Twice the area times the unit normal: larger triangles weigh more.
    const Vec3 n = (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
    for (const std::uint32_t v : t) normals[v] += n;
  }
  for (Vec3& n : normals) {
    const double length = n.norm();
    n = length > 0.0 ? Vec3(n / length) : Vec3::Zero();
  }
  return normals;
}

}  // namespace isopatch
