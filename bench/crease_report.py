#!/usr/bin/python3
"""The pictures and the table of docs/creases.md: CSG shapes meshed by isopatch along their creases,
by isopatch as smooth surfaces (--creases off) and by a plain dual contouring (bench/dual_contouring,
Ju et al. 2002) at about the same vertex count, each measured by `isopatch analyze` and drawn as a
wireframe and as isophotes by `isopatch render`.

    bench/crease_report.py --isopatch build/bin/isopatch --dc build/bin/isopatch_dual_contouring \
        --out docs/creases

Writes OUT/<model>-<mesher>-{wireframe,isophotes}.png and OUT/comparison.md (the table).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

MODELS = [
    # A cube turned off the grid's axes (an axis-aligned one is the one case a grid method gets exactly).
    ("turned-cube", "a=0.5;b=0.7;u=cos(a)*x-sin(a)*y;v=sin(a)*x+cos(a)*y;w=cos(b)*v-sin(b)*z;t=sin(b)*v+cos(b)*z;"
     "max(max(abs(u),abs(w)),abs(t))-1", "-1.9,-1.9,-1.9,1.9,1.9,1.9"),
    ("sphere-with-hole", "max(x^2+y^2+z^2-1,0.25-x^2-y^2)", "-1.2,-1.2,-1.2,1.2,1.2,1.2"),
    ("box-minus-cylinder", "max(max(max(abs(x),abs(y)),abs(z))-1,0.25-x^2-y^2)", "-1.5,-1.5,-1.5,1.5,1.5,1.5"),
    ("sphere-and-cube", "max(x^2+y^2+z^2-1.69,max(max(abs(x),abs(y)),abs(z))-1)", "-1.5,-1.5,-1.5,1.5,1.5,1.5"),
]
EDGE = 0.09  # a visible wireframe


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"failed ({r.returncode}): {' '.join(cmd)}\n{r.stderr}")
    return r.stdout


def analyze(isopatch, mesh, formula, box):
    d = json.loads(run([isopatch, "analyze", mesh, "--surface", formula, "--box", box, "--json"]))
    shape, acc = d["shape"], d["accuracy"]
    return {
        "vertices": d["mesh"]["vertices"],
        "min_angle": shape["min_angle_degrees"]["min"],
        "under_10": 100.0 * shape["share_below_10_degrees"],
        "valence_6": 100.0 * d["valence"]["share_6"],
        "self_intersections": d["self_intersections"]["pairs"],
        "distance": acc["vertex_distance_relative"]["max"],
        "normal_error": acc["triangle_normal_error_degrees"]["mean"],
        "watertight": d["topology"]["watertight"] and d["topology"]["manifold"],
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--isopatch", required=True)
    ap.add_argument("--dc", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--size", default="420x420")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, formula, box in MODELS:
            meshes = {}
            creased = os.path.join(tmp, f"{name}-creases.ply")
            run([args.isopatch, "mesh", formula, "--box", box, "--edge-length", str(EDGE), "-o", creased, "-q"])
            meshes["isopatch"] = creased
            smooth = os.path.join(tmp, f"{name}-smooth.ply")
            run([args.isopatch, "mesh", formula, "--box", box, "--edge-length", str(EDGE), "--creases", "off",
                 "-o", smooth, "-q"])
            meshes["isopatch --creases off"] = smooth
            target = analyze(args.isopatch, creased, formula, box)["vertices"]
            dc = os.path.join(tmp, f"{name}-dc.ply")
            run([args.dc, formula, "--box", box, "--vertices", str(target), "-o", dc])
            meshes["dual contouring"] = dc
            for mesher, path in meshes.items():
                m = analyze(args.isopatch, path, formula, box)
                tag = {"isopatch": "isopatch", "isopatch --creases off": "smooth", "dual contouring": "dc"}[mesher]
                for show in ("wireframe", "isophotes"):
                    png = os.path.join(args.out, f"{name}-{tag}-{show}.png")
                    run([args.isopatch, "render", path, "-o", png, "--show", show, "--size", args.size,
                         "--view", "35,40", "--caption", f"{name}: {mesher}", "-q"])
                rows.append((name, mesher, tag, m))
    lines = [
        "| model | mesher | vertices | watertight, manifold | min angle | under 10 deg | valence 6 |"
        " self-intersecting pairs | max distance to f / diagonal | mean normal error (deg) |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for name, mesher, _, m in rows:
        lines.append(
            f"| {name} | {mesher} | {m['vertices']} | {'yes' if m['watertight'] else 'no'} | {m['min_angle']:.1f} |"
            f" {m['under_10']:.2f}% | {m['valence_6']:.1f}% | {m['self_intersections']} | {m['distance']:.1e} |"
            f" {m['normal_error']:.2f} |")
    lines.append("")
    for name, _, _ in MODELS:
        lines.append(f"**{name}** (isopatch, isopatch --creases off, dual contouring):\n")
        for show in ("wireframe", "isophotes"):
            lines.append(" ".join(f"![{name} {tag} {show}]({name}-{tag}-{show}.png)" for tag in ("isopatch", "smooth", "dc")))
            lines.append("")
    with open(os.path.join(args.out, "comparison.md"), "w") as f:
        f.write("# CSG shapes: isopatch along creases, smooth, dual contouring\n\n"
                "Generated by `bench/crease_report.py` (edge length %g; dual contouring at the vertex count of the "
                "first row of each model).\n\n" % EDGE)
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines[:2 + len(rows)]))


if __name__ == "__main__":
    main()
