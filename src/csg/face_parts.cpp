/// \file face_parts.cpp
/// Parts of the faces on the coarse mesh and the shapes of their cycles (face_parts.hpp).
#include "csg/face_parts.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace isopatch {

Parts initial_parts(const ShapeSamples& s) {
  Parts parts;
  const std::size_t n = s.mesh.positions.size();
  parts.neighbours.resize(n);
  for (const Triangle& t : s.mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      parts.neighbours[a].push_back(static_cast<int>(b));
      parts.neighbours[b].push_back(static_cast<int>(a));
    }
  for (auto& list : parts.neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  parts.part.assign(n, -1);
  std::vector<int> all(n);
  for (std::size_t v = 0; v < n; ++v) all[v] = static_cast<int>(v);
  // Every vertex its own part first, then components of equal faces.
  parts.count = 0;
  std::vector<int> stack;
  for (std::size_t s0 = 0; s0 < n; ++s0) {
    if (parts.part[s0] >= 0) continue;
    const int id = parts.count++;
    parts.part[s0] = id;
    stack.push_back(static_cast<int>(s0));
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (const int w : parts.neighbours[static_cast<std::size_t>(v)])
        if (parts.part[static_cast<std::size_t>(w)] < 0 &&
            s.face[static_cast<std::size_t>(w)] == s.face[s0]) {
          parts.part[static_cast<std::size_t>(w)] = id;
          stack.push_back(w);
        }
    }
  }
  return parts;
}

CycleShape cycle_shape(const CreaseGraph& g, const FaceCycle& c) {
  CycleShape s;
  for (const HalfCurve& h : c.sides) {
    const std::vector<Vec3> p = half_points(g, h);
    s.points.insert(s.points.end(), p.begin(), p.end() - 1);
    for (std::size_t k = 1; k < p.size(); ++k) s.length += (p[k] - p[k - 1]).norm();
  }
  for (const Vec3& p : s.points) s.centroid += p;
  s.centroid /= static_cast<double>(s.points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : s.points) cov += (p - s.centroid) * (p - s.centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  s.normal = eig.eigenvectors().col(0);
  return s;
}

Concavity concavity(const CycleShape& s, const Surface& f) {
  const std::size_t n = s.points.size();
  Concavity best;
  if (n < 3) return best;
  std::vector<double> turn(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = s.points[i];
    const Vec3 a = p - s.points[(i + n - 1) % n], b = s.points[(i + 1) % n] - p;
    const Vec3 normal = f.value_gradient(p).gradient.normalized();
    turn[i] = std::atan2(normal.dot(a.cross(b)), a.dot(b));
    if (-turn[i] > best.sharpest) {
      best.sharpest = -turn[i];
      best.sharpest_at = p;
      best.sharpest_in = a;
    }
  }
  // Start after a left turn so that no stretch wraps round the start.
  std::size_t first = 0;
  while (first < n && turn[first] <= 1e-9) ++first;
  if (first == n) return best;
  for (std::size_t k = 1; k <= n;) {
    const std::size_t i = (first + k) % n;
    if (turn[i] > 1e-9) {
      ++k;
      continue;
    }
    double sum = 0.0;
    std::size_t end = k;
    std::vector<std::size_t> run;
    while (end <= n && turn[(first + end) % n] <= 1e-9) {
      run.push_back((first + end) % n);
      sum -= turn[(first + end) % n];
      ++end;
    }
    if (sum > best.turn) {
      best.turn = sum;
      double half = 0.0;
      std::size_t lo = run.size(), hi = 0;
      for (std::size_t r = 0; r < run.size(); ++r)
        if (turn[run[r]] < -1e-9) {
          lo = std::min(lo, r);
          hi = r;
        }
      for (const std::size_t r : run) {
        half -= turn[r];
        if (half >= 0.5 * sum) {
          best.middle = s.points[r];
          break;
        }
      }
      if (lo < run.size()) best.chord = s.points[run[hi]] - s.points[run[lo]];
    }
    k = end;
  }
  return best;
}

}  // namespace isopatch
