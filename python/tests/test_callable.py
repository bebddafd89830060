"""Python functions as surfaces: batched calls, vertices on f = 0, the GIL, threads, Ctrl-C."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import isopatch


class Counted:
    """f(points) = |p|^2 - 1, counting calls and the points passed."""

    def __init__(self):
        self.calls = 0
        self.points = 0
        self.shapes = set()

    def __call__(self, p):
        assert p.dtype == np.float64 and p.ndim == 2 and p.shape[1] == 3
        self.calls += 1
        self.points += len(p)
        return np.einsum("ij,ij->i", p, p) - 1.0


def test_callable_is_called_in_batches(unit_box):
    f = Counted()
    m = isopatch.mesh(f, box=unit_box, edge_length=0.1)
    python = m.stats["python"]
    assert f.calls == python["calls"]
    assert f.points == python["points"]
    assert f.calls <= 20  # sampling in a few batches, then one call per Newton step and one at the end
    assert f.points / f.calls > 10000
    # Vertices on f = 0 itself, not only on the interpolant; normals of the function.
    np.testing.assert_allclose(np.linalg.norm(m.vertices, axis=1), 1.0, atol=1e-10)
    np.testing.assert_allclose(m.normals, m.vertices, atol=1e-6)
    assert np.abs(m.fields["distance"]).max() < 1e-10
    assert python["unprojected_vertices"] == 0
    report = m.analyze()
    assert report["topology"]["watertight"] and report["valence"]["share_6"] >= 0.9


def test_batch_size_is_respected(unit_box):
    f = Counted()
    isopatch.mesh(f, box=unit_box, samples=40, batch=5000, quality="preview")
    assert f.calls >= 41 ** 3 // 5000
    assert f.points / f.calls <= 5000


def test_gradient_callable(unit_box):
    calls = []

    def gradient(p):
        calls.append(len(p))
        return 2.0 * p

    m = isopatch.mesh(lambda p: np.sum(p * p, axis=1) - 1.0, box=unit_box, gradient=gradient, edge_length=0.1)
    assert len(calls) >= 2  # the Newton steps and the final normals use it
    np.testing.assert_allclose(np.linalg.norm(m.vertices, axis=1), 1.0, atol=1e-10)
    np.testing.assert_allclose(m.normals, m.vertices, atol=1e-12)


def test_meshing_from_two_threads_at_once(unit_box):
    def ellipsoid(p):
        return p[:, 0] ** 2 + 2 * p[:, 1] ** 2 + 3 * p[:, 2] ** 2 - 1.0

    expected = isopatch.mesh(ellipsoid, box=unit_box, edge_length=0.08)
    results = [None, None]
    errors = []

    def work(slot):
        try:
            results[slot] = isopatch.mesh(ellipsoid, box=unit_box, edge_length=0.08)
        except Exception as e:  # noqa: BLE001  (reported below)
            errors.append(e)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    for r in results:
        assert np.array_equal(r.vertices, expected.vertices) and np.array_equal(r.faces, expected.faces)


def test_meshing_releases_the_gil(unit_box):
    ticks = 0
    stop = threading.Event()

    def count():
        nonlocal ticks
        while not stop.is_set():
            ticks += 1
            time.sleep(0.001)

    t = threading.Thread(target=count)
    t.start()
    start = time.perf_counter()
    meshing = 0.0
    while meshing < 0.5:  # however fast the machine, at least half a second inside the library
        before = time.perf_counter()
        isopatch.mesh("x^2+y^2+z^2-1", box=unit_box, edge_length=0.04)
        meshing += time.perf_counter() - before
    elapsed = time.perf_counter() - start
    stop.set()
    t.join()
    # A thread sleeping 1 ms per tick ticks hundreds of times in half a second only if the GIL is free
    # while the library meshes (holding it, the library would leave it a tick per call at most).
    assert ticks > 0.1 * elapsed / 0.001


def test_ctrl_c_cancels_cleanly(unit_box):
    sent = []

    def interrupt():
        sent.append(time.perf_counter())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(0.5, interrupt)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        # About 2 million triangles: far longer than the half second before the signal.
        isopatch.mesh("x^2+y^2+z^2-1", box=unit_box, edge_length=0.004)
    latency = time.perf_counter() - sent[0]
    timer.join()
    assert latency < 5.0  # stopped at the library's next cancellation check, not at the end of the run
    # The library is still usable afterwards.
    assert len(isopatch.mesh("x^2+y^2+z^2-1", box=unit_box, edge_length=0.2).vertices) > 100
