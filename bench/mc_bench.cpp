// Marching cubes throughput on the torus (R = 1, r = 0.4) written as a C++ callable, so the numbers do
// not depend on the expression evaluator. Counters: output vertices, vertices per second and f
// evaluations (grid samples plus root finding) per run.
#include <isopatch/callable_surface.hpp>
#include <isopatch/marching_cubes.hpp>

#include <benchmark/benchmark.h>

namespace {

isopatch::SurfacePtr bench_torus() {
  return isopatch::make_surface(
      [](auto x, auto y, auto z) {
        auto q = x * x + y * y + z * z + 1.0 - 0.16;
        return q * q - 4.0 * (x * x + y * y);
      },
      isopatch::Box{isopatch::Vec3(-1.6, -1.6, -0.6), isopatch::Vec3(1.6, 1.6, 0.6)}, "torus");
}

void run(benchmark::State& state, isopatch::EdgeRoot edge_root) {
  const isopatch::SurfacePtr surface = bench_torus();
  isopatch::Settings settings;
  settings.method = isopatch::Method::MarchingCubes;
  settings.grid = static_cast<int>(state.range(0));
  settings.edge_root = edge_root;
  isopatch::MeshStats stats;
  std::size_t vertices = 0;
  for (auto _ : state) {
    const isopatch::Mesh mesh = isopatch::marching_cubes(*surface, settings, &stats);
    vertices += mesh.vertex_count();
    benchmark::DoNotOptimize(mesh.positions.data());
  }
  state.counters["vertices"] = static_cast<double>(stats.vertices);
  state.counters["vertices_per_second"] =
      benchmark::Counter(static_cast<double>(vertices), benchmark::Counter::kIsRate);
  state.counters["f_evaluations"] = static_cast<double>(stats.value_evaluations);
}

void BM_MarchingCubesTorusBracketed(benchmark::State& state) {
  run(state, isopatch::EdgeRoot::Bracketed);
}
void BM_MarchingCubesTorusLinear(benchmark::State& state) {
  run(state, isopatch::EdgeRoot::Linear);
}

BENCHMARK(BM_MarchingCubesTorusBracketed)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MarchingCubesTorusLinear)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
