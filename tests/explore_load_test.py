#!/usr/bin/env python3
"""The explorer under load (common/app/explore_server.cpp; book §0.11), over HTTP with Python's
http.client:

  explore_load_test.py ROOT BIN_DIR WORK_DIR [sanitized]

Serves ch07's mirrors and sends 2,000 mixed requests from 8 clients at once: states, frames,
picks and side views, camera moves, options, scenes (good and refused), and requests the gate
turns away (no token, a foreign Host, a foreign Origin, a body over the limit). Every answer
must be the one expected, the server must still answer afterwards, and once it is idle again
its threads (/proc/PID/status Threads) and its memory (VmRSS) must be back where they were
before the load: the same number of threads, and the resident memory within MEMORY_SLACK.
While the load runs, it never has more threads than when idle plus the render's workers:
requests are served by a fixed pool, however many arrive.

"Before" is after a first round of the same 2,000 requests: the first time each of the
server's threads allocates, glibc gives it an arena, which keeps what it was given for that
thread's next allocations; oneTBB starts its workers the first time a tree is built in
parallel. Neither is a leak: with one arena (MALLOC_ARENA_MAX=1) the server's memory stopped
growing after 14,000 requests of this mix and stayed there for 10,000 more. A sanitized build
(the argument `sanitized`) keeps freed memory in quarantine: there only the threads are
compared.
"""
import json
import os
import pathlib
import socket
import sys
import threading
import time

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from checks import check, finish  # noqa: E402
from explore_client import Explorer  # noqa: E402

root, bin_dir, work = (pathlib.Path(a).resolve() for a in sys.argv[1:4])
sanitized = sys.argv[4:5] == ["sanitized"]
work.mkdir(parents=True, exist_ok=True)
SCENE = root / "chapters/ch07_specular_reflection/scenes/mirrors.json"
W, H, THREADS = 96, 54, 2
OPTIONS = ["--width", str(W), "--height", str(H), "--threads", str(THREADS)]
CLIENTS, REQUESTS = 8, 2000
# Resident memory may grow this much over the 2,000 requests: 4 to 9 times what it grew by on
# this machine (110 to 250 KiB: each thread's arena settling). A leak of 512 bytes a request
# on average, or of a frame, a scene or a side view per request of its kind, is past it.
MEMORY_SLACK = 1 << 20


def status_of(pid):
    """Threads and VmRSS (bytes) of a process, from /proc."""
    fields = dict(line.split(":", 1) for line in pathlib.Path(f"/proc/{pid}/status").read_text().splitlines())
    return int(fields["Threads"]), int(fields["VmRSS"].split()[0]) * 1024


def idle():
    """Threads and memory once the view has converged and the server has settled: the same
    frame for a while, and the thread count unchanged over several readings."""
    deadline = time.time() + 120
    last = None
    while time.time() < deadline:
        status, headers, _ = server.get("/api/frame?after=0&wait=0")
        done = status == 200 and headers["X-Samples"] == headers["X-Target-Samples"]
        readings = []
        for _ in range(5):
            time.sleep(0.1)
            readings.append(status_of(server.process.pid))
        frame = headers.get("X-Frame-Id")
        if done and frame == last and len({t for t, _ in readings}) == 1:
            return readings[-1]
        last = frame if done else None
    return None


scene_text = SCENE.read_text()
outside = json.loads(scene_text)
outside["surfaces"].append({"type": "mesh", "file": "/etc/passwd", "material": "red"})
outside = json.dumps(outside)


def one(k, i):
    """Request i of client k: what was asked, and whether the answer was the one expected."""
    which = (k + 3 * i) % 13
    x, y = (k * 7 + i) % W, (k + i * 5) % H
    if which == 0:
        s, _, body = server.get("/api/state")
        return "state", s == 200 and json.loads(body)["chapter"] == "ch07"
    if which == 1:
        s, _, _ = server.get(f"/api/frame?after={i}&wait=20")
        return "frame", s in (200, 204)
    if which == 2:
        s, _, body = server.get(f"/api/pick?x={x}&y={y}")
        return "pick", s == 200 and json.loads(body)["pixel"] == [x, y]
    if which == 3:
        s, _, body = server.get(f"/api/tree.svg?x={x}&y={y}")
        return "side view", s == 200 and body.startswith(b"<svg")
    if which == 4:
        eye = [-1.4 + 0.01 * k, 1.7, 3.4 - 0.001 * i]
        s, _, _ = server.post("/api/camera", json.dumps({"eye": eye, "target": [2, 1, -0.4], "fov": 55}))
        return "camera", s == 200
    if which == 5:
        s, _, _ = server.post("/api/options", json.dumps(OPTIONS + ["--spp", str(1 + i % 4)]))
        return "options", s == 200
    if which == 6:
        s, _, _ = server.post("/api/scene", scene_text.replace('"max_depth": 8', f'"max_depth": {2 + i % 6}'))
        return "scene", s == 200
    if which == 7:
        s, _, body = server.post("/api/scene", outside)
        return "scene refused", s == 400 and b"is refused" in body
    if which == 8:
        s, _, _ = server.get("/api/state", token=False)
        return "no token", s == 403
    if which == 9:
        s, _, _ = server.get("/api/state", host=f"evil.example:{server.port}")
        return "foreign Host", s == 403
    if which == 10:
        s, _, _ = server.post("/api/options", "[]", headers={"Origin": "http://evil.example"})
        return "foreign Origin", s == 403
    if which == 11:
        with socket.create_connection(("127.0.0.1", server.port), timeout=30) as c:
            c.sendall(f"POST /api/scene HTTP/1.1\r\nHost: 127.0.0.1:{server.port}\r\nX-Rtlab-Token: {server.token}\r\n"
                      f"Content-Length: {(16 << 20) + 1}\r\n\r\n".encode())
            return "body over the limit", c.recv(64).startswith(b"HTTP/1.1 413 ")
    s, _, body = server.get("/", token=False)
    return "page", s == 200 and b"rtlab explorer" in body


def load(requests):
    """`requests` requests from CLIENTS clients at once: the failures, and the most threads seen."""
    failures, lock, most = [], threading.Lock(), [0]
    running = threading.Event()
    running.set()

    def client(k):
        for i in range(requests // CLIENTS):
            try:
                what, ok = one(k, i)
            except Exception as e:  # a refused or broken connection is a failure too
                what, ok = f"request {k}/{i}: {e!r}", False
            if not ok:
                with lock:
                    failures.append(what)

    def watch():
        while running.is_set():
            most[0] = max(most[0], status_of(server.process.pid)[0])
            time.sleep(0.02)

    watcher = threading.Thread(target=watch)
    watcher.start()
    clients = [threading.Thread(target=client, args=(k,)) for k in range(CLIENTS)]
    for c in clients:
        c.start()
    for c in clients:
        c.join(300)
    running.clear()
    watcher.join()
    return failures, most[0]


server = Explorer(bin_dir / "ch07", "--scene", SCENE, *OPTIONS, "--spp", 4)
try:
    started = idle()
    check(started is not None, "the server settles after it starts")
    failures, _ = load(REQUESTS)  # the first round: arenas and oneTBB's workers (see above)
    check(not failures, f"the first round's answers are all as expected: {failures[:5]}")
    server.post("/api/options", json.dumps(OPTIONS + ["--spp", "4"]))
    before = idle()
    # oneTBB's workers (one fewer than the cores it may use) may have started in the first
    # round or before it, as the scheduler had it; nothing else may be new.
    tbb_workers = len(os.sched_getaffinity(0)) - 1
    check(before is not None and started[0] <= before[0] <= started[0] + tbb_workers,
          f"after the first round the server has the threads it started with, and oneTBB's "
          f"{tbb_workers} workers at most: {before} {started}")

    begun = time.time()
    failures, most = load(REQUESTS)
    seconds = time.time() - begun
    check(not failures, f"{REQUESTS} requests from {CLIENTS} clients answered as expected: {len(failures)} not, "
                        f"first {failures[:5]}")
    check(server.process.poll() is None and server.get("/api/state")[0] == 200, "the server still answers")
    check(most <= before[0] + THREADS, f"while loaded, at most {before[0]} threads and the render's {THREADS} "
                                       f"workers: {most}")
    server.post("/api/options", json.dumps(OPTIONS + ["--spp", "4"]))
    after = idle()
    check(after is not None, "the server settles after the load")
    if before and after:
        print(f"{REQUESTS} requests in {seconds:.1f} s; threads {before[0]} -> {after[0]} (at most {most} meanwhile); "
              f"VmRSS {before[1] / 2**20:.1f} -> {after[1] / 2**20:.1f} MiB")
        check(after[0] == before[0], f"threads back to where they were: {before[0]} -> {after[0]}")
        if sanitized:
            print("(a sanitized build: its allocator keeps what is freed in quarantine, so memory is not compared)")
        else:
            check(after[1] <= before[1] + MEMORY_SLACK,
                  f"memory back to where it was, within {MEMORY_SLACK >> 10} KiB: {before[1] >> 10} -> {after[1] >> 10} KiB")
finally:
    server.stop()

finish("explore_load")
