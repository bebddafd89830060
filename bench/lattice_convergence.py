#!/usr/bin/python3
"""Topology and volume of lattice parts against meshes four times finer (docs/lattices.md): each TPMS solid
(and, with --sheets, sheet at t = 0.3; with --sheets-only, the sheets alone) cut by the ball of radius 6,
or with --box capped by the box of two periods [-2 pi, 2 pi]^3, meshed at 1/N and 1/(4N) of the ball's
diameter (the box's side) through isopatch.mesh; prints one Markdown row per part: genus and components
of both, their volumes and the relative difference.
Usage: PYTHONPATH=build-test/python /usr/bin/python3 bench/lattice_convergence.py [N] [--sheets|--sheets-only] [--box]"""

import sys

import numpy as np

import isopatch

TPMS = {
    "gyroid": "sin(x)*cos(y)+sin(y)*cos(z)+sin(z)*cos(x)",
    "diamond": "sin(x)*sin(y)*sin(z)+sin(x)*cos(y)*cos(z)+cos(x)*sin(y)*cos(z)+cos(x)*cos(y)*sin(z)",
    "schwarz_p": "cos(x)+cos(y)+cos(z)",
    "neovius": "3*(cos(x)+cos(y)+cos(z))+4*cos(x)*cos(y)*cos(z)",
    "iwp": "2*(cos(x)*cos(y)+cos(y)*cos(z)+cos(z)*cos(x))-(cos(2*x)+cos(2*y)+cos(2*z))",
}
BOX = ((-6.6,) * 3, (6.6,) * 3)


def measure(formula, edge):
    m = isopatch.mesh(formula, box=BOX, edge_length=edge)
    a, b, c = (m.vertices[m.faces[:, k]] for k in range(3))
    volume = float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)
    t = m.analyze()["topology"]
    return t["genus"], t["components"], volume, len(m.vertices)


def main():
    n = int(next((a for a in sys.argv[1:] if a.isdigit()), "60"))
    kinds = ["sheet"] if "--sheets-only" in sys.argv else ["solid", "sheet"] if "--sheets" in sys.argv else ["solid"]
    boxed = "--box" in sys.argv
    cap, size = ("max(max(abs(x),abs(y)),abs(z))-2*pi", 4.0 * np.pi) if boxed else ("x*x+y*y+z*z-36", 12.0)
    print(f"| part | kind | genus 1/{n} | genus 1/{4 * n} | components | volume 1/{n} | volume 1/{4 * n} | relative |")
    print("|---|---|---|---|---|---|---|---|")
    for name, f in TPMS.items():
        for kind in kinds:
            lattice = f if kind == "solid" else f"abs({f})-0.3"
            part = f"max({lattice},{cap})"
            coarse = measure(part, size / n)
            fine = measure(part, size / (4 * n))
            rel = abs(coarse[2] - fine[2]) / fine[2]
            print(f"| {name} | {kind} | {coarse[0]} | {fine[0]} | {coarse[1]} / {fine[1]} | {coarse[2]:.4f} | "
                  f"{fine[2]:.4f} | {rel:.1e} |", flush=True)


if __name__ == "__main__":
    main()
