"""Writes are whole or not at all: the command-line tool writes every file into a temporary file beside
it and renames it at the end, so a full disk or an interruption (SIGINT, SIGTERM) in the middle of a
write leaves the file that was there before as it was, and no temporary file. A preloaded shim
(tests/support/write_fault_shim.cpp, ISOPATCH_WRITE_SHIM) makes the disk full or holds the write."""
import os
import signal
import subprocess
import time

import pytest

CLI = os.environ.get("ISOPATCH_CLI")
SHIM = os.environ.get("ISOPATCH_WRITE_SHIM")
IO_ERROR = 6  # the tool's exit code for input and output errors (docs/cli.md)

pytestmark = pytest.mark.skipif(not CLI or not SHIM, reason="ISOPATCH_CLI and ISOPATCH_WRITE_SHIM name the "
                                "tool and the shim (the test command sets both)")


def shim_env(**settings):
    env = dict(os.environ)
    env["LD_PRELOAD"] = SHIM
    env["ISOPATCH_SHIM_MATCH"] = ".isopatch-"  # the temporary files, named after the target and the process
    env.update({key: str(value) for key, value in settings.items()})
    return env


def previous_file(folder, name):
    path = folder / name
    path.write_bytes(b"the file from before\n")
    return path


@pytest.mark.parametrize("name", ["out.ply", "out.3mf", "out.obj"])
def test_a_full_disk_leaves_the_previous_file_and_names_the_file(tmp_path, name):
    target = previous_file(tmp_path, name)
    run = subprocess.run([CLI, "mesh", "sphere", "--edge-length", "0.05", "-o", str(target), "-q"],
                         capture_output=True, text=True, timeout=120, env=shim_env(ISOPATCH_SHIM_FAIL_AFTER=2000))
    assert run.returncode == IO_ERROR, run.stderr
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1 and name in lines[0] and "No space left on device" in lines[0], run.stderr
    assert target.read_bytes() == b"the file from before\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]


def test_a_full_disk_spares_the_statistics_file(tmp_path):
    stats = previous_file(tmp_path, "stats.json")
    run = subprocess.run([CLI, "mesh", "sphere", "--edge-length", "0.1", "-o", str(tmp_path / "m.ply"),
                          "--stats-json", str(stats), "-q"], capture_output=True, text=True, timeout=120,
                         env=shim_env(ISOPATCH_SHIM_MATCH=".stats.json.isopatch-", ISOPATCH_SHIM_FAIL_AFTER=10))
    assert run.returncode == IO_ERROR, run.stderr
    assert "stats.json" in run.stderr
    assert stats.read_bytes() == b"the file from before\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.ply", "stats.json"]


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_an_interruption_while_writing_leaves_no_part_of_the_file(tmp_path, sig):
    target = previous_file(tmp_path, "out.ply")
    mark = tmp_path.parent / f"{tmp_path.name}-writing"
    process = subprocess.Popen([CLI, "mesh", "sphere", "--edge-length", "0.05", "-o", str(target), "-q"],
                               stderr=subprocess.PIPE, text=True, env=shim_env(ISOPATCH_SHIM_STALL=mark))
    deadline = time.monotonic() + 60
    while not mark.exists():
        assert process.poll() is None, process.stderr.read()
        assert time.monotonic() < deadline, "the tool never began writing"
        time.sleep(0.02)
    process.send_signal(sig)
    _, err = process.communicate(timeout=60)
    # Ended by the signal itself (a shell reports 128 + its number: 130, 143), with one line saying so.
    assert process.returncode == -sig, err
    assert ("interrupted (SIGINT)" if sig == signal.SIGINT else "stopped (SIGTERM)") in err
    assert len(err.strip().splitlines()) == 1, err
    assert target.read_bytes() == b"the file from before\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.ply"]
    mark.unlink()


def test_a_symbolic_link_keeps_pointing_to_the_new_file(tmp_path):
    real = previous_file(tmp_path, "real.ply")
    link = tmp_path / "link.ply"
    link.symlink_to(real)
    run = subprocess.run([CLI, "mesh", "sphere", "--edge-length", "0.1", "-o", str(link), "-q"],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    assert link.is_symlink() and link.resolve() == real.resolve()
    assert real.read_bytes().startswith(b"ply\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.ply", "real.ply"]


def test_a_missing_or_unwritable_folder_is_one_line(tmp_path):
    run = subprocess.run([CLI, "mesh", "sphere", "--edge-length", "0.1", "-o", str(tmp_path / "no" / "m.ply"), "-q"],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == IO_ERROR
    assert len(run.stderr.strip().splitlines()) == 1 and "does not exist" in run.stderr, run.stderr


WRITER = """
import sys
import isopatch
mesh = isopatch.mesh("sphere", edge_length=0.03)
mesh.write(sys.argv[1])
"""


@pytest.mark.parametrize("name", ["out.ply", "out.3mf"])
def test_ctrl_c_in_python_while_writing_raises_keyboard_interrupt_and_leaves_no_part(tmp_path, name):
    target = previous_file(tmp_path, name)
    mark = tmp_path.parent / f"{tmp_path.name}-python-writing"
    process = subprocess.Popen(["/usr/bin/python3", "-c", WRITER, str(target)], stderr=subprocess.PIPE,
                               text=True, env=shim_env(ISOPATCH_SHIM_STALL=mark))
    deadline = time.monotonic() + 60
    while not mark.exists():
        assert process.poll() is None, process.stderr.read()
        assert time.monotonic() < deadline, "Mesh.write never began writing"
        time.sleep(0.02)
    process.send_signal(signal.SIGINT)
    time.sleep(0.5)  # the interpreter's signal check runs every 50 ms while the write is held
    mark.unlink()  # the held write goes on, and stops before its next chunk or the rename
    _, err = process.communicate(timeout=60)
    assert process.returncode == -signal.SIGINT, err  # Python ends by SIGINT after a KeyboardInterrupt
    assert "KeyboardInterrupt" in err, err
    assert target.read_bytes() == b"the file from before\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]
