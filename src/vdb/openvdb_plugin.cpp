// The OpenVDB part of the .vdb reader (openvdb_plugin.hpp): grid choice, value types, transforms,
// samples and tiles, OpenVDB's exceptions as one-line IoErrors. The only file that includes OpenVDB.
#include "vdb/openvdb_plugin.hpp"

#include <isopatch/error.hpp>
#include <isopatch/volume.hpp>

#include <openvdb/io/File.h>
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Count.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <new>
#include <sstream>

#include <sys/mman.h>
#include <unistd.h>

namespace isopatch::vdb {

namespace {

void initialize_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

std::string grid_class(const openvdb::GridBase& g) {
  return openvdb::GridBase::gridClassToString(g.getGridClass());
}

bool scalar(const openvdb::GridBase& g) {
  return g.isType<openvdb::FloatGrid>() || g.isType<openvdb::DoubleGrid>();
}

/// The grid named `wanted` among `grids`, or, without a name, the only level set, else the only scalar
/// grid. \throw InputError (setting "grid") naming the grids there are.
openvdb::GridBase::Ptr choose(const openvdb::GridPtrVec& grids, const std::string& wanted,
                              const std::string& name) {
  std::string names;
  for (const auto& g : grids)
    names += (names.empty() ? "'" : ", '") + g->getName() + "' (" + g->valueType() + ")";
  if (grids.empty()) throw IoError(name + ": the file holds no grid");
  if (!wanted.empty()) {
    for (const auto& g : grids)
      if (g->getName() == wanted) return g;
    throw InputError(name + " has no grid '" + wanted + "' (it has " + names + ")", "grid");
  }
  openvdb::GridBase::Ptr level_set, only_scalar;
  int level_sets = 0, scalars = 0;
  for (const auto& g : grids) {
    if (!scalar(*g)) continue;
    ++scalars;
    only_scalar = g;
    if (g->getGridClass() == openvdb::GRID_LEVEL_SET) {
      ++level_sets;
      level_set = g;
    }
  }
  if (scalars == 0) throw IoError(name + " holds no float or double grid (it has " + names + ")");
  if (level_sets == 1) return level_set;
  if (level_sets == 0 && scalars == 1) return only_scalar;
  throw InputError(name + " holds " + std::to_string(grids.size()) + " grids (" + names +
                       "): name the one to mesh (--grid NAME)",
                   "grid");
}

/// Voxel (i, j, k) at origin + (i, j, k) * spacing, or IoError for any other transform.
void take_transform(const openvdb::GridBase& g, SparseSamples& out, const std::string& where) {
  const openvdb::math::Transform& t = g.transform();
  const std::string type = t.baseMap()->type();
  const bool axis_aligned = type == openvdb::math::UniformScaleMap::mapType() ||
                            type == openvdb::math::UniformScaleTranslateMap::mapType() ||
                            type == openvdb::math::ScaleMap::mapType() ||
                            type == openvdb::math::ScaleTranslateMap::mapType() ||
                            type == openvdb::math::TranslationMap::mapType();
  if (!t.isLinear() || !axis_aligned)
    throw IoError(where + " has a " + type +
                  " transform: only axis-aligned voxels (scale and translation) are supported");
  const openvdb::Vec3d o = t.indexToWorld(openvdb::Vec3d(0.0, 0.0, 0.0));
  const openvdb::Vec3d one = t.indexToWorld(openvdb::Vec3d(1.0, 1.0, 1.0));
  for (int a = 0; a < 3; ++a) {
    out.origin[a] = o[a];
    out.spacing[a] = one[a] - o[a];
    if (!std::isfinite(out.origin[a]) || !(out.spacing[a] > 0.0) || !std::isfinite(out.spacing[a]))
      throw IoError(where + " has a transform with a non-positive or non-finite voxel size or origin");
  }
}

template <class GridT>
SparseSamples take_samples(const GridT& grid, const std::string& where) {
  SparseSamples out;
  take_transform(grid, out, where);
  const auto& tree = grid.tree();
  out.tiles.background = static_cast<double>(tree.background());
  if (!std::isfinite(out.tiles.background)) throw IoError(where + " has a non-finite background value");
  if (tree.leafCount() > kMaxVolumeSamples / kBrickVoxels)
    throw IoError(where + " stores " + std::to_string(tree.leafCount()) +
                  " leaves of 512 voxels: more than " + std::to_string(kMaxVolumeSamples) + " voxels");
  const auto check = [&](double v, const openvdb::Coord& at) {
    if (!std::isfinite(v))
      throw IoError(where + " has a non-finite value at voxel (" + std::to_string(at.x()) + ", " +
                    std::to_string(at.y()) + ", " + std::to_string(at.z()) + ")");
  };
  for (auto leaf = tree.cbeginLeaf(); leaf; ++leaf) {
    std::vector<double> values(kBrickVoxels);
    for (openvdb::Index n = 0; n < kBrickVoxels; ++n) {
      values[n] = static_cast<double>(leaf->getValue(n));
      check(values[n], leaf->offsetToGlobalCoord(n));
    }
    const openvdb::Coord o = leaf->origin();
    out.leaves.emplace(Coord{o.x() >> kBrickShift, o.y() >> kBrickShift, o.z() >> kBrickShift},
                       std::move(values));
  }
  auto it = tree.cbeginValueAll();
  it.setMaxDepth(tree.treeDepth() - 2);  // tiles only: leaf voxels are at depth treeDepth() - 1
  for (; it; ++it) {
    if (!it.isTileValue()) continue;
    const openvdb::CoordBBox b = it.getBoundingBox();
    const openvdb::Coord d = b.dim();
    int shift = 0;
    while (shift < 31 && (std::int64_t{1} << shift) < d.x()) ++shift;
    if (d.x() != d.y() || d.x() != d.z() || (std::int64_t{1} << shift) != d.x() || shift < kBrickShift)
      throw IoError(where + " has a tile that is not an aligned cube of at least 8 voxels");
    const double v = static_cast<double>(*it);
    check(v, b.min());
    if (v == out.tiles.background) continue;  // a lookup falls back to the background anyway
    const openvdb::Coord m = b.min();
    out.tiles.levels[shift][{m.x() >> shift, m.y() >> shift, m.z() >> shift}] = v;
  }
  // Counted on this thread: this runs in a forked child, where oneTBB's workers do not exist
  // (Tree::activeVoxelCount() counts in parallel).
  out.active_voxels = openvdb::tools::countActiveVoxels(tree, /*threaded=*/false);
  if (out.active_voxels > 0) {
    openvdb::CoordBBox box;
    tree.evalActiveVoxelBoundingBox(box);
    out.active_lo = {box.min().x(), box.min().y(), box.min().z()};
    out.active_hi = {box.max().x(), box.max().y(), box.max().z()};
  }
  return out;
}

SparseSamples take(const openvdb::GridBase& g, const std::string& name) {
  const std::string where = name + ": grid '" + g.getName() + "'";
  if (g.isType<openvdb::FloatGrid>()) return take_samples(static_cast<const openvdb::FloatGrid&>(g), where);
  if (g.isType<openvdb::DoubleGrid>()) return take_samples(static_cast<const openvdb::DoubleGrid&>(g), where);
  throw IoError(where + " holds " + g.valueType() +
                " values: want a float or double grid (a level set or a fog volume)");
}

/// OpenVDB's message, as one short line: a corrupt file's names can be long or hold line breaks.
std::string short_line(const char* what) {
  std::string s(what);
  constexpr std::size_t kLongest = 200;
  if (s.size() > kLongest) s = s.substr(0, kLongest) + "...";
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

/// Runs `read`, turning OpenVDB's and the allocator's exceptions into one-line IoErrors naming `name`.
template <class F>
auto guarded(const std::string& name, F&& read) {
  try {
    return read();
  } catch (const Error&) {
    throw;
  } catch (const openvdb::Exception& e) {
    throw IoError(name + ": not a readable OpenVDB file (" + short_line(e.what()) + ")");
  } catch (const std::bad_alloc&) {
    throw IoError(name + ": the file declares more data than memory holds (a corrupt file?)");
  } catch (const std::exception& e) {
    throw IoError(name + ": not a readable OpenVDB file (" + short_line(e.what()) + ")");
  }
}

/// Keeps a grid read in the child process alive until the child leaves (by _exit, right after it
/// answers): OpenVDB frees a tree with oneTBB's parallel loops, whose worker threads do not exist after
/// fork, and the child hung there waiting for them (seen in the test suite).
void keep_in_child(const openvdb::GridBase::Ptr& grid) {
  static std::vector<openvdb::GridBase::Ptr>* const kept = new std::vector<openvdb::GridBase::Ptr>;
  kept->push_back(grid);
}

SparseSamples read_samples(std::string_view bytes, bool offsets, const std::string& grid,
                           const std::string& name, std::string& grid_name) {
  return guarded(name, [&] {
    if (offsets) {
      const int fd = ::memfd_create("isopatch-vdb", 0);
      if (fd < 0) throw IoError(name + ": cannot hold the file in memory");
      for (std::string_view rest = bytes; !rest.empty();) {
        const ssize_t n = ::write(fd, rest.data(), rest.size());
        if (n <= 0) throw IoError(name + ": cannot hold the file in memory");
        rest.remove_prefix(static_cast<std::size_t>(n));
      }
      openvdb::io::File file("/proc/self/fd/" + std::to_string(fd));
      file.open(false);
      const openvdb::GridPtrVecPtr metadata = file.readAllGridMetadata();
      grid_name = choose(*metadata, grid, name)->getName();
      const openvdb::GridBase::Ptr g = file.readGrid(grid_name);
      keep_in_child(g);
      return take(*g, name);
    }
    std::istringstream in{std::string(bytes)};
    openvdb::io::Stream stream(in, false);
    const openvdb::GridPtrVecPtr grids = stream.getGrids();
    // OpenVDB does not check every read: a stream that ran out of bytes is a truncated file.
    if (in.fail()) throw IoError(name + ": the file is truncated (it ends inside its grids)");
    if (!grids) throw IoError(name + ": the file holds no grid");
    const openvdb::GridBase::Ptr g = choose(*grids, grid, name);
    keep_in_child(g);
    grid_name = g->getName();
    return take(*g, name);
  });
}

std::vector<VdbGridInfo> list_file_grids(const std::string& path) {
  return guarded(path, [&] {
    openvdb::io::File file(path);
    file.open(false);
    std::vector<VdbGridInfo> out;
    const openvdb::GridPtrVecPtr grids = file.readAllGridMetadata();  // alive through the loop
    for (const auto& g : *grids) {
      VdbGridInfo info{g->getName(), g->valueType(), grid_class(*g), 0};
      const auto count = g->getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_VOXEL_COUNT);
      if (count && count->value() > 0) info.active_voxels = static_cast<std::uint64_t>(count->value());
      out.push_back(std::move(info));
    }
    file.close();
    return out;
  });
}

constexpr OpenVdbFunctions kFunctions{kOpenVdbPluginVersion, initialize_openvdb, read_samples,
                                      list_file_grids};

}  // namespace

}  // namespace isopatch::vdb

extern "C" const isopatch::vdb::OpenVdbFunctions* isopatch_openvdb_functions() {
  return &isopatch::vdb::kFunctions;
}
