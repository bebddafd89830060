// The cache keeps the first value computed at each half-lattice point; gradients are added lazily
// from Surface::value_gradient, whose own value is discarded so that the sign of a point never
// depends on which evaluator (plain or differentiated) happened to run first. A point or segment is
// entered only after its evaluation succeeded, so an EvaluationError leaves the cache consistent.
#include "partition/sample_cache.hpp"

#include <optional>

namespace isopatch {

double SampleCache::value(const LatticePoint& h) {
  const std::uint64_t key = half_key(h);
  if (const auto index = point_index_.find(key)) return samples_[*index].value;
  if (base_)
    if (const auto shared = base_->point_index_.find(key)) return base_->samples_[*shared].value;
  return own_sample(key, h).value;
}

SampleCache::Sample& SampleCache::own_sample(std::uint64_t key, const LatticePoint& h) {
  if (const auto index = point_index_.find(key)) return samples_[*index];
  Sample s;
  if (const auto shared = base_ ? base_->point_index_.find(key) : std::nullopt)
    s = base_->samples_[*shared];  // a copy, to which this overlay adds the gradient
  else
    s.value = sampler_.value(lattice_.half_point(h));
  point_index_.insert(key);
  samples_.push_back(s);
  if (base_) sample_keys_.push_back(key);  // only an overlay merges, so only it needs the keys
  return samples_.back();
}

Vec3 SampleCache::gradient(const LatticePoint& h) {
  const std::uint64_t key = half_key(h);
  if (base_ && !point_index_.find(key))
    if (const auto shared = base_->point_index_.find(key); shared && base_->samples_[*shared].has_gradient)
      return base_->samples_[*shared].gradient;
  Sample& s = own_sample(key, h);
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
  if (base_)
    if (const auto shared = base_->segment_index_.find(key))
      return {base_->segment_values_.data() + *shared * n, n};
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
  if (base_) segment_keys_.push_back(key);
  return {segment_values_.data() + offset, n};
}

SampleCache SampleCache::overlay(const SampleCache& base) {
  SampleCache cache(base.sampler_, base.lattice_, base.segment_samples_);
  cache.base_ = &base;
  return cache;
}

void SampleCache::merge_into(SampleCache& base) const {
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const auto [index, inserted] = base.point_index_.insert(sample_keys_[i]);
    if (inserted) {
      base.samples_.push_back(samples_[i]);
      if (base.base_) base.sample_keys_.push_back(sample_keys_[i]);
    } else if (samples_[i].has_gradient && !base.samples_[index].has_gradient) {
      base.samples_[index] = samples_[i];
    }
  }
  const auto n = static_cast<std::size_t>(segment_samples_);
  for (std::size_t i = 0; i < segment_keys_.size(); ++i)
    if (base.segment_index_.insert(segment_keys_[i]).second) {
      if (base.base_) base.segment_keys_.push_back(segment_keys_[i]);
      const auto from = segment_values_.begin() + static_cast<std::ptrdiff_t>(i * n);
      base.segment_values_.insert(base.segment_values_.end(), from, from + static_cast<std::ptrdiff_t>(n));
    }
  base.segment_evaluations_ += segment_evaluations_;
}

}  // namespace isopatch
