"""A bounded soak of the viewer's server (`isopatch view`, started and stopped here on 127.0.0.1): 16
connections for ISOPATCH_SOAK_SECONDS (120 in the test command) of mixed requests - pages, state,
valid meshes, requests superseded by newer ones, malformed and oversized bodies, unsafe paths, other
host names and other sites' posts. Every answer must be well-formed HTTP with the status its request
calls for (JSON where the API answers), the server must live through it, and its resident memory at
the end must be within 20% of its value after the first 10 seconds."""
import http.client
import json
import os
import random
import signal
import subprocess
import threading
import time

import pytest

CLI = os.environ.get("ISOPATCH_CLI")
SECONDS = float(os.environ.get("ISOPATCH_SOAK_SECONDS", "120"))
CONNECTIONS = 16

pytestmark = pytest.mark.skipif(not CLI, reason="ISOPATCH_CLI names the command-line tool")


def resident_kib(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise AssertionError("no VmRSS")


def one_request(port, rng):
    """Sends one random request; returns (kind, status, body) or raises on a malformed answer."""
    own = f"127.0.0.1:{port}"
    kind = rng.choice(["page", "state", "mesh", "mesh", "bad_json", "oversized", "unknown_member", "unsafe_path",
                       "other_host", "other_origin", "download"])
    headers = {"Host": own}
    method, path, body = "GET", "/", None
    if kind == "state":
        path = "/api/state"
    elif kind == "mesh":
        method, path = "POST", "/api/mesh"
        request = {"surface": rng.choice(["sphere", "torus", "x^2+y^2+z^2-1", "genus2"]),
                   "edge_length": rng.choice([0.2, 0.3, 0.4]), "quality": "preview"}
        if "^" in request["surface"]:
            request["box"] = [-1.5, -1.5, -1.5, 1.5, 1.5, 1.5]
        body = json.dumps(request)
    elif kind == "bad_json":
        method, path, body = "POST", "/api/mesh", '{"surface": "sphere", '
    elif kind == "oversized":
        method, path, body = "POST", "/api/mesh", json.dumps({"surface": "x" * 70000})
    elif kind == "unknown_member":
        method, path, body = "POST", "/api/mesh", json.dumps({"surface": "sphere", "colour": "red"})
    elif kind == "unsafe_path":
        path = rng.choice(["/../CMakeLists.txt", "/%2e%2e/%2e%2e/etc/passwd", "/three/package.json"])
    elif kind == "other_host":
        headers["Host"] = f"attacker.example:{port}"
    elif kind == "other_origin":
        method, path, body = "POST", "/api/mesh", json.dumps({"surface": "sphere"})
        headers["Origin"] = "http://attacker.example"
    elif kind == "download":
        path = f"/api/mesh/{rng.randint(0, 50)}.glb"
    connection = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    try:
        if body is not None:
            headers["Content-Type"] = "application/json"
        connection.request(method, path, body=body, headers=headers)
        answer = connection.getresponse()
        data = answer.read()
        return kind, answer.status, data, answer.getheader("Content-Type") or ""
    except (ConnectionResetError, BrokenPipeError):
        # The server answers an oversized body from its Content-Length (413) and closes without reading
        # the body; the rest of the body still in flight makes the kernel reset the connection, which
        # may reach the client before the answer. Only there is a reset an answer.
        if kind != "oversized":
            raise ConnectionResetError("%s %s (%s): the connection was reset" % (method, path, kind)) from None
        return kind, 413, b"", ""
    finally:
        connection.close()


EXPECTED = {
    "page": {200}, "state": {200}, "mesh": {200, 409}, "bad_json": {400}, "oversized": {400, 413},
    "unknown_member": {400}, "unsafe_path": {400, 404}, "other_host": {403}, "other_origin": {403},
    "download": {200, 404},
}


def test_the_viewer_lives_through_minutes_of_mixed_and_hostile_requests():
    server = subprocess.Popen([CLI, "view", "torus", "--port", "0"], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True)
    try:
        url = server.stdout.readline().strip()
        assert url.startswith("http://127.0.0.1:"), server.stderr.read()
        port = int(url.rsplit(":", 1)[1].strip("/"))
        stop = time.monotonic() + SECONDS
        problems, counts = [], {}
        lock = threading.Lock()
        baseline = {}

        def worker(seed):
            rng = random.Random(seed)
            while time.monotonic() < stop and not problems:
                try:
                    kind, status, data, content_type = one_request(port, rng)
                except Exception as error:  # a malformed answer or a dropped connection
                    with lock:
                        problems.append(f"{type(error).__name__}: {error}")
                    return
                ok = status in EXPECTED[kind]
                if ok and content_type.startswith("application/json"):
                    try:
                        json.loads(data)
                    except ValueError:
                        ok = False
                with lock:
                    counts[kind] = counts.get(kind, 0) + 1
                    if not ok:
                        problems.append(f"{kind}: {status} {data[:200]!r}")

        threads = [threading.Thread(target=worker, args=(seed,)) for seed in range(CONNECTIONS)]
        for t in threads:
            t.start()
        time.sleep(min(10.0, SECONDS / 4))
        baseline["kib"] = resident_kib(server.pid)
        for t in threads:
            t.join()
        assert not problems, problems[:5]
        assert server.poll() is None, "the server died"
        end_kib = resident_kib(server.pid)
        assert end_kib <= 1.2 * baseline["kib"], (baseline, end_kib)
        assert all(counts.get(kind, 0) > 0 for kind in EXPECTED), counts
    finally:
        server.send_signal(signal.SIGINT)
        server.wait(timeout=60)
