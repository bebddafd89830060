// Blocked meshing for isopatch.distributed (blocks.hpp). A surface is named by a source dict, the same
// on the driver and on every worker: {"spec": formula, catalogue name, @file or a composite's .ipatch
// file, "params": {...}} or
// {"volume": path of a .npy or .nrrd file, "level": value}, with "coefficients" (a .npy of its B-spline
// coefficients made by the distributed prefilter, mapped instead of the volume read), "spacing" and
// "origin" when a blocked run made them.
#include "blocks.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <isopatch/blocks.hpp>
#include <isopatch/composite_mesh.hpp>
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/volume_io.hpp>
#include <isopatch/volume_surface.hpp>

#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "arrays.hpp"
#include "run_released.hpp"
#include "settings_args.hpp"
#include "surface_source.hpp"

namespace py = pybind11;

namespace isopatch::python {
namespace {

Mesh to_mesh(const Positions& positions, const Indices& triangles) {
  if (positions.ndim() != 2 || positions.shape(1) != 3)
    throw InputError("base positions must be (V, 3)", "base");
  if (triangles.ndim() != 2 || triangles.shape(1) != 3)
    throw InputError("base triangles must be (T, 3)", "base");
  Mesh mesh;
  const double* p = positions.data();
  for (py::ssize_t i = 0; i < positions.shape(0); ++i)
    mesh.positions.emplace_back(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
  const std::uint32_t* t = triangles.data();
  for (py::ssize_t i = 0; i < triangles.shape(0); ++i)
    mesh.triangles.push_back({t[3 * i], t[3 * i + 1], t[3 * i + 2]});
  mesh.validate();
  return mesh;
}

/// A composite base's patches as arrays: triangle_patch, curve_segments, and the curves' vertices
/// flattened (curve_vertices) with where each curve's begin (curve_offsets, one more than the curves).
py::dict patches_dict(const BasePatches& patches) {
  std::vector<std::int64_t> offsets{0};
  std::vector<std::uint32_t> vertices;
  for (const auto& curve : patches.curve_vertices) {
    vertices.insert(vertices.end(), curve.begin(), curve.end());
    offsets.push_back(static_cast<std::int64_t>(vertices.size()));
  }
  const auto array = [](const auto& v) { return vector_array(v); };
  py::dict out;
  out["triangle_patch"] = array(patches.triangle_patch);
  out["curve_segments"] =
      array(std::vector<std::int32_t>(patches.curve_segments.begin(), patches.curve_segments.end()));
  out["curve_offsets"] = array(offsets);
  out["curve_vertices"] = array(vertices);
  return out;
}

/// patches_dict() read back. \throw InputError when the arrays do not fit together.
BasePatches to_patches(const py::dict& arrays) {
  const auto get = [&](const char* key) {
    if (!arrays.contains(key))
      throw InputError(std::string("the base's patches have no '") + key + "'", "base");
    return arrays[key];
  };
  BasePatches out;
  const auto patch =
      get("triangle_patch").cast<py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>>();
  out.triangle_patch.assign(patch.data(), patch.data() + patch.size());
  const auto segments =
      get("curve_segments").cast<py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>>();
  out.curve_segments.assign(segments.data(), segments.data() + segments.size());
  const auto offsets =
      get("curve_offsets").cast<py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>>();
  const auto vertices =
      get("curve_vertices").cast<py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>>();
  if (offsets.size() != segments.size() + 1 || offsets.data()[0] != 0 ||
      offsets.data()[offsets.size() - 1] != vertices.size())
    throw InputError("the base's curve offsets do not fit its curves", "base");
  for (py::ssize_t c = 0; c + 1 < offsets.size(); ++c) {
    const std::int64_t begin = offsets.data()[c], end = offsets.data()[c + 1];
    if (begin > end) throw InputError("the base's curve offsets do not rise", "base");
    out.curve_vertices.emplace_back(vertices.data() + begin, vertices.data() + end);
  }
  return out;
}

/// A capped, shelled or sheet lattice's parts (capped_pieces()): {"parts": how many, "cut_parts": the
/// part of every cut surface to mesh in blocks}; None for any other surface.
py::object capped_parts(const py::dict& source, const BoxArg& box, const py::dict& options) {
  Settings settings = to_settings(options);
  settings.box = to_box(box);
  const Source named(source);
  if (named.composite() || !named.volume.empty()) return py::none();
  std::size_t parts = 0;
  const std::optional<std::vector<std::size_t>> cuts = run_released([&](const std::atomic<bool>* cancel) {
    settings.cancel = cancel;
    const auto pieces = capped_pieces(*named.surface(settings.box), settings);
    if (!pieces) return std::optional<std::vector<std::size_t>>();
    parts = capped_part_count(*pieces);
    return std::optional<std::vector<std::size_t>>(capped_cut_parts(*pieces));
  });
  if (!cuts) return py::none();
  py::dict out;
  out["parts"] = parts;
  out["cut_parts"] = *cuts;
  return out;
}

/// The capped pieces of the source's formula. \throw InputError when it is not a capped lattice.
std::shared_ptr<const CappedPieces> capped_of(const Source& named, const Settings& settings) {
  auto pieces = capped_pieces(*named.surface(settings.box), settings);
  if (!pieces)
    throw InputError("the job names a part of a capped lattice but the formula is not one", "part");
  return pieces;
}

/// The capped lattice closed from its cut surfaces' meshes (`cuts`: (positions, triangles) per cut
/// surface): close_capped() as arrays, with the caps' counts.
py::dict close_capped_arrays(const py::dict& source, const BoxArg& box, const py::dict& options,
                             const py::list& cuts) {
  Settings settings = to_settings(options);
  settings.box = to_box(box);
  const Source named(source);
  std::vector<Mesh> meshes;
  for (const py::handle c : cuts) {
    const auto pair = c.cast<py::tuple>();
    if (pair.size() != 2) throw InputError("a part's cut must be (positions, triangles)", "parts");
    meshes.push_back(to_mesh(pair[0].cast<Positions>(), pair[1].cast<Indices>()));
  }
  MeshStats stats;
  const Mesh mesh = run_released([&](const std::atomic<bool>* cancel) {
    settings.cancel = cancel;
    return close_capped(*capped_of(named, settings), std::move(meshes), settings, &stats);
  });
  py::dict out;
  out["positions"] = vec3_array(mesh.positions);
  out["triangles"] = triangle_array(mesh.triangles);
  out["caps"] = stats.creases ? stats.creases->caps : 0;
  out["crease_vertices"] = stats.creases ? stats.creases->crease_vertices : 0;
  out["repair_moves"] = stats.creases ? stats.creases->repair_moves : 0;
  return out;
}

py::dict base_of(const py::dict& source, const BoxArg& box, const py::dict& options, int part) {
  Settings settings = to_settings(options);
  settings.box = to_box(box);
  const Source named(source);
  BlockBase base = run_released([&](const std::atomic<bool>* cancel) {
    settings.cancel = cancel;
    if (part >= 0) return block_base(*capped_of(named, settings), static_cast<std::size_t>(part), settings);
    if (named.composite()) return block_base(named.read_model(), settings);
    const SurfacePtr surface = named.surface(settings.box);
    if (const auto creased = creased_pieces(*surface, settings)) return block_base(*creased, settings);
    return block_base(*surface, settings);
  });
  py::dict out;
  out["positions"] = vec3_array(base.base.positions);
  out["triangles"] = triangle_array(base.base.triangles);
  out["level"] = base.level;
  if (!base.patches.triangle_patch.empty()) out["patches"] = patches_dict(base.patches);
  return out;
}

/// A blocked job as a process holds it: the base, its plan and, made on first use, the surface (a
/// worker refines all its blocks of a job with one: the formula compiled, or the coefficients mapped, once).
class BlockJob {
 public:
  /// `patches`: a composite base's (patches_dict()), None for a surface of one function.
  BlockJob(const py::dict& source, const BoxArg& box, const Positions& positions, const Indices& triangles,
           int level, int blocks, const py::object& patches, int part)
      : source_(source), box_(to_box(box)), base_(to_mesh(positions, triangles)), part_(part) {
    // A composite's base has patches; a formula's has them when it is meshed along its creases.
    if (patches.is_none() ? source_.composite() : !source_.volume.empty())
      throw InputError(
          patches.is_none() ? "a composite's base needs its patches" : "a volume's base has no patches",
          "base");
    if (!patches.is_none()) patches_ = to_patches(patches.cast<py::dict>());
    plan_ =
        run_released([&](const std::atomic<bool>*) { return plan_blocks(base_, level, blocks, patches_); });
  }

  /// The output's counts and where each block's numbers begin.
  py::dict counts() const {
    py::dict out;
    out["vertices"] = plan_.vertices;
    out["triangles"] = plan_.triangles;
    out["first_vertex"] = plan_.first_vertex;
    out["vertex_count"] = plan_.vertex_count;
    out["first_triangle"] = plan_.first_triangle;
    out["triangle_count"] = plan_.triangle_count;
    return out;
  }

  /// Block `block` refined with `options` (refine_block), as arrays.
  py::dict refine(const py::dict& options, int block) {
    Settings settings = to_settings(options);
    settings.box = box_;
    BlockMesh mesh = run_released([&](const std::atomic<bool>* cancel) {
      settings.cancel = cancel;
      if (part_ >= 0)
        return refine_block(*capped(settings), static_cast<std::size_t>(part_), settings, base_, plan_,
                            block);
      if (source_.composite()) return refine_block(*model(), patches_, settings, base_, plan_, block);
      if (!patches_.triangle_patch.empty())
        return refine_block(*creased(settings), patches_, settings, base_, plan_, block);
      return refine_block(*surface(), settings, base_, plan_, block);
    });
    py::dict out;
    out["positions"] = vec3_array(mesh.positions);
    out["triangles"] = triangle_array(mesh.triangles);
    out["seam_ids"] =
        py::array_t<std::uint64_t>(static_cast<py::ssize_t>(mesh.seam_ids.size()), mesh.seam_ids.data());
    out["seam_positions"] = vec3_array(mesh.seam_positions);
    put_refinement_figures(out, mesh);
    return out;
  }

 private:
  Source source_;
  std::optional<Box> box_;
  Mesh base_;
  BasePatches patches_;
  BlockPlan plan_;
  std::mutex surface_mutex_;  // a worker of several threads may refine two blocks at once
  SurfacePtr surface_;
  std::optional<CompositeModel> model_;

  std::shared_ptr<const CreasedPieces> creased_;
  int part_ = -1;  ///< the part of a capped lattice this job meshes the cut of (-1: none)
  std::shared_ptr<const CappedPieces> capped_;

  /// The capped lattice's parts (made once, as creased()).
  std::shared_ptr<const CappedPieces> capped(const Settings& settings) {
    const std::lock_guard<std::mutex> lock(surface_mutex_);
    if (!capped_) capped_ = capped_of(source_, settings);
    return capped_;
  }

  /// The formula's crease analysis (made once: the job's settings are the same for every block; the
  /// level a retry halves does not enter it). \throw InputError when the formula has no creases now.
  std::shared_ptr<const CreasedPieces> creased(const Settings& settings) {
    const SurfacePtr f = surface();
    const std::lock_guard<std::mutex> lock(surface_mutex_);
    if (!creased_) creased_ = creased_pieces(*f, settings);
    if (!creased_) throw InputError("the base has crease pieces but the formula has no creases here", "base");
    return creased_;
  }

  const CompositeModel* model() {
    const std::lock_guard<std::mutex> lock(surface_mutex_);
    if (!model_) model_.emplace(source_.read_model());
    return &*model_;
  }

  SurfacePtr surface() {
    const std::lock_guard<std::mutex> lock(surface_mutex_);
    if (!surface_) surface_ = source_.surface(box_);
    return surface_;
  }
};

void write_arrays(const Positions& positions, const Indices& triangles, const std::string& path) {
  const Mesh mesh = to_mesh(positions, triangles);
  run_released([&](const std::atomic<bool>*) {
    write_mesh(mesh, path);
    return 0;
  });
}

/// interpolating_coefficients() in place on a C-contiguous float64 array of 3 dimensions.
void prefilter(py::array_t<double, py::array::c_style> samples) {
  if (samples.ndim() != 3)
    throw InputError("a volume window must have 3 dimensions, not " + std::to_string(samples.ndim()),
                     "volume");
  const std::array<std::size_t, 3> shape{static_cast<std::size_t>(samples.shape(0)),
                                         static_cast<std::size_t>(samples.shape(1)),
                                         static_cast<std::size_t>(samples.shape(2))};
  const std::span<double> values(samples.mutable_data(), static_cast<std::size_t>(samples.size()));
  run_released([&](const std::atomic<bool>*) {
    interpolating_coefficients(values, shape);
    return 0;
  });
}

}  // namespace

void bind_blocks(py::module_& m) {
  m.attr("PREFILTER_HALO") = kPrefilterHalo;
  m.def("prefilter", &prefilter, py::arg("samples").noconvert());
  m.def("block_base", &base_of, py::arg("source"), py::arg("box"), py::arg("options"), py::arg("part") = -1);
  m.def("capped_parts", &capped_parts, py::arg("source"), py::arg("box"), py::arg("options"));
  m.def("close_capped", &close_capped_arrays, py::arg("source"), py::arg("box"), py::arg("options"),
        py::arg("cuts"));
  py::class_<BlockJob>(m, "BlockJob")
      .def(py::init<const py::dict&, const BoxArg&, const Positions&, const Indices&, int, int,
                    const py::object&, int>(),
           py::arg("source"), py::arg("box"), py::arg("positions"), py::arg("triangles"), py::arg("level"),
           py::arg("blocks"), py::arg("patches") = py::none(), py::arg("part") = -1)
      .def("counts", &BlockJob::counts)
      .def("refine", &BlockJob::refine, py::arg("options"), py::arg("block"));
  m.def("write_arrays", &write_arrays, py::arg("positions"), py::arg("triangles"), py::arg("path"));
}

}  // namespace isopatch::python
