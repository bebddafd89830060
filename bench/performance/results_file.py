"""results.json: every run of a performance report written out, and read back to rebuild the report
without measuring (driver.py --from-results). Files written before the header and sizes were kept are
read too."""

import dataclasses
import json

import measure
import systems

FIELDS = {f.name for f in dataclasses.fields(systems.Timed)}


def save(path, results, large, sizes, seconds, header, loads) -> None:
    """Writes the runs (nested runs as objects), the sizes, the header lines and the loads."""
    data = {"surfaces": [{"surface": spec.name, "args": surface,
                          "groups": [{"size": g.label, "target": g.target, "load": g.load,
                                      "runs": {k: dataclasses.asdict(r) for k, r in g.runs.items()}}
                                     for g in groups]}
                         for spec, surface, groups in results],
            "large": None if large is None else dataclasses.asdict(large), "seconds": seconds,
            "sizes": [[label, target] for label, target in sizes], "header": header, "loads": loads}
    with open(path, "w", encoding="utf-8") as f:
        json.dump(data, f, indent=1, default=str)


def run_from(data):
    """A systems.Timed from its dict (unknown keys left out, nested runs read too), or None."""
    if data is None:
        return None
    values = {k: v for k, v in data.items() if k in FIELDS}
    for nested in ("reference", "fe"):
        values[nested] = run_from(values.get(nested))
    return systems.Timed(**values)


def load(path, closed_surfaces) -> dict:
    """{"results": [(spec, args, [Group])], "large", "sizes", "seconds", "header" (None in older files),
    "loads"} from a results.json; `closed_surfaces` gives the specs by name."""
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    specs = {s.name: s for s in closed_surfaces}
    results, sizes = [], {}
    for entry in data["surfaces"]:
        groups = []
        for g in entry["groups"]:
            sizes.setdefault(g["size"], g["target"])
            groups.append(measure.Group(g["size"], g["target"], {k: run_from(r) for k, r in g["runs"].items()},
                                        g.get("load")))
        results.append((specs[entry["surface"]], entry["args"], groups))
    loads = data.get("loads") or [g.load for _, _, gs in results for g in gs if g.load is not None]
    return {"results": results, "large": run_from(data.get("large")),
            "sizes": [tuple(s) for s in data.get("sizes") or sorted(sizes.items(), key=lambda s: s[1])],
            "seconds": data.get("seconds", 0.0), "header": data.get("header"), "loads": loads or [0.0]}
