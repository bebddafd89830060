#!/usr/bin/python3
"""Prints the library's module graph from src/CMakeLists.txt and each module's isopatch_module() line:
one line per module, grouped by level (a module's level is one more than the highest level it uses).
`─>` lists PUBLIC uses, `┄` PRIVATE ones; every module uses core, which is not repeated.
docs/architecture.md embeds its output; the test docs.module_graph checks that it is up to date:
  scripts/module_graph.py --check docs/architecture.md"""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
order_text = (root / "src/CMakeLists.txt").read_text()
order = re.search(r"set\(ISOPATCH_MODULE_ORDER ([^)]*)\)", order_text).group(1).split()
uses = {}
for module in order:
    text = (root / "src" / module / "CMakeLists.txt").read_text()
    head = re.search(r"isopatch_module\((.*?)\)", text, re.S).group(1).split("HEADERS")[0].split()[1:]
    public, private, mode = [], [], None
    for token in head:
        if token in ("PUBLIC", "PRIVATE"):
            mode = token
        elif token != "core":
            (public if mode == "PUBLIC" else private).append(token)
    uses[module] = (public, private)
level = {}
for module in order:
    public, private = uses[module]
    level[module] = 1 + max((level[m] for m in public + private), default=-1)
width = max(len(m) for m in order)
lines = []
for lv in range(max(level.values()), -1, -1):
    for module in (m for m in order if level[m] == lv):
        public, private = uses[module]
        line = f"{lv}  {module:<{width}}"
        if public:
            line += " ─> " + ", ".join(public)
        if private:
            line += ("  ┄ " if public else " ┄  ") + ", ".join(private)
        lines.append(line.rstrip())
graph = "\n".join(lines) + "\n"
if len(sys.argv) == 3 and sys.argv[1] == "--check":
    if "```\n" + graph + "```" not in pathlib.Path(sys.argv[2]).read_text():
        sys.exit(f"{sys.argv[2]} does not hold the module graph of src/ (run scripts/module_graph.py)")
else:
    sys.stdout.write(graph)
