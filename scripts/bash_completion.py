#!/usr/bin/python3
"""Writes the bash completion of the isopatch tool from its own help (`isopatch --help`, every
subcommand's `--help`) and its catalogue (`isopatch surfaces`): subcommands, each one's options, and for a
subcommand's words that are not options, the catalogue's surface names and files.

Usage: scripts/bash_completion.py TOOL OUTPUT
"""

import argparse
import re
import subprocess
import sys

from man_page import entries, help_of, sections


def options(terms):
    """The flags of CLI11 option terms such as "-o,--output TEXT" or "--box TEXT"."""
    out = []
    for term in terms:
        for flag in term.split()[0].split(","):
            if flag.startswith("-"):
                out.append(flag)
    return out


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("tool")
    p.add_argument("output")
    a = p.parse_args()
    _, top = sections(help_of(a.tool))
    commands = [name for name, _ in entries(top.get("Subcommands", ""))]
    listing = subprocess.run([a.tool, "surfaces"], capture_output=True, text=True, timeout=60).stdout
    surfaces = re.findall(r"^(\w+)\s", listing, re.M)
    lines = [
        "# bash completion for isopatch(1), generated from the tool's --help by scripts/bash_completion.py",
        "_isopatch() {",
        '  local cur="${COMP_WORDS[COMP_CWORD]}" opts=""',
        "  if [[ $COMP_CWORD -eq 1 ]]; then",
        '    COMPREPLY=($(compgen -W "%s --help --version" -- "$cur"))' % " ".join(commands),
        "    return",
        "  fi",
        '  case "${COMP_WORDS[1]}" in',
    ]
    for name in commands:
        _, parts = sections(help_of(a.tool, name))
        flags = options(term for term, _ in entries(parts.get("Options", "")))
        lines.append('    %s) opts="%s" ;;' % (name, " ".join(flags)))
    lines += [
        "  esac",
        '  if [[ "$cur" == -* ]]; then',
        '    COMPREPLY=($(compgen -W "$opts" -- "$cur"))',
        "  else",
        '    COMPREPLY=($(compgen -W "%s" -- "$cur") $(compgen -f -- "$cur"))' % " ".join(surfaces),
        "  fi",
        "}",
        "complete -o filenames -F _isopatch isopatch",
    ]
    with open(a.output, "w") as f:
        f.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
