// Speed of the expression evaluators against the same functions compiled as C++ lambdas, on the
// torus and the tanglecube: batch values, single-point values, value with gradient (forward mode)
// and interval bounds. Prints points (or boxes) per second and the ratio tape / lambda at the end.
#include <isopatch/autodiff.hpp>
#include <isopatch/catalogue.hpp>
#include <isopatch/expression.hpp>
#include <isopatch/interval_math.hpp>

#include <benchmark/benchmark.h>

#include <array>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace isopatch {
namespace {

// ---- number types the lambdas are instantiated with ------------------------------------------

// Value and gradient: the library's first-order jet (autodiff.hpp), the compiled counterpart of
// Expression::value_gradient.
using Dual = GradientJet;

inline double sq(double a) {
  return a * a;
}
inline Dual sq(const Dual& a) {
  return a * a;
}
inline Interval sq(const Interval& a) {
  return sqr(a);
}

template <class T>
T constant(double c);
template <>
double constant<double>(double c) {
  return c;
}
template <>
Dual constant<Dual>(double c) {
  return Dual(c);
}
template <>
Interval constant<Interval>(double c) {
  return {c, c};
}

template <class T>
T torus(T x, T y, T z) {
  const T q = sq(x) + sq(y) + sq(z) + constant<T>(1.0 - 0.16);
  return sq(q) - constant<T>(4.0) * (sq(x) + sq(y));
}

template <class T>
T tanglecube(T x, T y, T z) {
  const T x2 = sq(x), y2 = sq(y), z2 = sq(z), five = constant<T>(5.0);
  return sq(x2) - five * x2 + sq(y2) - five * y2 + sq(z2) - five * z2 + constant<T>(11.8);
}

// ---- workloads --------------------------------------------------------------------------------

constexpr std::size_t kPoints = 4096;

struct Workload {
  std::string name;
  Expression expression;
  Box box;
  std::vector<Vec3> points;
  std::vector<double> xs, ys, zs;
  std::vector<Box> boxes;
};

Workload make_workload(const std::string& name) {
  const CatalogueEntry* e = find_in_catalogue(name);
  Workload w{name, parse_expression(e->formula), e->box, {}, {}, {}, {}, {}};
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < kPoints; ++i) {
    Vec3 p;
    for (int k = 0; k < 3; ++k) p[k] = w.box.lo[k] + u(rng) * (w.box.hi[k] - w.box.lo[k]);
    w.points.push_back(p);
    w.xs.push_back(p.x());
    w.ys.push_back(p.y());
    w.zs.push_back(p.z());
    const Vec3 half = 0.02 * (w.box.hi - w.box.lo);
    w.boxes.push_back(Box{p - half, p + half});
  }
  return w;
}

template <class F>
void register_pair(const std::string& group, const Workload& w, F lambda_f) {
  const Workload* wp = &w;
  benchmark::RegisterBenchmark((group + "/" + w.name + "/batch/lambda").c_str(),
                               [wp, lambda_f](benchmark::State& s) {
                                 std::vector<double> out(kPoints);
                                 for (auto _ : s) {
                                   const Vec3* p = wp->points.data();
                                   for (std::size_t i = 0; i < kPoints; ++i)
                                     out[i] = lambda_f(p[i].x(), p[i].y(), p[i].z());
                                   benchmark::DoNotOptimize(out.data());
                                   benchmark::ClobberMemory();
                                 }
                                 s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations() * kPoints));
                               });
  benchmark::RegisterBenchmark((group + "/" + w.name + "/batch/tape").c_str(), [wp](benchmark::State& s) {
    std::vector<double> out(kPoints);
    for (auto _ : s) {
      wp->expression.values(wp->points, out);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
    s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations() * kPoints));
  });
  benchmark::RegisterBenchmark((group + "/" + w.name + "/batch_soa/tape").c_str(), [wp](benchmark::State& s) {
    std::vector<double> out(kPoints);
    for (auto _ : s) {
      wp->expression.values(wp->xs.data(), wp->ys.data(), wp->zs.data(), out.data(), kPoints);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
    s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations() * kPoints));
  });
  benchmark::RegisterBenchmark((group + "/" + w.name + "/point/tape").c_str(), [wp](benchmark::State& s) {
    double sum = 0.0;
    for (auto _ : s) {
      for (const Vec3& p : wp->points) sum += wp->expression.value(p);
      benchmark::DoNotOptimize(sum);
    }
    s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations() * kPoints));
  });
  benchmark::RegisterBenchmark(
      (group + "/" + w.name + "/gradient/lambda").c_str(), [wp, lambda_f](benchmark::State& s) {
        double sum = 0.0;
        for (auto _ : s) {
          for (const Vec3& p : wp->points) {
            const Dual d =
                lambda_f(Dual::variable(0, p.x()), Dual::variable(1, p.y()), Dual::variable(2, p.z()));
            sum += d.v + d.g[0] + d.g[1] + d.g[2];
          }
          benchmark::DoNotOptimize(sum);
        }
        s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations() * kPoints));
      });
  benchmark::RegisterBenchmark((group + "/" + w.name + "/gradient/tape").c_str(), [wp](benchmark::State& s) {
    double sum = 0.0;
    for (auto _ : s) {
      for (const Vec3& p : wp->points) {
        const ValueGradient vg = wp->expression.value_gradient(p);
        sum += vg.value + vg.gradient.sum();
      }
      benchmark::DoNotOptimize(sum);
    }
    s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations() * kPoints));
  });
  benchmark::RegisterBenchmark(
      (group + "/" + w.name + "/interval/lambda").c_str(), [wp, lambda_f](benchmark::State& s) {
        double sum = 0.0;
        for (auto _ : s) {
          for (const Box& b : wp->boxes) {
            const Interval r = lambda_f(Interval{b.lo.x(), b.hi.x()}, Interval{b.lo.y(), b.hi.y()},
                                        Interval{b.lo.z(), b.hi.z()});
            sum += r.lo + r.hi;
          }
          benchmark::DoNotOptimize(sum);
        }
        s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations() * kPoints));
      });
  benchmark::RegisterBenchmark((group + "/" + w.name + "/interval/tape").c_str(), [wp](benchmark::State& s) {
    double sum = 0.0;
    for (auto _ : s) {
      for (const Box& b : wp->boxes) {
        const Interval r = wp->expression.bound(b);
        sum += r.lo + r.hi;
      }
      benchmark::DoNotOptimize(sum);
    }
    s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations() * kPoints));
  });
}

/// Remembers every benchmark's rate so the ratios can be printed after the run.
class RateReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      const auto it = r.counters.find("items_per_second");
      if (it == r.counters.end()) continue;
      // With --benchmark_repetitions the median stands for the benchmark.
      if (r.run_type == Run::RT_Iteration && !medians_.count(r.run_name.str()))
        rates[r.run_name.str()] = it->second.value;
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name == "median") {
        rates[r.run_name.str()] = it->second.value;
        medians_.insert(r.run_name.str());
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
  std::map<std::string, double> rates;

 private:
  std::set<std::string> medians_;
};

}  // namespace
}  // namespace isopatch

int main(int argc, char** argv) {
  using namespace isopatch;
  static const Workload torus_w = make_workload("torus");
  static const Workload tangle_w = make_workload("tanglecube");
  const auto torus_f = [](auto x, auto y, auto z) { return torus(x, y, z); };
  const auto tangle_f = [](auto x, auto y, auto z) { return tanglecube(x, y, z); };
  register_pair("expr", torus_w, torus_f);
  register_pair("expr", tangle_w, tangle_f);

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RateReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);

  std::printf("\n%-11s %-22s %16s %16s %8s\n", "surface", "evaluator", "lambda /s", "tape /s", "ratio");
  const std::pair<const char*, const char*> rows[] = {{"batch", "batch values (AoS)"},
                                                      {"batch_soa", "batch values (SoA)"},
                                                      {"point", "single-point value"},
                                                      {"gradient", "value + gradient"},
                                                      {"interval", "interval bound"}};
  for (const char* surface : {"torus", "tanglecube"}) {
    for (const auto& [key, label] : rows) {
      const std::string base = std::string("expr/") + surface + "/";
      const std::string lambda_key =
          base + (std::string(key) == "gradient" || std::string(key) == "interval" ? key : "batch") +
          "/lambda";
      const auto l = reporter.rates.find(lambda_key);
      const auto t = reporter.rates.find(base + key + "/tape");
      if (l == reporter.rates.end() || t == reporter.rates.end()) continue;
      std::printf("%-11s %-22s %16.3e %16.3e %8.3f\n", surface, label, l->second, t->second,
                  t->second / l->second);
    }
  }
  return 0;
}
