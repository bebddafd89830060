// analyze_quality: the topology, self-intersections, shape, valence and accuracy reports of one mesh
// together.
#include <isopatch/metrics.hpp>

namespace isopatch {

QualityReport analyze_quality(const Mesh& mesh, const Surface* surface) {
  QualityReport report;
  report.topology = analyze_topology(mesh);  // validates the indices and positions first
  report.self_intersections = find_self_intersections(mesh);
  report.shape = analyze_shape(mesh);
  report.valence = analyze_valence(mesh);
  if (surface != nullptr) report.accuracy = analyze_accuracy(mesh, *surface);
  return report;
}

}  // namespace isopatch
