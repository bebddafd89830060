#pragma once
// The sign rule of docs/algorithms.md 1.3, shared by every sampler of f: a sample with f >= 0 counts
// as positive, so f = 0 exactly at a sample never makes a crossing of its own.

namespace isopatch {

/// f < 0: the sample counts as negative (inside).
inline bool is_negative(double value) {
  return value < 0.0;
}

}  // namespace isopatch
