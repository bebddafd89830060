"""The public benchmark surfaces of docs/algorithms.md 7.4 (docs: docs/quality-method.md).

Each entry says how to name the surface on the command line (a catalogue name, or a formula with its
box when the catalogue lacks it), what kind it is and the genus the specification gives. These are
the specification's data, not measurements.
"""

from dataclasses import dataclass, field


@dataclass(frozen=True)
class SurfaceSpec:
    name: str
    kind: str  # "closed", "open" (clipped by the box) or "singular"
    genus: int | None  # the specification's genus; None when it has none (open)
    formula: str | None = None  # used when the catalogue has no entry of that name
    box: str | None = None
    note: str = ""
    args: list[str] = field(default_factory=list)

    def cli_args(self, catalogue: set[str]) -> list[str]:
        """The surface arguments for `isopatch mesh`, `analyze` and the CGAL peer."""
        if self.name in catalogue or self.formula is None:
            return [self.name]
        return [self.formula, "--box", self.box]

    @property
    def targeted(self) -> bool:
        """The targets of docs/algorithms.md 7.4 apply to every closed public surface except heart."""
        return self.kind == "closed"


PUBLIC_SURFACES = [
    SurfaceSpec("sphere", "closed", 0),
    SurfaceSpec("ellipsoid", "closed", 0),
    SurfaceSpec("torus", "closed", 1),
    SurfaceSpec("tanglecube", "closed", 5),
    SurfaceSpec("genus2", "closed", 2),
    SurfaceSpec("double_torus", "closed", 2),
    SurfaceSpec("chmutov6", "closed", 28),
    SurfaceSpec("blobby", "closed", 0),
    SurfaceSpec("cassini", "closed", 0, note="thin neck"),
    SurfaceSpec("gyroid", "open", None, note="open, clipped by its box: topology targets do not apply"),
    SurfaceSpec(
        "heart",
        "singular",
        0,
        formula="(x^2+9/4*y^2+z^2-1)^3-x^2*z^3-9/80*y^2*z^3",
        box="-1.3,-0.8,-1.2,1.3,0.8,1.4",
        note="singular at (0,0,+-1): must be handled, not crash; targets do not apply",
    ),
]
