// Time of the self-intersection check (find_self_intersections) on a mesh file: the check the CLI runs
// after every mesh. Usage: bench_self_intersection MESH [--repeat N]; prints the pairs found and the
// median, smallest and largest wall time of N runs (default 5), the mesh read once before.
#include <isopatch/mesh_io.hpp>
#include <isopatch/self_intersection.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_self_intersection MESH [--repeat N]\n");
    return 2;
  }
  int repeat = 5;
  if (argc == 4 && std::string(argv[2]) == "--repeat") repeat = std::max(1, std::atoi(argv[3]));
  const isopatch::Mesh mesh = isopatch::read_mesh(argv[1]);
  std::vector<double> seconds;
  isopatch::SelfIntersectionReport report;
  for (int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    report = isopatch::find_self_intersections(mesh);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  std::printf("%zu triangles, %zu intersecting pairs: median %.4f s, min %.4f s, max %.4f s (%d runs)\n",
              mesh.triangles.size(), report.pairs, seconds[seconds.size() / 2], seconds.front(),
              seconds.back(), repeat);
  return 0;
}
