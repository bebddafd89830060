"""The numbers of one analysed mesh, read defensively from `isopatch analyze --json`."""


def dig(data: dict | None, *path, default=None):
    """data[path[0]][path[1]]...; default when any step is missing."""
    for key in path:
        if not isinstance(data, dict) or key not in data:
            return default
        data = data[key]
    return data


def metrics(analysis: dict | None) -> dict:
    """The report's metrics of one mesh; a value is None when the analysis lacks it."""
    a = analysis
    crossings = dig(a, "self_intersections", "pairs")
    return {
        "valence6": dig(a, "valence", "share_6"),
        "min_angle": dig(a, "shape", "min_angle_degrees", "min"),
        "p1_angle": dig(a, "shape", "min_angle_degrees", "p1"),
        "p5_angle": dig(a, "shape", "min_angle_degrees", "p5"),
        "below10": dig(a, "shape", "share_below_10_degrees"),
        "below20": dig(a, "shape", "share_below_20_degrees"),
        "h_nrms": dig(a, "accuracy", "mean_curvature", "nrms"),
        "vertex_distance": dig(a, "accuracy", "vertex_distance_relative", "max"),
        "centroid_distance": dig(a, "accuracy", "centroid_distance_relative", "max"),
        "normal_error": dig(a, "accuracy", "triangle_normal_error_degrees", "mean"),
        "watertight": dig(a, "topology", "watertight"),
        "manifold": dig(a, "topology", "manifold"),
        "oriented": dig(a, "topology", "consistently_oriented"),
        "outward": dig(a, "topology", "outward_oriented"),
        "genus": dig(a, "topology", "genus"),
        "components": dig(a, "topology", "components"),
        "boundary_edges": dig(a, "topology", "boundary_edges"),
        "intersection_free": None if crossings is None else crossings == 0,
    }
