#!/usr/bin/env bash
# The format check: every C++ file of the repository (.cpp, .hpp, .h; tracked, or new and not ignored)
# must be exactly as clang-format 14 (Debian's clang-format-14) formats it with the repository's
# .clang-format. Third-party and generated files are left out (none is committed today: generated
# headers live in the build folder). Fails listing the files to reformat.
#
# Usage: scripts/check_format.sh [--fix] [FILE...]
#   --fix   reformat the failing files in place (clang-format -i) instead of failing
#   FILE    check only these files (default: all of them)
# $CLANG_FORMAT names another clang-format binary (default clang-format-14, else clang-format).
set -euo pipefail
case "${1:-}" in -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
caller="$(pwd)"
cd "$(dirname "$0")/.."
fix=0
if [ "${1:-}" = --fix ]; then fix=1; shift; fi

clang_format="${CLANG_FORMAT:-}"
if [ -z "$clang_format" ]; then
  if command -v clang-format-14 >/dev/null; then clang_format=clang-format-14
  elif command -v clang-format >/dev/null; then clang_format=clang-format
  else echo "check_format: clang-format-14 not found (scripts/install-deps.sh installs it)" >&2; exit 2
  fi
fi

# Paths never checked: third-party or generated code, should any be added.
excluded='^(third_party|external|vendor)/|/generated/|^web/node_modules/'
files=()
if [ $# -gt 0 ]; then
  for f in "$@"; do
    case "$f" in /*) ;; *) f="$caller/$f" ;; esac
    [ -f "$f" ] || { echo "check_format: no file $f" >&2; exit 2; }
    files+=("$f")
  done
else
  while IFS= read -r -d '' f; do
    [ -f "$f" ] || continue  # deleted in the work tree, not yet in the index
    [[ "$f" =~ $excluded ]] && continue
    files+=("$f")
  done < <(git ls-files -z --cached --others --exclude-standard -- '*.cpp' '*.hpp' '*.h')
fi
[ ${#files[@]} -gt 0 ] || { echo "check_format: no C++ files"; exit 0; }

if ! "$clang_format" --style=file --assume-filename=check.cpp --dump-config >/dev/null; then
  echo "check_format: $clang_format cannot read .clang-format" >&2
  exit 2
fi
# clang-format over batches of files, as many at a time as there are cores; a file fails when formatting
# would change it (one "FILE:LINE:COL: error: code should be clang-formatted" per file: --ferror-limit=1).
failing=()
while IFS= read -r f; do
  [ -n "$f" ] && failing+=("$f")
done < <(printf '%s\0' "${files[@]}" |
         { xargs -0 -n 32 -P "$(nproc)" "$clang_format" --dry-run -Werror --ferror-limit=1 2>&1 || true; } |
         sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' | sort -u)
if [ ${#failing[@]} -eq 0 ]; then
  echo "check_format: ${#files[@]} files formatted as .clang-format asks ($("$clang_format" --version | sed 's/.*version //'))"
  exit 0
fi
if [ "$fix" = 1 ]; then
  "$clang_format" -i "${failing[@]}"
  printf 'check_format: reformatted %s\n' "${failing[@]}"
  exit 0
fi
echo "check_format: ${#failing[@]} of ${#files[@]} files are not formatted as .clang-format asks:" >&2
printf '  %s\n' "${failing[@]}" >&2
echo "Reformat them with: scripts/check_format.sh --fix (or $clang_format -i FILE...); see the" \
     "differences with: $clang_format --dry-run FILE" >&2
exit 1
