// QualityReport -> dict (report_dict.hpp).
#include "report_dict.hpp"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace isopatch::python {

namespace {

py::dict distribution(const Distribution& d) {
  py::dict r;
  const std::pair<const char*, double> entries[] = {{"min", d.min},       {"p1", d.p1},     {"p5", d.p5},
                                                    {"median", d.median}, {"p95", d.p95},   {"p99", d.p99},
                                                    {"max", d.max},       {"mean", d.mean}, {"rms", d.rms}};
  r["count"] = d.count;
  for (const auto& [key, value] : entries) r[key] = value;
  return r;
}

py::dict topology(const TopologyReport& t) {
  py::dict r;
  r["vertices"] = t.vertices;
  r["edges"] = t.edges;
  r["triangles"] = t.triangles;
  r["components"] = t.components.size();
  r["boundary_edges"] = t.boundary_edges;
  r["non_manifold_edges"] = t.non_manifold_edges;
  r["non_manifold_vertices"] = t.non_manifold_vertices;
  r["inconsistent_edges"] = t.inconsistent_edges;
  r["degenerate_triangles"] = t.degenerate_triangles;
  r["unreferenced_vertices"] = t.unreferenced_vertices;
  r["duplicate_vertices"] = t.duplicate_vertices;
  r["euler_characteristic"] = t.euler_characteristic;
  r["genus"] = t.genus;
  r["watertight"] = t.watertight();
  r["manifold"] = t.manifold();
  r["consistently_oriented"] = t.consistently_oriented();
  r["outward_oriented"] = t.outward_oriented();
  return r;
}

py::dict curvature_error(const CurvatureError& c) {
  py::dict r;
  r["vertices"] = c.vertices;
  r["undefined"] = c.undefined;
  r["nrms"] = c.nrms;
  r["abs_error"] = distribution(c.abs_error);
  return r;
}

py::dict accuracy(const AccuracyReport& a) {
  py::dict r;
  r["diagonal"] = a.diagonal;
  r["vertex_distance"] = distribution(a.vertex_distance);
  r["centroid_distance"] = distribution(a.centroid_distance);
  r["triangle_normal_error_degrees"] = distribution(a.triangle_normal_error);
  r["vertex_normal_error_degrees"] = distribution(a.vertex_normal_error);
  r["undefined_samples"] = a.undefined_samples;
  r["mean_curvature"] = curvature_error(a.mean_curvature);
  r["gaussian_curvature"] = curvature_error(a.gaussian_curvature);
  return r;
}

}  // namespace

py::dict report_dict(const QualityReport& q) {
  py::dict r;
  r["topology"] = topology(q.topology);
  py::dict self;
  self["pairs"] = q.self_intersections.pairs;
  self["capped"] = q.self_intersections.capped;
  r["self_intersections"] = self;
  py::dict shape;
  shape["min_angle_degrees"] = distribution(q.shape.min_angle);
  shape["share_below_10_degrees"] = q.shape.share_below_10;
  shape["share_below_20_degrees"] = q.shape.share_below_20;
  shape["share_below_30_degrees"] = q.shape.share_below_30;
  shape["aspect_ratio"] = distribution(q.shape.aspect_ratio);
  shape["quality"] = distribution(q.shape.quality);
  shape["edge_length"] = distribution(q.shape.edge_length);
  shape["edge_length_cv"] = q.shape.edge_length_cv;
  r["shape"] = shape;
  py::dict valence;
  valence["interior_vertices"] = q.valence.interior_vertices;
  valence["other_vertices"] = q.valence.other_vertices;
  valence["histogram"] = q.valence.histogram;
  valence["share_6"] = q.valence.share_6;
  valence["share_5_to_7"] = q.valence.share_5_to_7;
  r["valence"] = valence;
  if (q.accuracy) r["accuracy"] = accuracy(*q.accuracy);
  return r;
}

}  // namespace isopatch::python
