// Example (c): mesh a composite surface read from an .ipatch file (docs/ipatch.md).
//
// A composite is made of patches, each the zero set of its own function inside its own region, that
// meet along curves known from the construction (e.g. the I-patches of a control polyhedron, or a solid
// with setback vertex blends). mesh_composite() samples every curve once and shares it between the two
// patches beside it, so the mesh is watertight without welding.
//
// Usage: isopatch_example_composite_file FILE.ipatch [OUT.obj]

#include <isopatch/composite_mesh.hpp>  // read_composite(), mesh_composite()
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>   // write_mesh()
#include <isopatch/topology.hpp>  // analyze_topology()

#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: " << argv[0] << " FILE.ipatch [OUT.obj]\n";
    return 2;
  }
  try {
    const isopatch::CompositeModel model = isopatch::read_composite(argv[1]);
    // A patch whose function misbehaves in its region (an extra sheet, a fold) is reported here
    // before meshing: such a patch is likely closed by a fan.
    for (const std::string& warning : model.shape_warnings()) std::cerr << "warning: " << warning << "\n";

    isopatch::Settings settings;  // projection; the edge length defaults to the longest box side / 64
    settings.edge_length = 0.12;
    isopatch::MeshStats stats;
    const isopatch::Mesh mesh = isopatch::mesh_composite(model, settings, &stats);
    if (argc > 2) isopatch::write_mesh(mesh, argv[2]);

    const isopatch::TopologyReport topology = isopatch::analyze_topology(mesh);
    std::cout << "patches: " << model.patch_count() << "\n"
              << "vertices: " << mesh.vertex_count() << "\n"
              << "watertight: " << topology.watertight() << "\n"
              << "outward: " << topology.outward_oriented() << "\n"
              << "genus: " << topology.genus << "\n"
              << "fan patches: " << stats.warnings.fan_patches << "\n";
    return 0;
  } catch (const isopatch::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
