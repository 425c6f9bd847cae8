#!/usr/bin/env python3
"""The explorer's server (common/app/explore_server.cpp), over HTTP (tests/explore_client.py:
http.client, with the token the explorer printed; what it refuses is tests/explore_gate_test.py).

  explore_endpoints_test.py ROOT BIN_DIR WORK_DIR

Starts ch07 --explore on a free port of 127.0.0.1 and checks: the page and three.js are
served; a converged frame is the image ch07 renders with the same settings (within one 8-bit
step: the page's sRGB table); a pick is what --pick prints, key for key; bad requests get a
4xx and one line naming the problem; a scene error is the loader's FILE:LINE:COL: /pointer:
message, as the command line prints it, and renders nothing; many requests at once, and a
connection that sends nothing, neither crash nor stall it; a taken port is refused.
"""
import json
import pathlib
import socket
import struct
import subprocess
import sys
import threading
import time

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from checks import check, finish  # noqa: E402
from explore_client import Explorer  # noqa: E402

root, bin_dir, work = (pathlib.Path(a).resolve() for a in sys.argv[1:4])
work.mkdir(parents=True, exist_ok=True)
ch07 = str(bin_dir / "ch07")
W, H = 96, 54
SCENE = root / "chapters/ch07_specular_reflection/scenes/mirrors.json"
# What the page posts: every option it sets (those not given take their defaults again).
OPTIONS = json.dumps(["--width", str(W), "--height", str(H), "--spp", "4"])


def request(path, body=None, method=None, timeout=30):
    """(status, headers, bytes) of one request; never raises for an HTTP error status."""
    return server.request(method or ("GET" if body is None else "POST"), path, body, timeout=timeout)


def error_of(body):
    try:
        return json.loads(body)["error"]
    except (ValueError, KeyError):
        return None


def srgb(linear):
    c = min(max(linear, 0.0), 1.0)
    return 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055


def read_pfm(path):
    data = path.read_bytes()
    parts = data.split(b"\n", 3)
    w, h = map(int, parts[1].split())
    scale = float(parts[2])
    values = struct.unpack(("<" if scale < 0 else ">") + f"{w * h * 3}f", parts[3][: w * h * 12])
    rows = [values[(h - 1 - y) * w * 3:(h - y) * w * 3] for y in range(h)]  # PFM rows go up
    return w, h, [v for row in rows for v in row]


server = Explorer(ch07, "--scene", SCENE, "--width", W, "--height", H, "--spp", 4)
port = server.port
check(port is not None and server.line.startswith("ch07: the explorer is at http://127.0.0.1:") and
      len(server.token) == 32, f"the first line gives the address and its token: {server.line!r}")
try:
    # The page, its script and three.js from libjs-three.
    status, headers, body = request("/")
    check(status == 200 and b"rtlab explorer" in body and b"three.min.js" in body, "GET / serves the page")
    status, _, body = request("/three.min.js")
    check(status == 200 and b"THREE" in body[:2000] + body[-2000:], "three.js is served")
    status, _, body = request("/api/state")
    state = json.loads(body)
    check(state["chapter"] == "ch07" and state["scene"] == "mirrors", f"state names the chapter and scene: {state['chapter']} {state['scene']}")
    check(state["options"]["width"] == W and state["options"]["spp"] == 4, f"state has the options: {state['options']}")
    check(state["build"]["track"] in ("solutions", "exercises"), "state says which exercises run")

    # Refining to the target, one sample per pass.
    def converged(generation_after=0):
        """The first frame of a later generation than the one given that has all 4 samples."""
        after, deadline = 0, time.time() + 120
        while time.time() < deadline:
            status, headers, body = request(f"/api/frame?after={after}&wait=2000")
            if status == 200:
                after = int(headers["X-Frame-Id"])
                if int(headers["X-Generation"]) > generation_after and int(headers["X-Samples"]) == 4:
                    return int(headers["X-Generation"]), body
        return generation_after, None

    generation, frame = converged()
    check(frame is not None and len(frame) == W * H * 4, "the frame converges to 4 samples, RGBA")
    # The same seed again gives the same frame, byte for byte; another seed another one.
    check(request("/api/options", OPTIONS, "POST")[0] == 200, "the same options again restart")
    generation, again = converged(generation)
    check(again == frame, "a still camera converges to the same frame for the same seed")
    check(request("/api/options", json.dumps(json.loads(OPTIONS) + ["--seed", "7"]), "POST")[0] == 200, "another seed")
    generation, other = converged(generation)
    check(other is not None and other != frame, "another seed, another frame")
    request("/api/options", OPTIONS, "POST")
    def render(seed):
        path = work / f"mirrors-{seed}.pfm"
        subprocess.run([ch07, "--scene", str(SCENE), "--width", str(W), "--height", str(H), "--spp", "4",
                        "--seed", str(seed), "-o", str(path)], check=True)
        _, _, linear = read_pfm(path)
        return [round(255 * srgb(v)) for v in linear]

    def mean_difference(a, b):  # a, b: RGB; frames are RGBA
        return sum(abs(a[i] - b[i]) for i in range(len(b))) / len(b)

    if frame is not None:
        # Each pass has random numbers of its own (explore_session.cpp), so the converged frame
        # is another 4-sample estimate of ch07's image: as far from ch07's render as two of
        # ch07's renders with different seeds are from each other, and no further.
        rgb = [frame[4 * i + c] for i in range(W * H) for c in range(3)]
        cli0, cli1 = render(0), render(1)
        noise, ours = mean_difference(cli0, cli1), mean_difference(rgb, cli0)
        check(ours <= 1.5 * noise + 0.5, f"the converged frame is ch07's render but for noise ({ours:.2f}, ch07 against itself {noise:.2f})")
        check(all(frame[4 * i + 3] == 255 for i in range(W * H)), "alpha is opaque")
    status, headers, _ = request("/api/frame?after=0")
    check(float(headers["X-Nodes-Per-Ray"]) > 0 and float(headers["X-Primitives-Per-Ray"]) > 0,
          f"a frame says what the search cost per ray: {headers['X-Nodes-Per-Ray']}, {headers['X-Primitives-Per-Ray']}")
    # The same frame as rgb and as rgba: asked for in turn until both are of one frame (the
    # view converges in a few passes, and then the frame stays).
    same = None
    for _ in range(100):
        _, h_rgb, packed = request("/api/frame?after=0&format=rgb")
        _, h_rgba, rgba = request("/api/frame?after=0&format=rgba")
        if h_rgb["X-Frame-Id"] == h_rgba["X-Frame-Id"]:
            same = (packed, rgba)
            break
        time.sleep(0.05)
    check(same is not None and len(same[0]) == W * H * 3 and same[0] == bytes(b for i, b in enumerate(same[1]) if i % 4 != 3),
          "format=rgb sends the RGBA frame's bytes without alpha")
    for fmt, magic in (("png", b"\x89PNG"), ("jpeg", b"\xff\xd8")):
        status, headers, body = request(f"/api/frame?after=0&format={fmt}")
        check(status == 200 and body.startswith(magic) and headers["Content-Type"].startswith("image/"),
              f"format={fmt} sends a {fmt}")

    # A pick is what --pick prints for the same pixel and settings, key for key.
    status, _, body = request("/api/pick?x=70&y=20")
    picked = json.loads(body)
    cli = json.loads(subprocess.run([ch07, "--scene", str(SCENE), "--width", str(W), "--height", str(H),
                                     "--pick", "70,20"], check=True, capture_output=True, text=True).stdout)
    check(status == 200 and picked == cli, "a pick is exactly what --pick prints")
    status, headers, body = request("/api/tree.svg?x=70&y=20")
    svg_file = work / "tree.svg"
    subprocess.run([ch07, "--scene", str(SCENE), "--width", str(W), "--height", str(H), "--pick", "70,20",
                    "--svg", str(svg_file)], check=True, capture_output=True)
    check(status == 200 and headers["Content-Type"] == "image/svg+xml" and body == svg_file.read_bytes(),
          "the side view is what --svg draws")

    # Bad requests: a 4xx and a line naming the problem; the server carries on.
    bad = [
        ("/api/frame?after=abc", None, 400, "parameter 'after' must be a whole number"),
        ("/api/frame?after=-1", None, 400, "parameter 'after'"),
        ("/api/frame?wait=99999999", None, 400, "parameter 'wait'"),
        ("/api/frame?format=gif", None, 400, "must be rgb, rgba, png or jpeg, not 'gif'"),
        ("/api/pick?x=5", None, 400, "missing parameter 'y'"),
        (f"/api/pick?x={W}&y=0", None, 400, f"is outside the {W}x{H} image"),
        ("/api/pick?x=1e3&y=0", None, 400, "parameter 'x'"),
        ("/api/tree.svg?y=0", None, 400, "missing parameter 'x'"),
        ("/nothing/here", None, 404, "no such page: GET /nothing/here"),
        ("/api/options", "{\"spp\": 4}", 400, "a JSON array of strings"),
        ("/api/options", "not json", 400, "a JSON array of strings"),
        ("/api/options", "[\"--spp\", \"0\"]", 400, "--spp"),
        ("/api/options", "[\"--spp\", \"3\", \"--pattern\", \"jittered\"]", 400, "n x n samples"),
        ("/api/options", "[\"--bogus\"]", 400, "--bogus"),
        ("/api/options", "[\"--accel\", \"octree\"]", 400, "unknown 'octree'"),
        ("/api/camera", "{\"eye\": [0, 1]}", 400, "camera:1:2: /eye: must be an array of 3 numbers"),
        ("/api/camera", "{\"eye\": [0,0,0], \"target\": [0,0,0]}", 400, "camera:"),
        ("/api/camera", "{", 400, "not valid JSON"),
        ("/api/scene", "", 400, "not valid JSON"),
    ]
    for path, body, want_status, words in bad:
        status, _, got = request(path, body, "POST" if body is not None else "GET")
        message = error_of(got) or ""
        check(status == want_status and words in message and "\n" not in message,
              f"{path} {body!r}: {status} {message!r}, expected {want_status} with {words!r}")

    # A scene error is the loader's line, as the command line prints it, and renders nothing.
    _, headers, _ = request(f"/api/frame?after=0")
    generation = int(headers["X-Generation"])
    text = SCENE.read_text().replace('"max_depth": 8', '"max_depth": "deep"')
    bad_file = work / "mirrors.json"
    bad_file.write_text(text)
    status, _, body = request("/api/scene", text, "POST")
    cli = subprocess.run([ch07, "--scene", str(bad_file)], capture_output=True, text=True)
    expected = cli.stderr.strip().replace(f"ch07: error: {bad_file}", "")
    message = error_of(body) or ""
    check(status == 400 and cli.returncode == 2 and message == str(SCENE) + expected,
          f"a scene error is the loader's: {message!r} against {cli.stderr.strip()!r}")
    time.sleep(0.5)
    _, headers, _ = request(f"/api/frame?after=0")
    check(int(headers["X-Generation"]) == generation, "a refused scene renders nothing")
    # A good edit is taken and rendered.
    status, _, body = request("/api/scene", SCENE.read_text().replace('"max_depth": 8', '"max_depth": 2'), "POST")
    check(status == 200, f"a good scene is taken: {body!r}")
    status, headers, _ = request(f"/api/frame?after=0&wait=5000")
    deadline = time.time() + 30
    while int(headers["X-Generation"]) == generation and time.time() < deadline:
        status, headers, _ = request(f"/api/frame?after={headers['X-Frame-Id']}&wait=2000")
    check(int(headers["X-Generation"]) > generation, "a good scene renders")

    # --depth overrides the file's max_depth while it is given, through a new scene too.
    request("/api/options", json.dumps(json.loads(OPTIONS) + ["--depth", "3"]), "POST")
    request("/api/scene", SCENE.read_text(), "POST")
    depth = json.loads(request("/api/state")[2])["options"]["depth"]
    request("/api/options", OPTIONS, "POST")
    check((depth, json.loads(request("/api/state")[2])["options"]["depth"]) == (3, 8),
          f"--depth 3 overrides max_depth 8, and without it the file's is back: {depth}")

    # A click right after a move sees the moved camera.
    eye = [-1.0, 1.5, 3.0]
    request("/api/camera", json.dumps({"eye": eye, "target": [2, 1, -0.4], "fov": 50}), "POST")
    status, _, body = request("/api/pick?x=10&y=10")
    check(status == 200 and json.loads(body)["ray"]["origin"] == eye, f"a pick after a move starts at the new eye: {body[:120]!r}")

    # A connection that sends nothing holds one worker, not the server.
    idle = socket.create_connection(("127.0.0.1", port))
    idle.sendall(b"GET /api/state HTTP/1.1\r\n")  # and never the rest

    # Many requests at once: long polls, state, picks, camera moves and options.
    results = []
    lock = threading.Lock()

    def client(k):
        for i in range(6):
            which = (k + i) % 5
            if which == 0:
                r = request("/api/frame?after=999999&wait=300")
                ok = r[0] == 200
            elif which == 1:
                r = request("/api/state")
                ok = r[0] == 200 and json.loads(r[2])["chapter"] == "ch07"
            elif which == 2:
                r = request(f"/api/pick?x={k % W}&y={i % H}")
                ok = r[0] == 200 and json.loads(r[2])["pixel"] == [k % W, i % H]
            elif which == 3:
                eye = [-1.4 + 0.01 * k, 1.7, 3.4]
                r = request("/api/camera", json.dumps({"eye": eye, "target": [2, 1, -0.4], "fov": 55}), "POST")
                ok = r[0] == 200
            else:
                r = request("/api/options", json.dumps(["--spp", str(1 + (k + i) % 4)]), "POST")
                ok = r[0] == 200
            with lock:
                results.append((ok, which, r[0]))

    start_time = time.time()
    threads = [threading.Thread(target=client, args=(k,)) for k in range(12)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(120)
    elapsed = time.time() - start_time
    check(len(results) == 72 and all(ok for ok, _, _ in results),
          f"72 concurrent requests all answered: {[r for r in results if not r[0]][:5]} of {len(results)}")
    check(elapsed < 60, f"and within a minute ({elapsed:.1f} s)")
    idle.close()
    check(server.process.poll() is None, "the server is still running")
    status, _, _ = request("/api/state")
    check(status == 200, "and answers")

    # The port is taken: a second server on it is refused with one line, exit 2.
    second = subprocess.run([ch07, "--explore", "--port", str(port)], capture_output=True, text=True, timeout=60)
    check(second.returncode == 2 and second.stderr.count("\n") == 1 and f"--port {port}" in second.stderr,
          f"a taken port: exit {second.returncode}, {second.stderr!r}")
finally:
    server.stop()

# Options only the explorer takes.
for args, words in ((["--port", "8000"], "--port: an option of the explorer, so it needs --explore"),
                    (["--allow", str(work)], "--allow: an option of the explorer, so it needs --explore"),
                    (["--no-token"], "--no-token: an option of the explorer, so it needs --explore"),
                    (["--explore", "--allow", str(work / "no-such-folder")], "--allow"),
                    (["--explore", "--pick", "1,1"], "--explore: serves a page"),
                    (["--explore", "--port", "70000"], "--port")):
    r = subprocess.run([ch07, *args], capture_output=True, text=True, timeout=60)
    check(r.returncode == 2 and words in r.stderr and r.stderr.count("\n") == 1, f"{args}: {r.returncode} {r.stderr!r}")

finish("explore_endpoints")
