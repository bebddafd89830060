#include "flying_edges.hpp"

#include <isopatch/error.hpp>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMP.h>  // VTK_SMP_BACKEND (vtkSMPTools.h itself does not compile as C++20)

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "peer_support/orient.hpp"

namespace isopatch::bench {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The grid of `box`: cubic cells of side `spacing`, points per axis reaching box.hi.
std::array<int, 3> grid_points(const Box& box, double spacing) {
  std::array<int, 3> n{};
  for (int axis = 0; axis < 3; ++axis)
    n[static_cast<std::size_t>(axis)] =
        std::max(2, static_cast<int>(std::ceil(box.size()[axis] / spacing - 1e-9)) + 1);
  return n;
}

// Fills values (x fastest, then y, then z) with f at the grid points, z-slices split over `threads`
// threads; a non-finite value becomes +1 (outside) and is counted.
std::size_t sample(const Surface& surface, const Box& box, double spacing, const std::array<int, 3>& n,
                   int threads, std::span<double> values) {
  const std::size_t slice = static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]);
  std::atomic<int> next{0};
  std::atomic<std::size_t> non_finite{0};
  std::mutex failure_mutex;
  std::exception_ptr failure;  // the first exception of a thread, rethrown once all have joined
  auto slices = [&] {
    std::vector<Vec3> points(slice);
    std::size_t bad = 0;
    for (int k = next++; k < n[2]; k = next++) {
      std::size_t i = 0;
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x) points[i++] = box.lo + spacing * Vec3(x, y, k);
      const std::span<double> out = values.subspan(static_cast<std::size_t>(k) * slice, slice);
      surface.values(points, out);
      for (double& v : out)
        if (!std::isfinite(v)) {
          v = 1.0;
          ++bad;
        }
    }
    non_finite += bad;
  };
  auto worker = [&] {
    try {
      slices();
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = n[2];  // the others stop at their next slice
    }
  };
  {
    std::vector<std::jthread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
  }  // joins
  if (failure) std::rethrow_exception(failure);
  return non_finite;
}

// VTK's triangles as an isopatch Mesh; triangles with a repeated vertex are dropped and counted.
std::size_t to_mesh(vtkPolyData& poly, Mesh& mesh) {
  vtkPoints* points = poly.GetPoints();
  const vtkIdType count = points ? points->GetNumberOfPoints() : 0;
  mesh.positions.resize(static_cast<std::size_t>(count));
  for (vtkIdType i = 0; i < count; ++i) {
    double p[3];
    points->GetPoint(i, p);
    mesh.positions[static_cast<std::size_t>(i)] = Vec3(p[0], p[1], p[2]);
  }
  std::size_t dropped = 0;
  vtkCellArray* polys = poly.GetPolys();
  mesh.triangles.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()));
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(size, ids);) {
    if (size != 3) continue;
    const Triangle t{static_cast<std::uint32_t>(ids[0]), static_cast<std::uint32_t>(ids[1]),
                     static_cast<std::uint32_t>(ids[2])};
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      ++dropped;
    else
      mesh.triangles.push_back(t);
  }
  return dropped;
}

}  // namespace

FlyingEdgesResult flying_edges(const Surface& surface, const Box& box, const FlyingEdgesOptions& options) {
  if (!box.valid()) throw InputError("invalid box");
  if (options.grid < 2 || options.threads < 1)
    throw InputError("Flying Edges needs grid >= 2 and threads >= 1");
  // VTK reads its thread count from the environment when its SMP tools first start (in Update below).
  setenv("VTK_SMP_MAX_THREADS", std::to_string(options.threads).c_str(), 1);
  FlyingEdgesResult r;
  r.smp_backend = VTK_SMP_BACKEND;
  const double spacing = box.size().maxCoeff() / options.grid;
  r.samples = grid_points(box, spacing);
  r.value_evaluations = static_cast<std::size_t>(r.samples[0]) * static_cast<std::size_t>(r.samples[1]) *
                        static_cast<std::size_t>(r.samples[2]);

  const auto start = Clock::now();
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(r.value_evaluations));
  r.non_finite_values = sample(surface, box, spacing, r.samples, options.threads,
                               std::span<double>(scalars->GetPointer(0), r.value_evaluations));
  r.sample_seconds = since(start);

  const auto contour_start = Clock::now();
  vtkNew<vtkImageData> image;
  image->SetDimensions(r.samples[0], r.samples[1], r.samples[2]);
  image->SetOrigin(box.lo.x(), box.lo.y(), box.lo.z());
  image->SetSpacing(spacing, spacing, spacing);
  image->GetPointData()->SetScalars(scalars);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  r.contour_seconds = since(contour_start);

  const auto convert_start = Clock::now();
  r.degenerate_dropped = to_mesh(*contour->GetOutput(), r.mesh);
  r.convert_seconds = since(convert_start);
  r.seconds = since(start);
  orient_along_gradient(r.mesh, surface);
  return r;
}

}  // namespace isopatch::bench
