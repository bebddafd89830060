#!/usr/bin/python3
"""Writes the manual page isopatch(1) from the tool's own help (`isopatch --help` and every
subcommand's `--help`), so that the page never disagrees with the tool.

Usage: scripts/man_page.py TOOL OUTPUT [--date YYYY-MM-DD]
"""

import argparse
import re
import subprocess
import sys


def roff(text: str) -> str:
    """Text made safe for roff: backslashes and hyphens escaped, no line starting with a dot."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    return re.sub(r"^([.'])", r"\\&\1", text, flags=re.M)


def help_of(tool: str, *args: str) -> str:
    run = subprocess.run([tool, *args, "--help"], capture_output=True, text=True, timeout=60)
    if run.returncode != 0:
        sys.exit("man_page: %s %s --help failed: %s" % (tool, " ".join(args), run.stderr.strip()))
    return run.stdout


def entries(block: str):
    """(term, description) pairs of a CLI11 options or positionals block: a term starts at two spaces,
    its description after two or more spaces or on lines indented further."""
    out = []
    for line in block.splitlines():
        m = re.match(r"^  (\S.*?)(?:\s{2,}(\S.*))?$", line)
        if m and not line.startswith("    "):
            out.append([m.group(1).strip(), (m.group(2) or "").strip()])
        elif out and line.strip():
            out[-1][1] = (out[-1][1] + " " + line.strip()).strip()
    return out


def sections(text: str):
    """The help's sections by title (Options, Positionals, Subcommands), and the lines before them."""
    found = {}
    head = []
    current = None
    for line in text.splitlines():
        m = re.match(r"^(Options|Positionals|Subcommands):$", line)
        if m:
            current = m.group(1)
            found[current] = []
        elif current:
            found[current].append(line)
        else:
            head.append(line)
    return head, {k: "\n".join(v) for k, v in found.items()}


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("tool")
    p.add_argument("output")
    p.add_argument("--date", default="")
    a = p.parse_args()
    version = subprocess.run([a.tool, "--version"], capture_output=True, text=True, timeout=60).stdout.strip()
    top_head, top = sections(help_of(a.tool))
    summary = top_head[0].split(":", 1)[-1].strip() if top_head else "meshes of implicit surfaces"
    commands = entries(top.get("Subcommands", ""))
    out = [
        '.TH ISOPATCH 1 "%s" "isopatch %s" "User Commands"' % (a.date, roff(version.split()[-1] if version else "")),
        ".SH NAME",
        "isopatch \\- " + roff(summary),
        ".SH SYNOPSIS",
        ".B isopatch",
        ".I subcommand",
        "[\\fIoptions\\fR] [\\fIarguments\\fR]",
        ".br",
        ".B isopatch",
        "[\\fB\\-\\-help\\fR | \\fB\\-\\-version\\fR]",
        ".SH DESCRIPTION",
        roff("isopatch turns smooth implicit surfaces f(x,y,z) = 0 into triangle meshes of nearly equilateral "
             "triangles, almost every vertex of valence 6, every vertex on f = 0 (after Sipos & Salvi 2021, "
             "\"Creating good quality meshes from smooth implicit surfaces\"). Each subcommand below has its "
             "own options; `isopatch SUBCOMMAND --help` prints them as this page does."),
        ".SH SUBCOMMANDS",
    ]
    for name, what in commands:
        out += [".TP", ".B " + roff(name), roff(what)]
    for name, _ in commands:
        head, parts = sections(help_of(a.tool, name))
        out += [".SH " + roff(name.upper()), ".B isopatch " + roff(name)]
        usage = next((l for l in head if l.startswith("Usage:")), "")
        if usage:
            out += ["\\fI" + roff(usage.split(name, 1)[-1].strip()) + "\\fR"]
        if head and head[0].strip():
            out += [".PP", roff(head[0].strip())]
        for title in ("Positionals", "Options"):
            if title not in parts:
                continue
            out += [".PP", ".I " + title]
            for term, what in entries(parts[title]):
                out += [".TP", "\\fB" + roff(term) + "\\fR", roff(what)]
    out += [
        ".SH EXIT STATUS",
        roff("0 on success; 1 an internal error; 2 a usage error; 3 for bad input or settings; 4 an unknown surface; 5 a "
             "malformed formula; 6 a file that cannot be read or written; 7 f not finite; 8 no surface in the "
             "box; 9 a limit reached (budgets, sizes, cancel); 10 a singular surface; 11 creases that cannot "
             "be meshed."),
        ".SH SEE ALSO",
        roff("The documentation in /usr/share/doc/isopatch and the project's docs/ folder."),
    ]
    with open(a.output, "w") as f:
        f.write("\n".join(out) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
