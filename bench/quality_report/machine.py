"""What the report's header says about where and when it was measured (read, never changed)."""

import datetime
import os
import subprocess


def cpu_model() -> str:
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def commit(repo: str) -> str:
    """HEAD's commit, read from the .git folder's files (no git command is run)."""
    git = common = os.path.join(repo, ".git")
    try:
        if os.path.isfile(git):  # a linked worktree: "gitdir: PATH", refs in that folder's commondir
            with open(git, encoding="utf-8") as f:
                git = f.read().split(":", 1)[1].strip()
            with open(os.path.join(git, "commondir"), encoding="utf-8") as f:
                common = os.path.normpath(os.path.join(git, f.read().strip()))
        with open(os.path.join(git, "HEAD"), encoding="utf-8") as f:
            head = f.read().strip()
        if not head.startswith("ref: "):
            return head[:10]
        ref = head[5:]
        path = os.path.join(common, ref)
        if os.path.exists(path):
            with open(path, encoding="utf-8") as f:
                return f.read().strip()[:10] + f" ({ref.rsplit('/', 1)[-1]})"
        with open(os.path.join(common, "packed-refs"), encoding="utf-8") as f:
            for line in f:
                if line.strip().endswith(" " + ref):
                    return line.split()[0][:10] + f" ({ref.rsplit('/', 1)[-1]})"
    except OSError:
        pass
    return "unknown"


def debian_version(package: str, name: str) -> str:
    """"NAME VERSION (Debian PACKAGE)" from dpkg, or "NAME (version unknown)"."""
    try:
        p = subprocess.run(["dpkg-query", "-W", "-f=${Version}", package], capture_output=True, text=True,
                           timeout=10, check=False)
        if p.returncode == 0 and p.stdout.strip():
            return f"{name} {p.stdout.strip()} (Debian {package})"
    except (OSError, subprocess.TimeoutExpired):
        pass
    return f"{name} (version unknown)"


def cgal_version() -> str:
    return debian_version("libcgal-dev", "CGAL")


def header(repo: str, command: str, seconds: float, peer_built: bool, quick: bool) -> list[str]:
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    try:
        load = " / ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:
        load = "unknown"
    peer = cgal_version() + ", Surface_mesher" if peer_built else "not built (CGAL not found): CGAL rows say so"
    return [
        f"- date: {now}" + (" — **quick run** (one size, smoke test)" if quick else ""),
        f"- machine: {os.cpu_count()} cores, {cpu_model()}; load average at the end {load} "
        "(a shared machine: compare the ratios, not the absolute times)",
        f"- commit: {commit(repo)} (uncommitted changes are not detected)",
        f"- peer: {peer}",
        f"- reproduce: `{command}`",
        f"- runtime of the whole report: {seconds / 60:.1f} min",
    ]
