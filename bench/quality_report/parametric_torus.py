#!/usr/bin/env python3
"""A globally aligned valence-6 mesh of the catalogue torus (R = 1, r = 0.4), for comparison.

Vertices on a (u, v) grid of the torus's own parametrization, every other row shifted by half a step
and each quad cut so that every vertex has valence 6: the lattice follows the principal directions
everywhere, with no seams and no irregular vertex. It shows what a globally aligned lattice gives
the cotangent curvature estimate at a given vertex count (docs/whole-surface-quality.md):

    bench/quality_report/parametric_torus.py 70 28 torus70x28.obj
    isopatch analyze torus70x28.obj --surface torus
"""
import math
import sys


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: parametric_torus.py AROUND_AXIS AROUND_TUBE OUT.obj (AROUND_TUBE even)")
    nu, nv, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    if nu < 3 or nv < 4 or nv % 2:
        sys.exit("parametric_torus: need at least 3 x 4 vertices and an even count around the tube")
    big, small = 1.0, 0.4
    with open(out, "w") as f:
        for j in range(nv):
            for i in range(nu):
                u = 2 * math.pi * (i + 0.5 * (j % 2)) / nu
                v = 2 * math.pi * j / nv
                rho = big + small * math.cos(v)
                f.write(f"v {rho * math.cos(u):.17g} {rho * math.sin(u):.17g} {small * math.sin(v):.17g}\n")

        def at(i, j):
            return (j % nv) * nu + (i % nu) + 1

        for j in range(nv):
            for i in range(nu):
                if j % 2 == 0:
                    tris = [(at(i, j), at(i + 1, j), at(i, j + 1)), (at(i + 1, j), at(i + 1, j + 1), at(i, j + 1))]
                else:
                    tris = [(at(i, j), at(i + 1, j + 1), at(i, j + 1)), (at(i, j), at(i + 1, j), at(i + 1, j + 1))]
                for a, b, c in tris:
                    f.write(f"f {a} {b} {c}\n")


if __name__ == "__main__":
    main()
