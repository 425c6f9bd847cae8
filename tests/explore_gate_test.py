#!/usr/bin/env python3
"""What the explorer refuses (common/app/explore_gate.cpp, common/io/file_access.cpp; book
§0.11), asked of a real ch07 --explore over HTTP with Python's http.client:

  explore_gate_test.py ROOT BIN_DIR WORK_DIR

- no token, or a wrong one, on every endpoint but the page's own files: 403 and one line, and
  nothing changed;
- each foreign Host (another name, another port, none at all), even with the token: 403; this
  server's three names are served;
- a foreign Origin on each POST: 403, and nothing changed; the page's own origin is taken;
- no CORS header in any answer, and a preflight refused;
- a body over the scene-file limit refused before it is sent, a chunked one, a Content-Length
  that is not a number;
- --allow and --no-token refused from the page;
- a scene's mesh outside the chapter's scenes, ../shared/assets and --allow's folder (absolute,
  "..", a link that leads out): one line naming the rule, the same whether or not the file is
  there, no byte of it, and the file never opened (inotify watches it); inside, it is loaded;
- a surface named with <script> and "onload=: escaped in /api/tree.svg, which is well-formed
  XML with no script element and no event attribute, sent with a policy that runs nothing;
- the headers: the page's Content-Security-Policy, nosniff on every answer;
- --no-token: said on the terminal; no token asked, Host and Origin still checked.
"""
import ctypes
import json
import os
import pathlib
import socket
import struct
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from checks import check, finish  # noqa: E402
from explore_client import Explorer, ball_scene  # noqa: E402

root, bin_dir, work = (pathlib.Path(a).resolve() for a in sys.argv[1:4])
work.mkdir(parents=True, exist_ok=True)
ch07 = bin_dir / "ch07"
SCENE = root / "chapters/ch07_specular_reflection/scenes/mirrors.json"
SIZE = ["--width", 64, "--height", 36, "--spp", 1]

# The files a posted scene names: one under --allow's folder, one outside it with a secret in
# it, and a link from the allowed folder to the secret.
allowed, outside = work / "allowed", work / "outside"
for folder in (allowed, outside):
    folder.mkdir(exist_ok=True)
(allowed / "tri.obj").write_text("v 0 0 -3\nv 1 0 -3\nv 0 1 -3\nf 1 2 3\n")
secret = outside / "secret.obj"
secret.write_text("v zz_secret_token 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
link = allowed / "link.obj"
if link.is_symlink():
    link.unlink()
link.symlink_to(os.path.relpath(secret, allowed))


class Opens:
    """inotify(7) on some files and folders: how many times anything opened or read them."""
    IN_ACCESS, IN_OPEN = 0x1, 0x20

    def __init__(self, *paths):
        libc = ctypes.CDLL(None, use_errno=True)
        self.fd = libc.inotify_init1(os.O_NONBLOCK)
        self.watching = self.fd >= 0 and all(
            libc.inotify_add_watch(self.fd, os.fsencode(p), self.IN_OPEN | self.IN_ACCESS) >= 0 for p in paths)

    def count(self):
        try:
            data = os.read(self.fd, 1 << 16)
        except BlockingIOError:
            return 0
        n = 0
        while data:
            _, _, _, length = struct.unpack_from("iIII", data)
            data = data[16 + length:]
            n += 1
        return n


def error_of(body):
    try:
        return json.loads(body)["error"]
    except (ValueError, KeyError, TypeError):
        return ""


cors = []  # every answer's Access-Control-* headers: there must be none


def ask(method, path, body=None, **options):
    status, headers, data = server.request(method, path, body, **options)
    cors.extend(k for k in headers.keys() if k.lower().startswith("access-control-"))
    return status, headers, data


def state():
    return json.loads(ask("GET", "/api/state")[2])


def refused(status, body, want_status, words):
    message = error_of(body)
    return status == want_status and words in message and "\n" not in message


server = Explorer(ch07, "--scene", SCENE, *SIZE, "--allow", allowed)
port, token = server.port, server.token
check(port and len(token) == 32 and all(c in "0123456789abcdef" for c in token),
      f"the address has a token of 128 random bits: {server.line!r}")
try:
    # Another run, another token.
    other = Explorer(ch07, "--scene", SCENE, *SIZE)
    check(other.token and other.token != token, "each run has its own token")
    other.stop()

    # The page's own files need no token; everything else does.
    for path in ("/", "/explore.js", "/explore.css", "/three.min.js"):
        check(ask("GET", path, token=False)[0] == 200, f"{path} is served without the token")
    status, headers, _ = ask("GET", "/", token=False)
    policy = headers.get("Content-Security-Policy", "")
    check("script-src 'self'" in policy and "default-src 'none'" in policy and "frame-ancestors 'none'" in policy,
          f"the page says scripts come from its own origin only: {policy!r}")
    endpoints = [("GET", "/api/state", None), ("GET", "/api/frame?after=0&wait=0", None),
                 ("GET", "/api/pick?x=1&y=1", None), ("GET", "/api/tree.svg?x=1&y=1", None),
                 ("GET", "/nothing/here", None), ("POST", "/api/scene", SCENE.read_text()),
                 ("POST", "/api/camera", json.dumps({"eye": [0, 1, 9], "target": [0, 1, 0]})),
                 ("POST", "/api/options", json.dumps(["--spp", "3"]))]
    wrong = {"no token": False, "no token (empty)": "", "wrong token": token[:-1] + ("0" if token[-1] != "0" else "1"),
             "wrong token (short)": token[:16], "wrong token (long)": token + "0"}
    before = state()
    for method, path, body in endpoints:
        for what, sent in wrong.items():
            status, headers, got = ask(method, path, body, token=sent)
            check(refused(status, got, 403, what.split(" (")[0] + ": open the address the explorer printed"),
                  f"{method} {path} with {what}: {status} {error_of(got)!r}")
            check(headers.get("X-Content-Type-Options") == "nosniff", f"{method} {path}: nosniff on a refusal")
    after = state()
    check(after["camera"] == before["camera"] and after["options"] == before["options"],
          "nothing sent without the right token changed anything")
    check(ask("GET", "/api/state", token=token.upper())[0] == (200 if token == token.upper() else 403),
          "the token is compared as it is")

    # Host: only this server's names, with its port; anything else even with the token.
    other_port = port + 1 if port < 65535 else port - 1
    for host in (f"evil.example:{port}", f"127.0.0.1:{other_port}", f"localhost:{other_port}", "127.0.0.1",
                 f"127.0.0.1.evil.example:{port}", f"localhost.:{port}", f"[::1]:{other_port}", None):
        status, _, got = ask("GET", "/api/state", host=host)
        check(refused(status, got, 403, "Host" if host else "no Host header"), f"Host {host!r}: {status} {error_of(got)!r}")
        status, _, got = ask("GET", "/", host=host, token=False)
        check(status == 403, f"Host {host!r} is refused the page too: {status}")
    for host in (f"127.0.0.1:{port}", f"localhost:{port}", f"[::1]:{port}", f"LocalHost:{port}"):
        check(ask("GET", "/api/state", host=host)[0] == 200, f"Host {host!r} is served")
    status, _, got = ask("GET", "/api/state", headers={"Host": f"127.0.0.1:{port}"}, host=f"127.0.0.1:{port}")
    check(refused(status, got, 400, "more than one Host header"), f"two Host headers are refused: {status}")

    # Origin: a foreign one on each POST changes nothing.
    before = state()
    for method, path, body in endpoints:
        if method != "POST":
            continue
        for origin in ("http://evil.example", f"http://evil.example:{port}", f"http://127.0.0.1:{other_port}",
                       f"https://127.0.0.1:{port}", "null"):
            status, _, got = ask(method, path, body, headers={"Origin": origin})
            check(refused(status, got, 403, f"Origin '{origin}' is not this explorer's page"),
                  f"POST {path} from {origin}: {status} {error_of(got)!r}")
    after = state()
    check(after["camera"] == before["camera"] and after["options"] == before["options"] and
          after["text"] == before["text"], "no POST from another origin changed anything")
    for origin in (f"http://127.0.0.1:{port}", f"http://localhost:{port}", f"http://[::1]:{port}"):
        status, _, got = ask("POST", "/api/options", json.dumps(list(map(str, SIZE))), headers={"Origin": origin})
        check(status == 200, f"a POST from the page's own origin {origin} is taken: {status} {got!r}")
    # A preflight, as a page of another site would send before a POST with the token header.
    status, headers, _ = ask("OPTIONS", "/api/scene", token=False,
                             headers={"Origin": "http://evil.example", "Access-Control-Request-Method": "POST",
                                      "Access-Control-Request-Headers": "x-rtlab-token"})
    check(status == 403, f"a preflight from another site is refused: {status}")

    # The page cannot widen what it may do.
    for args in (["--allow", "/"], ["--allow=/"], ["--no-token"]):
        status, _, got = ask("POST", "/api/options", json.dumps(args))
        check(refused(status, got, 400, "is the command line's"), f"{args} from the page: {status} {error_of(got)!r}")

    # Bodies: the size is known before a byte of the body is read. The body is never sent here:
    # the answer comes at once, not after the server's 5 s read timeout (the socket's timeout,
    # 4 s, would end the wait first).
    def raw(extra):
        with socket.create_connection(("127.0.0.1", port), timeout=4) as s:
            s.sendall(f"POST /api/scene HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nX-Rtlab-Token: {token}\r\n{extra}\r\n"
                      .encode())
            answer = b""
            try:
                while chunk := s.recv(65536):
                    answer += chunk
            except socket.timeout:
                return answer, False
            return answer, True  # and the server closed the connection

    limit = 16 << 20
    for extra, status, words in ((f"Content-Length: {limit + 1}\r\n", 413, f"not {limit + 1}"),
                                 (f"Content-Length: {limit + 1}\r\nExpect: 100-continue\r\n", 413, "refused before it is read"),
                                 ("Content-Length: 99999999999999999999999\r\n", 413, "refused before it is read"),
                                 ("Transfer-Encoding: chunked\r\n", 411, "chunked bodies are refused"),
                                 ("Content-Length: 12x\r\n", 400, "is not a whole number")):
        answer, closed = raw(extra)
        head, _, body = answer.partition(b"\r\n\r\n")
        check(head.startswith(f"HTTP/1.1 {status} ".encode()) and words in error_of(body) and closed,
              f"{extra.strip()!r}: {head[:40]!r} {body[:160]!r}, closed: {closed}")
    answer, _ = raw("Content-Length: 5\r\nExpect: 100-continue\r\n")
    check(answer.startswith(b"HTTP/1.1 100 Continue"), "a body within the limit is asked for")

    # Meshes: only under the chapter's scenes, ../shared/assets and --allow's folder.
    scene_dir = SCENE.parent

    def mesh_scene(file):
        text = json.loads(SCENE.read_text())
        text["surfaces"].append({"type": "mesh", "name": "posted", "file": str(file), "material": "red"})
        return json.dumps(text, indent=1)

    opens = Opens(secret, outside)
    check(opens.watching, "inotify watches the secret")
    refusals = {}
    for what, name in (("absolute", secret), ("..", os.path.relpath(secret, scene_dir)),
                       ("a link that leads out", link), ("a link that leads out, relative", os.path.relpath(link, scene_dir)),
                       ("the root", "/etc/passwd"), ("many ..", "../" * 40 + "etc/passwd"),
                       ("not there", outside / "missing.obj"), ("past a real file", allowed / "tri.obj/../../outside/secret.obj")):
        status, _, got = ask("POST", "/api/scene", mesh_scene(name))
        message = error_of(got)
        check(status == 400 and f"/file: '{name}' is refused: this scene may only name files under " in message and
              "--allow DIR" in message and "\n" not in message, f"a mesh {what}: {status} {message!r}")
        check("zz_secret" not in message and "vertex" not in message, f"a mesh {what}: no byte of the file is quoted")
        refusals[what] = message.replace(f"'{name}'", "NAME")
    check(len(set(refusals.values())) == 1, f"the same line whether or not the file is there: {set(refusals.values())}")
    check(opens.count() == 0, "no refused mesh was opened, nor its folder")
    folders = str(scene_dir.resolve()), str(allowed.resolve())
    check(all(f in next(iter(refusals.values())) for f in folders), f"the line names the folders allowed: {folders}")
    check(state()["text"] == SCENE.read_text(), "a refused scene is not taken")
    allowed_opens = Opens(allowed / "tri.obj")
    for name in (allowed / "tri.obj", os.path.relpath(allowed / "tri.obj", scene_dir)):
        status, _, got = ask("POST", "/api/scene", mesh_scene(name))
        check(status == 200, f"a mesh under --allow's folder ({name}) is loaded: {status} {error_of(got)!r}")
    check(allowed_opens.count() > 0, "and opened (the watch sees opens)")

    # Names that are markup are text: escaped in the SVG, which runs nothing.
    name = '<script>alert("rtlab")</script>"onload="alert(1)'
    ball = ball_scene(name)
    check(ask("POST", "/api/scene", json.dumps(ball))[0] == 200, "a surface named with markup is taken")
    status, _, got = ask("GET", "/api/pick?x=32&y=18")
    check(status == 200 and json.loads(got)["surface"] == name, f"the pick names it as it is: {got[:200]!r}")
    status, headers, svg = ask("GET", "/api/tree.svg?x=32&y=18")
    text = svg.decode("utf-8", "replace")
    check(status == 200 and headers.get("Content-Type") == "image/svg+xml", f"the side view: {status}")
    check("&lt;script&gt;alert(&quot;rtlab&quot;)&lt;/script&gt;&quot;onload=&quot;alert(1)" in text,
          "the name is escaped in the SVG")
    check("<script" not in text and '"onload=' not in text, "no markup of the name is left in the SVG")
    try:
        elements = list(ElementTree.fromstring(svg).iter())
    except ElementTree.ParseError as e:
        elements = []
        check(False, f"the SVG is well-formed XML: {e}")
    check(elements and not any(e.tag.split("}")[-1].lower() in ("script", "foreignobject") for e in elements),
          "the SVG has no script element")
    check(elements and not any(k.lower().startswith("on") for e in elements for k in e.attrib),
          "and no event attribute")
    policy = headers.get("Content-Security-Policy", "")
    check("default-src 'none'" in policy and "sandbox" in policy and "script-src" not in policy,
          f"the SVG is sent with a policy under which nothing runs: {policy!r}")
    check(headers.get("X-Content-Type-Options") == "nosniff", "and nosniff")
    check(not cors, f"no answer has a CORS header: {sorted(set(cors))}")
    check(server.process.poll() is None and ask("GET", "/api/state")[0] == 200, "the server still answers")
finally:
    server.stop()

# --no-token: for tests only, and it says so; pages of other sites are still refused.
server = Explorer(ch07, "--scene", SCENE, *SIZE, "--no-token")
try:
    check(server.url == f"http://127.0.0.1:{server.port}/", f"--no-token prints no token: {server.line!r}")
    check(server.request("GET", "/api/state")[0] == 200, "--no-token: served without a token")
    check(server.request("GET", "/api/state", host=f"evil.example:{server.port}")[0] == 403, "--no-token: Host checked")
    check(server.request("POST", "/api/options", "[]", headers={"Origin": "http://evil.example"})[0] == 403,
          "--no-token: Origin checked")
finally:
    said = server.stop()
check("--no-token: any program on this machine may drive this explorer (for tests only)" in said,
      f"--no-token is said on the terminal: {said!r}")

finish("explore_gate")
