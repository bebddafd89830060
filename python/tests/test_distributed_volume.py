"""Sampled volumes in blocked runs (isopatch.distributed): the B-spline prefilter made as a distributed
pass over windows with a halo equals the whole volume's to rounding, is the same bytes whatever runs it,
is reused, and the blocked mesh of the mapped coefficients is watertight, on the interpolant and of
one process's topology; bad volumes are refused with the library's errors."""

import json
import os
import re
import subprocess

import numpy as np
import pytest

import isopatch
from conftest import read_ply, require
from isopatch import _isopatch, distributed

require("distributed", "python3-distributed")

CLI = os.environ.get("ISOPATCH_CLI")
SHAPE = (70, 58, 64)
LEVEL = 500.0
WINDOW = 24  # 3 x 3 x 3 windows, none of them a divisor of the shape


def blobs() -> np.ndarray:
    """A CT-like int16 volume: three overlapping Gaussian blobs (a closed surface of genus 0 at LEVEL,
    well inside the grid) scaled to 0..1000, with a little deterministic noise."""
    i, j, k = np.meshgrid(*(np.arange(n, dtype=np.float64) for n in SHAPE), indexing="ij")
    field = np.zeros(SHAPE)
    for centre, width in (((30, 28, 30), 9.0), ((42, 30, 34), 8.0), ((34, 22, 40), 7.0)):
        field += np.exp(-((i - centre[0]) ** 2 + (j - centre[1]) ** 2 + (k - centre[2]) ** 2) / (2 * width ** 2))
    noise = np.random.default_rng(7).uniform(-2.0, 2.0, SHAPE)
    return np.round(1000.0 * np.minimum(field, 1.0) + noise).astype(np.int16)


def spline_value(coefficients: np.ndarray, points: np.ndarray) -> np.ndarray:
    """The tricubic B-spline of `coefficients` (spacing 1, origin 0, mirror boundary) at `points`,
    written out here independently of the library."""
    def weights(t):
        s = 1.0 - t
        return np.stack([s ** 3, 3 * t ** 3 - 6 * t ** 2 + 4, -3 * t ** 3 + 3 * t ** 2 + 3 * t + 1, t ** 3], 1) / 6

    def mirror(index, n):
        period = 2 * (n - 1)
        m = np.mod(index, period)
        return np.where(m >= n, period - m, m)

    cells = np.floor(points)
    w = [weights(points[:, a] - cells[:, a]) for a in range(3)]
    idx = [mirror(cells[:, a, None].astype(np.int64) - 1 + np.arange(4), coefficients.shape[a]) for a in range(3)]
    total = np.zeros(len(points))
    for a in range(4):
        for b in range(4):
            for c in range(4):
                total += (w[0][:, a] * w[1][:, b] * w[2][:, c]
                          * coefficients[idx[0][:, a], idx[1][:, b], idx[2][:, c]])
    return total


def edges_in_two_triangles(faces: np.ndarray) -> bool:
    directed = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    keys = directed[:, 0].astype(np.int64) * (1 << 32) + directed[:, 1]
    reverse = directed[:, 1].astype(np.int64) * (1 << 32) + directed[:, 0]
    return len(np.unique(keys)) == len(keys) and bool(np.isin(reverse, keys).all())


@pytest.fixture(scope="module")
def volume_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("volume") / "blobs.npy"
    np.save(path, blobs())
    return path


@pytest.fixture(scope="module")
def blocked(client, volume_file, tmp_path_factory):
    out = tmp_path_factory.mktemp("blocked")
    manifest = distributed.mesh_blocks(volume=str(volume_file), level=LEVEL, tiles=4, out_dir=str(out),
                                       output=str(out / "blobs.ply"), refine=2, prefilter_window=WINDOW,
                                       scheduler=client)
    return out, manifest


def test_windowed_coefficients_equal_the_whole_volumes_to_rounding(blocked, volume_file):
    out, manifest = blocked
    info = manifest["prefilter"]
    assert info["windows"] == 27 and info["halo"] == 32 and not info["reused"]
    assert info["sample_range"] == [float(blobs().min()), float(blobs().max())]
    mapped = np.load(out / info["file"])
    whole = np.load(volume_file).astype(np.float64)
    _isopatch.prefilter(whole)
    assert mapped.dtype == np.dtype("<f8") and mapped.shape == SHAPE
    assert np.abs(mapped - whole).max() <= 1e-14 * np.abs(whole).max()


def test_the_blocked_volume_mesh_is_watertight_on_the_interpolant_and_of_one_process_topology(blocked,
                                                                                                volume_file):
    out, manifest = blocked
    vertices, faces = read_ply(out / "blobs.ply")
    assert manifest["vertices"] == len(vertices) and manifest["triangles"] == len(faces)
    assert edges_in_two_triangles(faces)
    assert len(np.unique(vertices, axis=0)) == len(vertices)
    coefficients = np.load(out / manifest["prefilter"]["file"])
    assert np.abs(spline_value(coefficients, vertices) - LEVEL).max() < 1e-6  # samples span 0..1000
    one = isopatch.mesh_volume(np.load(volume_file), LEVEL, refine=2)
    assert len(one.vertices) == len(vertices) and len(one.faces) == len(faces)
    euler = len(vertices) - len(faces) // 2  # V - E + F with E = 3F/2
    assert euler == len(one.vertices) - len(one.faces) // 2 == 2


def test_the_coefficients_and_the_mesh_are_the_same_bytes_when_run_again_and_are_reused(blocked, client,
                                                                                        volume_file, tmp_path):
    out, manifest = blocked
    again = distributed.mesh_blocks(volume=str(volume_file), level=LEVEL, tiles=4, out_dir=str(tmp_path),
                                    output=str(tmp_path / "blobs.ply"), refine=2, prefilter_window=WINDOW,
                                    scheduler=client, _test={"reverse": True})
    assert again["output"]["sha256"] == manifest["output"]["sha256"]
    assert (open(tmp_path / again["prefilter"]["file"], "rb").read()
            == open(out / manifest["prefilter"]["file"], "rb").read())
    reused = distributed.mesh_blocks(volume=str(volume_file), level=LEVEL, tiles=4, out_dir=str(tmp_path),
                                     refine=2, prefilter_window=WINDOW, scheduler=client)
    assert reused["prefilter"]["reused"] and reused["reused"] == 4 and reused["computed"] == 0
    with open(reused["manifest"]) as f:
        assert json.load(f)["prefilter"]["file"] == manifest["prefilter"]["file"]


def test_a_nrrd_volume_with_spacing_and_origin(client, tmp_path):
    samples = blobs()
    header = ("NRRD0004\ntype: int16\ndimension: 3\nsizes: %d %d %d\nspacings: 0.5 0.5 0.5\n"
              "space origin: (1,2,3)\nencoding: raw\nendian: little\n\n" % SHAPE)
    path = tmp_path / "blobs.nrrd"
    with open(path, "wb") as f:
        f.write(header.encode() + samples.astype("<i2").tobytes(order="F"))
    manifest = distributed.mesh_blocks(volume=str(path), level=LEVEL, tiles=3, out_dir=str(tmp_path / "out"),
                                       output=str(tmp_path / "blobs.ply"), refine=2, prefilter_window=WINDOW,
                                       scheduler=client)
    vertices, _ = read_ply(tmp_path / "blobs.ply")
    extent_hi = np.array([1, 2, 3]) + 0.5 * (np.array(SHAPE) - 1)
    assert (vertices > [1, 2, 3]).all() and (vertices < extent_hi).all()
    coefficients = np.load(tmp_path / "out" / manifest["prefilter"]["file"])
    grid = (vertices - [1, 2, 3]) / 0.5
    assert np.abs(spline_value(coefficients, grid) - LEVEL).max() < 1e-6


@pytest.mark.parametrize("case", ["nan", "no_crossing", "missing", "flat", "window", "text"])
def test_bad_volumes_are_refused_with_the_librarys_errors(client, tmp_path, case):
    path = tmp_path / "v.npy"
    samples = blobs().astype(np.float32)
    level, window = LEVEL, WINDOW
    expected, words = isopatch.InputError, "NaN at index (61, 5, 33)"
    if case == "nan":
        samples[61, 5, 33] = np.nan
    elif case == "no_crossing":
        level, expected, words = 5000.0, isopatch.NoSurfaceError, "crosses level 5000"
    elif case == "missing":
        path, expected, words = tmp_path / "none.npy", isopatch.IoError, "no such file"
    elif case == "flat":
        samples, expected, words = samples[:, :, :1], isopatch.IoError, "at least 2 samples"
    elif case == "window":
        window, expected, words = 1, isopatch.InputError, "window"
    else:
        path, expected, words = tmp_path / "v.txt", isopatch.IoError, "not a volume file"
    if case != "missing":
        np.save(tmp_path / "v.npy", samples)
        if case == "text":
            os.replace(tmp_path / "v.npy", path)
    with pytest.raises(expected, match=words.replace("(", r"\(").replace(")", r"\)")):
        distributed.mesh_blocks(volume=str(path), level=level, tiles=2, out_dir=str(tmp_path / "out"),
                                prefilter_window=window, scheduler=client)
    leftovers = [n for n in os.listdir(tmp_path / "out")] if (tmp_path / "out").exists() else []
    assert not [n for n in leftovers if ".part" in n]


@pytest.mark.skipif(not CLI, reason="the command-line tool is not built")
def test_the_command_line_meshes_a_volume_in_blocks(volume_file, tmp_path):
    out = tmp_path / "blobs.ply"
    run = subprocess.run([CLI, "mesh", str(volume_file), "--level", "500", "--refine", "2", "--tiles", "2",
                          "--prefilter-window", "40", "--out-dir", str(tmp_path / "blocks"), "-o", str(out)],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert "vertices" in run.stdout and out.exists()
    assert edges_in_two_triangles(read_ply(out)[1])
    with open(re.search(r"manifest (\S+?);", run.stdout).group(1)) as f:
        assert json.load(f)["prefilter"]["windows"] == 8  # 2 x 2 x 2 windows of 40
    alone = subprocess.run([CLI, "mesh", str(volume_file), "--level", "500", "--prefilter-window", "40", "-o",
                            str(tmp_path / "one.ply")], capture_output=True, text=True, timeout=300)
    assert alone.returncode == 3 and "--prefilter-window needs --tiles" in alone.stderr


@pytest.mark.parametrize("window", [24, 64, 100])
def test_every_window_layout_writes_the_whole_volumes_coefficients(volume_file, tmp_path, window):
    """The window tasks run here in order, without a cluster: windows that split the last axis (written
    row by row), that span it (plane by plane) and one window for the whole volume."""
    from isopatch import _prefilter
    part = tmp_path / "c.npy"
    created = np.lib.format.open_memmap(part, mode="w+", dtype="<f8", shape=SHAPE)
    job = {"samples": str(volume_file), "windows": _prefilter.plan_windows(SHAPE, window), "part": str(part),
           "offset": int(created.offset)}
    del created
    ranges = [_prefilter.prefilter_window(job, i) for i in range(len(job["windows"]))]
    whole = np.load(volume_file).astype(np.float64)
    assert min(r["min"] for r in ranges) == whole.min() and max(r["max"] for r in ranges) == whole.max()
    _isopatch.prefilter(whole)
    assert np.abs(np.load(part) - whole).max() <= 1e-14 * np.abs(whole).max()
