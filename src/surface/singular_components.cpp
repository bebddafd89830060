// Converged singular points merged, grouped and described: see singular_components.hpp.
#include "surface/singular_components.hpp"

#include "surface/sign_rule.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <numeric>

#include "core/point_grid.hpp"

namespace isopatch {
namespace singular {
namespace {

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

bool lexicographic_less(const Vec3& a, const Vec3& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

}  // namespace

std::vector<Converged> merge_converged(std::vector<Converged> found, double spacing) {
  std::sort(found.begin(), found.end(), [](const Converged& a, const Converged& b) {
    return a.residual != b.residual ? a.residual < b.residual : a.start < b.start;
  });
  std::vector<Converged> kept;
  PointGrid grid(spacing);
  for (const Converged& c : found) {
    bool close = false;
    grid.near(c.point, [&](std::size_t id) {
      if ((kept[id].point - c.point).norm() < spacing) close = true;
    });
    if (close) continue;
    grid.insert(c.point, kept.size());
    kept.push_back(c);
  }
  return kept;
}

bool smooth_sheet(const Surface& surface, const Vec3& p, double radius) {
  constexpr int kSamples = 256;
  constexpr double kBand = 0.2;    // directions this close to the plane are not judged
  constexpr double kAgree = 0.95;  // share of the judged directions that must agree
  std::array<Vec3, kSamples> directions;
  std::array<int, kSamples> signs;
  Vec3 mean = Vec3::Zero();
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < kSamples; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / kSamples;
    const double r = std::sqrt(1.0 - z * z);
    directions[i] = Vec3(r * std::cos(golden * i), r * std::sin(golden * i), z);
    const double v = surface.value(p + radius * directions[i]);
    if (!std::isfinite(v)) return false;
    signs[i] = is_negative(v) ? -1 : 1;
    mean += signs[i] * directions[i];
  }
  if (!(mean.norm() > 0.0)) return false;
  const Vec3 n = mean.normalized();
  int judged = 0, agree = 0;
  for (int i = 0; i < kSamples; ++i) {
    const double d = n.dot(directions[i]);
    if (std::abs(d) < kBand) continue;
    ++judged;
    if ((d > 0.0) == (signs[i] > 0)) ++agree;
  }
  return judged > 0 && agree >= kAgree * judged;
}

void group_points(const std::vector<Converged>& kept, const std::vector<bool>& smooth, double spacing,
                  SingularPoints* out) {
  const double join = kJoinSpacings * spacing;
  std::vector<std::size_t> parent(kept.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  PointGrid grid(join);
  for (std::size_t i = 0; i < kept.size(); ++i) {
    grid.near(kept[i].point, [&](std::size_t j) {
      if (smooth[i] == smooth[j] && (kept[j].point - kept[i].point).norm() < join) {
        const std::size_t a = find_root(parent, i), b = find_root(parent, j);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
      }
    });
    grid.insert(kept[i].point, i);
  }
  // Members by root, in kept order (so the first member is the one with the smallest residual).
  std::unordered_map<std::size_t, std::vector<std::size_t>> members;
  std::vector<std::size_t> roots;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const std::size_t r = find_root(parent, i);
    auto [it, fresh] = members.try_emplace(r);
    if (fresh) roots.push_back(r);
    it->second.push_back(i);
  }
  struct Group {
    SingularComponent component;
    std::vector<Vec3> samples;
  };
  std::vector<Group> groups;
  groups.reserve(roots.size());
  for (const std::size_t r : roots) {
    const std::vector<std::size_t>& ids = members[r];
    Group g;
    const Vec3& first = kept[ids.front()].point;
    g.component.position = first;
    g.component.samples = ids.size();
    g.component.curve = ids.size() > 1;
    g.component.smooth_sheet = smooth[ids.front()];
    g.component.extent = Box{first, first};
    for (const std::size_t id : ids) {
      const Vec3& p = kept[id].point;
      g.samples.push_back(p);
      g.component.extent.lo = g.component.extent.lo.cwiseMin(p);
      g.component.extent.hi = g.component.extent.hi.cwiseMax(p);
    }
    std::sort(g.samples.begin(), g.samples.end(), lexicographic_less);
    groups.push_back(std::move(g));
  }
  std::sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) {
    if (a.component.smooth_sheet != b.component.smooth_sheet) return !a.component.smooth_sheet;
    return lexicographic_less(a.component.position, b.component.position);
  });
  out->points.clear();
  out->components.clear();
  for (Group& g : groups) {
    out->components.push_back(g.component);
    out->points.insert(out->points.end(), g.samples.begin(), g.samples.end());
  }
}

}  // namespace singular

const char* status_name(SingularSearchStatus status) {
  switch (status) {
    case SingularSearchStatus::Complete:
      return "complete";
    case SingularSearchStatus::BudgetExhausted:
      return "budget exhausted";
    case SingularSearchStatus::NotSearched:
      return "not searched";
  }
  return "not searched";
}

std::size_t SingularPoints::isolated_points() const {
  return static_cast<std::size_t>(
      std::count_if(components.begin(), components.end(),
                    [](const SingularComponent& c) { return !c.smooth_sheet && !c.curve; }));
}

std::size_t SingularPoints::curves() const {
  return static_cast<std::size_t>(
      std::count_if(components.begin(), components.end(),
                    [](const SingularComponent& c) { return !c.smooth_sheet && c.curve; }));
}

std::size_t SingularPoints::degenerate() const {
  return components.size() - isolated_points() - curves();
}

std::vector<Vec3> SingularPoints::singular_samples() const {
  std::vector<Vec3> out;
  std::size_t first = 0;
  for (const SingularComponent& c : components) {
    if (!c.smooth_sheet) out.insert(out.end(), points.begin() + first, points.begin() + first + c.samples);
    first += c.samples;
  }
  return out;
}

std::string format_singular_point(const Vec3& p, double zero) {
  const auto shown = [&](double c) { return std::abs(c) < zero ? 0.0 : c; };
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", shown(p.x()), shown(p.y()), shown(p.z()));
  return text;
}

namespace {

/// The components of one kind named one after another, at most `listed`, then "and N more".
std::string list_components(const SingularPoints& found, bool smooth_sheet, double zero, std::size_t listed) {
  std::string text;
  std::size_t shown = 0, total = 0;
  for (const SingularComponent& c : found.components) {
    if (c.smooth_sheet != smooth_sheet) continue;
    if (total++ >= listed) continue;
    if (shown++ > 0) text += ", ";
    if (c.curve)
      text += "a curve of " + std::to_string(c.samples) + " samples within " +
              format_singular_point(c.extent.lo, zero) + " .. " + format_singular_point(c.extent.hi, zero);
    else
      text += format_singular_point(c.position, zero);
  }
  if (total > shown) text += " and " + std::to_string(total - shown) + " more";
  return text;
}

std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::string describe_singular_points(const SingularPoints& found, const Box& box, std::size_t listed) {
  const std::size_t points = found.isolated_points(), curves = found.curves();
  if (points + curves == 0) return {};
  std::string text;
  if (points > 0) text = plural(points, "singular point", "singular points");
  if (curves > 0)
    text += (text.empty() ? "" : " and ") +
            plural(curves, "curve of singular points", "curves of singular points");
  text += " of f = 0 (grad f = 0) in the box: " +
          list_components(found, false, 1e-9 * box.size().maxCoeff(), listed);
  if (found.status == SingularSearchStatus::BudgetExhausted)
    text += " (the search stopped at its budget: there may be more)";
  return text;
}

std::string describe_degenerate_points(const SingularPoints& found, const Box& box, std::size_t listed) {
  if (found.degenerate() == 0) return {};
  return "grad f also vanishes where f = 0 is a smooth sheet (f is degenerate there, the surface is not): " +
         list_components(found, true, 1e-9 * box.size().maxCoeff(), listed);
}

}  // namespace isopatch
