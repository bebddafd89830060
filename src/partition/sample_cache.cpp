// The cache keeps the first value computed at each half-lattice point; gradients are added lazily
// from Surface::value_gradient, whose own value is discarded so that the sign of a point never
// depends on which evaluator (plain or differentiated) happened to run first. A point or segment is
// entered only after its evaluation succeeded, so an EvaluationError leaves the cache consistent.
#include "partition/sample_cache.hpp"

namespace isopatch {

SampleCache::Sample& SampleCache::sample(const LatticePoint& h) {
  const std::uint64_t key = half_key(h);
  if (const auto index = point_index_.find(key)) return samples_[*index];
  const double v = sampler_.value(lattice_.half_point(h));
  point_index_.insert(key);
  samples_.push_back(Sample{v});
  return samples_.back();
}

Vec3 SampleCache::gradient(const LatticePoint& h) {
  Sample& s = sample(h);
  if (!s.has_gradient) {
    // A gradient that is not finite (f not differentiable there, e.g. sqrt at the edge of its domain
    // on a box face) is kept as it is: the sampling tests treat it as failing (no pruning, no single
    // sheet), while the crossings that need it raise EvaluationError themselves.
    s.gradient = sampler_.value_gradient_unchecked(lattice_.half_point(h)).gradient;
    s.has_gradient = true;
  }
  return s.gradient;
}

std::span<const double> SampleCache::segment_samples(const SegmentKey& key) {
  const auto n = static_cast<std::size_t>(segment_samples_);
  if (const auto index = segment_index_.find(key)) return {segment_values_.data() + *index * n, n};
  const Vec3 a = lattice_.point(key.start);
  const Vec3 b = lattice_.point(key.end());
  // One batch per segment: the batch evaluator gives the single-point values bit for bit, at a
  // fraction of the cost per point.
  points_.resize(n);
  for (std::size_t k = 1; k <= n; ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(n + 1);
    points_[k - 1] = (1.0 - t) * a + t * b;
  }
  const std::size_t offset = segment_values_.size();
  segment_values_.resize(offset + n);
  try {
    sampler_.values(points_, std::span<double>(segment_values_.data() + offset, n));
  } catch (...) {
    segment_values_.resize(offset);
    throw;
  }
  segment_evaluations_ += n;
  segment_index_.insert(key);
  return {segment_values_.data() + offset, n};
}

}  // namespace isopatch
