// Summary statistics of a sample: sort once, read the percentiles off the order statistics.
#include <isopatch/error.hpp>
#include <isopatch/metrics.hpp>

#include <algorithm>
#include <cmath>

namespace isopatch {
namespace {

// Linear interpolation at rank q (n - 1) of the sorted sample (R's type 7, numpy's default).
double percentile(const std::vector<double>& sorted, double q) {
  const double rank = q * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(rank));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double t = rank - static_cast<double>(below);
  // Equal neighbours (also two infinities, whose difference is NaN) need no interpolation.
  if (t == 0.0 || sorted[below] == sorted[above]) return sorted[below];
  return sorted[below] + t * (sorted[above] - sorted[below]);
}

}  // namespace

Distribution summarize(std::vector<double> samples) {
  Distribution d;
  d.count = samples.size();
  if (samples.empty()) return d;
  if (std::any_of(samples.begin(), samples.end(), [](double x) { return std::isnan(x); }))
    throw InputError("summarize: a sample is NaN");
  std::sort(samples.begin(), samples.end());
  d.min = samples.front();
  d.max = samples.back();
  d.p1 = percentile(samples, 0.01);
  d.p5 = percentile(samples, 0.05);
  d.median = percentile(samples, 0.5);
  d.p95 = percentile(samples, 0.95);
  d.p99 = percentile(samples, 0.99);
  double sum = 0.0;
  double squares = 0.0;
  for (double x : samples) {
    sum += x;
    squares += x * x;
  }
  const auto n = static_cast<double>(samples.size());
  d.mean = sum / n;
  d.rms = std::sqrt(squares / n);
  return d;
}

}  // namespace isopatch
