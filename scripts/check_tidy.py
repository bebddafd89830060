"""The clang-tidy check of scripts/check_tidy.sh (see there for the usage): clang-tidy over the sources
of the library and the tool in a build folder's compile_commands.json, one process per core, the
findings listed by file and counted by check.

A source that passed is remembered in <build>/clang-tidy-passed/ under a key made of everything its
result depends on: the clang-tidy version, .clang-tidy, its compile command, and the contents of the
source and of every header it includes (as Ninja recorded them at its last compilation: `ninja -t
deps`). Such a source is not analysed again until one of those changes; a source without an up-to-date
Ninja record (not compiled since it or a header changed, or another generator) is always analysed."""

import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

FINDING = re.compile(r"^(?P<path>[^ ].*?):(?P<line>\d+):(?P<col>\d+): (?:warning|error): .*\[(?P<checks>[^\]]+)\]$")


def fail(message: str, status: int = 2) -> None:
    print(f"check_tidy: {message}", file=sys.stderr)
    sys.exit(status)


def find_tool(override: str, *names: str) -> str:
    for name in (override, *names):
        if name and shutil.which(name):
            return shutil.which(name)
    fail(f"none of {', '.join(names)} found (scripts/install-deps.sh installs clang-tidy)")
    return ""


def sources(repo: str, build: str, patterns: list[str]) -> dict[str, dict]:
    """The compile_commands.json entries of src/**/*.cpp and apps/**/*.cpp, by absolute source path."""
    path = os.path.join(build, "compile_commands.json")
    if not os.path.isfile(path):
        fail(f"{path} is missing: configure with CMake first (cmake -S . -B {build} -G Ninja; "
             "the top CMakeLists.txt exports it)")
    with open(path, encoding="utf-8") as f:
        entries = json.load(f)
    # The library's and the tool's sources must be compiled one by one (the tests may be unity builds).
    def unity_of_mine(entry: dict) -> bool:
        file = os.path.normpath(os.path.join(entry["directory"], entry["file"]))
        return bool(re.search(r"unity_[0-9]+_cxx\.cxx$", file)) and \
            os.path.relpath(file, os.path.abspath(build)).split(os.sep)[0] in ("src", "apps")
    if any(unity_of_mine(e) for e in entries):
        fail(f"{build} is a unity build: give a build folder without CMAKE_UNITY_BUILD (e.g. build-test)")
    selected = {}
    mine = re.compile(r"^(src|apps)/.*\.cpp$")
    for entry in entries:
        file = os.path.normpath(os.path.join(entry["directory"], entry["file"]))
        relative = os.path.relpath(file, repo)
        if mine.match(relative) and (not patterns or any(re.search(p, relative) for p in patterns)):
            selected[file] = entry
    return selected


def object_of(entry: dict) -> str | None:
    """The object file of a compile command (its -o argument), relative to the build folder."""
    args = entry.get("arguments") or shlex.split(entry["command"])
    for i, arg in enumerate(args[:-1]):
        if arg == "-o":
            return args[i + 1]
    return None


def ninja_deps(build: str) -> dict[str, list[str]]:
    """Object -> the files it was compiled from, for the objects whose record is up to date."""
    if not os.path.isfile(os.path.join(build, "build.ninja")) or not shutil.which("ninja"):
        return {}
    run = subprocess.run(["ninja", "-C", build, "-t", "deps"], capture_output=True, text=True, check=False)
    deps: dict[str, list[str]] = {}
    current = None
    for line in run.stdout.splitlines():
        if line and not line.startswith(" "):
            name, _, state = line.partition(":")
            current = name if state.rstrip().endswith("(VALID)") else None
            if current:
                deps[current] = []
        elif current and line.strip():
            deps[current].append(os.path.normpath(os.path.join(build, line.strip())))
    return deps


class Digests:
    """SHA-256 of file contents, each file read once per run."""

    def __init__(self) -> None:
        self.known: dict[str, str] = {}

    def of(self, path: str) -> str | None:
        if path not in self.known:
            try:
                with open(path, "rb") as f:
                    self.known[path] = hashlib.sha256(f.read()).hexdigest()
            except OSError:
                self.known[path] = ""
        return self.known[path] or None


def cache_key(base: str, entry: dict, obj: str, files: list[str] | None, digests: Digests) -> str | None:
    """None unless the object is up to date (newer than every file it was compiled from, so that the
    list of those files is current)."""
    if not files:
        return None
    try:
        built = os.stat(obj).st_mtime_ns
        if any(os.stat(path).st_mtime_ns > built for path in files):
            return None
    except OSError:
        return None
    h = hashlib.sha256(base.encode())
    h.update(json.dumps(entry, sort_keys=True).encode())
    for path in files:
        digest = digests.of(path)
        if digest is None:  # a header gone since the last compilation: analyse again
            return None
        h.update(f"{path}\0{digest}\0".encode())
    return h.hexdigest()


def readable(text: str, repo: str, build: str) -> str:
    """Paths in the repository's own terms: modules include their headers through links in
    <build>/layers/<module>/ (cmake/IsopatchModules.cmake)."""
    layers = re.escape(os.path.join(build, "layers"))
    text = re.sub(layers + r"/([a-z_0-9]+)/isopatch/", os.path.join(repo, "include", "isopatch") + "/", text)
    text = re.sub(layers + r"/([a-z_0-9]+)/\1/", lambda m: os.path.join(repo, "src", m.group(1)) + "/", text)
    return text.replace(repo + "/", "")


def main() -> int:
    parser = argparse.ArgumentParser(prog="scripts/check_tidy.sh", add_help=False)
    parser.add_argument("build", nargs="?")
    parser.add_argument("patterns", nargs="*")
    parser.add_argument("--repo", required=True)
    parser.add_argument("--no-cache", action="store_true")
    parser.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1)
    args = parser.parse_args()
    repo = os.path.realpath(args.repo)
    build = os.path.realpath(args.build) if args.build else os.path.join(repo, "build-test")
    if not os.path.isdir(build):
        fail(f"no build folder '{args.build or build}'")

    clang_tidy = find_tool(os.environ.get("CLANG_TIDY", ""), "clang-tidy-14", "clang-tidy")
    version = subprocess.run([clang_tidy, "--version"], capture_output=True, text=True, check=True).stdout
    with open(os.path.join(repo, ".clang-tidy"), encoding="utf-8") as f:
        config = f.read()
    selected = sources(repo, build, args.patterns)
    if not selected:
        fail(f"no source of src/ or apps/ in {build}/compile_commands.json matches")

    cache_dir = os.path.join(build, "clang-tidy-passed")
    deps = {} if args.no_cache else ninja_deps(build)
    digests = Digests()
    base = version + "\0" + config
    keys: dict[str, str | None] = {}
    todo = []
    for file, entry in sorted(selected.items()):
        obj = object_of(entry)
        key = (cache_key(base, entry, os.path.join(build, obj), deps.get(obj), digests)
               if deps and obj else None)
        keys[file] = key
        if key and os.path.exists(os.path.join(cache_dir, key)):
            continue
        todo.append(file)

    start = time.monotonic()

    def tidy(file: str) -> tuple[str, int, str]:
        run = subprocess.run([clang_tidy, "-p", build, "--quiet", file], capture_output=True, text=True,
                             check=False)
        return file, run.returncode, run.stdout + run.stderr

    findings: set[str] = set()
    broken: list[str] = []
    passed: list[str] = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for file, status, output in pool.map(tidy, todo):
            found = [line for line in readable(output, repo, build).splitlines() if FINDING.match(line)]
            findings.update(found)
            if status == 0 and not found:
                passed.append(file)
            elif not found:  # clang-tidy failed without a diagnostic: show why
                broken.append(f"{os.path.relpath(file, repo)} (status {status}):\n{output}")
    seconds = time.monotonic() - start

    os.makedirs(cache_dir, exist_ok=True)
    for file in passed:
        if keys[file]:
            open(os.path.join(cache_dir, keys[file]), "w").close()
    if not args.patterns and not args.no_cache:  # forget what no source has any more
        current = {k for k in keys.values() if k}
        for name in os.listdir(cache_dir):
            if name not in current:
                os.remove(os.path.join(cache_dir, name))

    summary = (f"{len(todo)} of {len(selected)} sources analysed in {seconds:.0f} s with {args.jobs} jobs "
               f"({len(selected) - len(todo)} unchanged since they passed, not analysed again)")
    if not findings and not broken:
        print(f"check_tidy: no findings in src/ and apps/: {summary}")
        return 0
    for text in broken:
        print(text, file=sys.stderr)
    for line in sorted(findings):
        print(line, file=sys.stderr)
    counts: dict[str, int] = {}
    for line in findings:
        for check in FINDING.match(line).group("checks").split(","):
            if check != "-warnings-as-errors":
                counts[check] = counts.get(check, 0) + 1
    print(f"\ncheck_tidy: {len(findings)} findings, {len(broken)} sources clang-tidy could not analyse; {summary}",
          file=sys.stderr)
    for check, count in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])):
        print(f"  {count:4d} {check}", file=sys.stderr)
    print("Fix them, or silence a deliberate one with // NOLINT(check-name) and the reason.", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main())
