#pragma once
/// \file sample_cache.hpp
/// Values and gradients of f on the half lattice, cached by packed integer coordinates
/// (docs/algorithms.md 2.2), plus the interior samples of lattice segments used by the edge test. Every
/// value is checked (NaN or infinity throws EvaluationError naming the point) and counted. Not
/// thread-safe: one per build, plus one overlay per task of a parallel step (overlay(), merge_into()).

#include "partition/index_map.hpp"
#include "partition/lattice.hpp"
#include "surface/sampler.hpp"

#include <cstdint>
#include <span>
#include <vector>

#include "surface/sign_rule.hpp"

namespace isopatch {

class SampleCache {
 public:
  /// \param segment_samples  the number of interior samples per segment (edge test), >= 0
  SampleCache(const Sampler& sampler, const Lattice& lattice, int segment_samples)
      : sampler_(sampler), lattice_(lattice), segment_samples_(segment_samples) {}

  /// f at the half-lattice point h, evaluated once. \throw EvaluationError when not finite.
  double value(const LatticePoint& h);
  /// grad f at the half-lattice point h, evaluated once on first request. The value at h is always
  /// the one of value(h), whichever is asked first. May be NaN or infinite (f not differentiable
  /// there): callers treat such a gradient as failing their test. \throw EvaluationError when the
  /// value at h is not finite.
  Vec3 gradient(const LatticePoint& h);

  /// f at the segment_samples points strictly inside the segment, t = k / (n + 1), k = 1..n, from
  /// key.start to key.end(); evaluated once per segment. The span is valid until the next call.
  std::span<const double> segment_samples(const SegmentKey& key);

  std::uint64_t segment_sample_evaluations() const { return segment_evaluations_; }
  const Lattice& lattice() const { return lattice_; }

  /// An empty cache on top of `base` for one task: it reads what base holds and evaluates and keeps the
  /// rest itself. \pre base does not change while the overlay lives (many overlays may read it at once).
  static SampleCache overlay(const SampleCache& base);
  /// Hands what this overlay evaluated to `base` (points base lacks, gradients it lacks, segments it
  /// lacks, the segment-sample count). The values are those base would have computed: a point's value
  /// is a function of the point.
  void merge_into(SampleCache& base) const;

 private:
  struct Sample {
    double value = 0.0;
    Vec3 gradient = Vec3::Zero();
    bool has_gradient = false;
  };
  /// The sample of `key` (= half_key(h)) held by this cache itself: copied from base_ or evaluated.
  Sample& own_sample(std::uint64_t key, const LatticePoint& h);

  const Sampler& sampler_;
  const SampleCache* base_ = nullptr;  // read-only, for an overlay
  Lattice lattice_;
  int segment_samples_;
  IndexMap<std::uint64_t, Mix64Hash> point_index_;
  std::vector<Sample> samples_;
  std::vector<std::uint64_t> sample_keys_;  // an overlay's: the key of each sample, same order
  IndexMap<SegmentKey, SegmentKeyHash> segment_index_;
  std::vector<double> segment_values_;    // segment_samples_ consecutive values per segment
  std::vector<SegmentKey> segment_keys_;  // an overlay's: the key of each segment, same order
  std::vector<Vec3> points_;              // scratch: one segment's sample points
  std::uint64_t segment_evaluations_ = 0;
};

}  // namespace isopatch
