#!/usr/bin/env python3
"""The explorer's frame rate and latency, as a browser shows them (./lab bench explore).

  bench/explore_bench.py BIN_DIR SCREENSHOT.png

For each scene, ch07 --explore serves it at 640x360 on 2 threads and Debian's chromium
(headless, through selenium; composited in software and WebGL on SwiftShader, as
tools/chromium.py says why) loads the page and counts the frames it actually draws:
  moving    the camera orbits a little every 16 ms for 4 s: every frame is a first frame
            after a move, one sample per pixel (smaller while a full pass is too slow)
  refining  the camera still for 3 s: a sample per pixel per frame
  move      a single orbit step, then the time until the first frame made after it is
            drawn (median and worst of 15)
  click     a pixel picked, then the time until its ray tree is drawn (median and worst of 10)
and where a refining frame's time goes: render (render() itself), pass (all the render
thread's time between two frames: render() and what it does around it; the frame interval
while refining), finish (the pass added into the running sum and made 8-bit sRGB, on a
second thread while the next pass renders), encode (the frame into the format sent),
transfer (its bytes, from the response's headers to its last byte) and draw (into the
canvas). All but render and pass overlap the next pass: they slow it only by taking a share
of the 2 cores. Then the four formats a frame can travel in, for the bunny.
Scenes: the Stanford bunny (69,451 triangles, from ../shared/assets: never copied into the
lab) with normal shading, and Whitted with one light; bench/scenes/spheres488.json (the
layout of Ray Tracing in One Weekend's cover: a grid of small spheres, three large ones, a
ground sphere) with Whitted shading and its two lights. Last, a screenshot of ch07's
mirrors with a picked pixel's ray tree: SCREENSHOT.
"""
import json
import os
import pathlib
import statistics
import subprocess
import sys
import time

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By

root = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(root / "tools"))
from chromium import browser  # noqa: E402
from chromium import wait_for as wait_or_none  # noqa: E402

bin_dir, screenshot = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
work = root / "out/bench/explore"
work.mkdir(parents=True, exist_ok=True)
bunny_obj = (root / "../shared/assets/meshes/stanford-bunny.obj").resolve()
SIZE = ["--width", "640", "--height", "360", "--threads", "2"]


def bunny_scene(shading):
    scene = {
        "description": f"The Stanford bunny, {shading} (bench/explore_bench.py)",
        "camera": {"eye": [0.1, 0.95, 3.3], "target": [-0.15, 0.75, 0], "fov": 32},
        "shading": shading,
        "background": [0.55, 0.7, 0.9],
        "ambient": [0.1, 0.1, 0.1],
        "materials": {"clay": {"diffuse": [0.8, 0.6, 0.45], "specular": [0.3, 0.3, 0.3], "exponent": 40}},
        "lights": [{"type": "point", "position": [3, 5, 4], "color": [1, 1, 1]}],
        "surfaces": [{"type": "mesh", "file": str(bunny_obj), "scale": 10, "translate": [0, -0.3, 0],
                      "material": "clay"}],
    }
    path = work / f"bunny-{shading}.json"
    path.write_text(json.dumps(scene, indent=1))
    return path


def spheres_whitted():
    scene = json.loads((root / "bench/scenes/spheres488.json").read_text())
    scene["shading"] = "whitted"
    path = work / "spheres488-whitted.json"
    path.write_text(json.dumps(scene))
    return path


def serve(scene, *args):
    """The server, and the address it prints: the page's, with the session's token."""
    p = subprocess.Popen([str(bin_dir / "ch07"), "--explore", "--scene", str(scene), *SIZE, *args],
                         stdout=subprocess.PIPE, text=True)
    return p, p.stdout.readline().split(" at ")[1].split()[0]


def wait_for(driver, script, seconds=60):
    value = wait_or_none(driver, script, seconds, poll=0.05)
    if not value:
        raise RuntimeError(f"timed out waiting for: {script}")
    return value


# Every frame the page draws, kept in the page: what a frame cost, where.
RECORD = """
window.benchFrames = [];
let last = 0;
(function watch() {
  const f = window.rtlab.frame;
  if (f && f.id !== last) { last = f.id; window.benchFrames.push(f); }
  requestAnimationFrame(watch);
})();
"""


def frames_over(driver, seconds, during=None):
    """Frames drawn in `seconds`, and the frames' records."""
    start = driver.execute_script("return window.rtlab.framesDrawn")
    driver.execute_script("window.benchFrames = window.benchFrames || []; window.benchFrames.length = 0;")
    if during:
        driver.execute_script(during)
    time.sleep(seconds)
    end = driver.execute_script("return window.rtlab.framesDrawn")
    records = driver.execute_script("return window.benchFrames.slice()")
    return (end - start) / seconds, records


def mean(records, key):
    return statistics.fmean(r[key] for r in records) if records else float("nan")


def measure(driver, url):
    driver.get(url)
    wait_for(driver, "const f = window.rtlab.frame; return f && f.width === 640")
    driver.execute_script(RECORD)
    # Moving: a small orbit every 16 ms (a mouse drag sends about that many).
    moving, moving_records = frames_over(driver, 4, "window.benchOrbit = setInterval(() => orbit(3, 0), 16)")
    driver.execute_script("clearInterval(window.benchOrbit)")
    full = sum(r["width"] == 640 for r in moving_records) / 4
    time.sleep(0.5)
    refining, records = frames_over(driver, 3)
    # Single moves, apart.
    driver.execute_script("window.rtlab.moveLatencies.length = 0")
    for _ in range(15):
        driver.execute_script("orbit(4, 0)")
        time.sleep(0.4)
    moves = driver.execute_script("return window.rtlab.moveLatencies.slice()")
    # Clicks.
    driver.execute_script("window.rtlab.clickLatencies.length = 0")
    for k in range(10):
        driver.execute_script(f"pickPixel({200 + 20 * k}, {150 + 5 * k})")
        time.sleep(0.4)
    clicks = driver.execute_script("return window.rtlab.clickLatencies.slice()")
    return {
        "moving": moving, "moving_full": full, "refining": refining,
        "mrays": mean(records, "mrays"), "render": mean(records, "renderMs"), "pass": mean(records, "passMs"),
        "finish": mean(records, "finishMs"), "encode": mean(records, "encodeMs"),
        "transfer": mean(records, "transferMs"), "draw": mean(records, "drawMs"), "bytes": mean(records, "bytes"),
        "move_median": statistics.median(moves) if moves else float("nan"), "move_worst": max(moves, default=float("nan")),
        "moves": len(moves),
        "click_median": statistics.median(clicks) if clicks else float("nan"),
        "click_worst": max(clicks, default=float("nan")),
    }


def load():
    return os.getloadavg()[0]


cases = []
if bunny_obj.is_file():
    cases += [("bunny, normal", bunny_scene("normal"), []), ("bunny, whitted 1 light", bunny_scene("whitted"), [])]
else:
    print(f"(no {bunny_obj}: the bunny's rows are left out)")
cases.append(("spheres488, whitted", spheres_whitted(), []))

driver = browser()
results = []
try:
    for name, scene, args in cases:
        server, url = serve(scene, "--spp", "4096", *args)
        try:
            results.append((name, measure(driver, url), load()))
        finally:
            server.terminate()
            server.wait(30)
    formats = []
    if bunny_obj.is_file():
        server, url = serve(bunny_scene("normal"), "--spp", "4096")
        try:
            for fmt in ("rgba", "rgb", "png", "jpeg"):
                driver.get(url + f"&format={fmt}")  # after ?token=...
                wait_for(driver, "const f = window.rtlab.frame; return f && f.width === 640")
                driver.execute_script(RECORD)
                time.sleep(0.5)
                fps, records = frames_over(driver, 3)
                formats.append((fmt, fps, records))
        finally:
            server.terminate()
            server.wait(30)

    # The screenshot: ch07's mirrors, converged, a pixel picked.
    server, url = serve(root / "chapters/ch07_specular_reflection/scenes/mirrors.json", "--spp", "16")
    try:
        driver.get(url)
        wait_for(driver, "const f = window.rtlab.frame; return f && f.width === 640 && f.samples === f.target", 120)
        canvas = driver.find_element(By.ID, "frame")
        ActionChains(driver).move_to_element_with_offset(canvas, 120, -60).click().perform()
        wait_for(driver, "return window.rtlab.pick")
        time.sleep(0.5)
        driver.save_screenshot(str(screenshot))
    finally:
        server.terminate()
        server.wait(30)
finally:
    driver.quit()

print("640x360, 2 render threads; frames counted as headless chromium drew them;")
print("frames sent as raw RGB (the formats: last table). The machine was shared:")
print("its load average while measuring is the last column. Targets: moving >= 30 fps")
print("(normal) and >= 15 (whitted); move <= 50 ms; click <= 100 ms.")
print()
print(f"{'scene':24} {'moving':>7} {'(full)':>7} {'refine':>7} {'Mrays/s':>8} {'move ms':>13} {'click ms':>13} {'load':>5}")
print(f"{'':24} {'fps':>7} {'fps':>7} {'fps':>7} {'':>8} {'median/worst':>13} {'median/worst':>13} {'':>5}")
for name, r, load_average in results:
    print(f"{name:24} {r['moving']:7.1f} {r['moving_full']:7.1f} {r['refining']:7.1f} {r['mrays']:8.1f} "
          f"{r['move_median']:6.0f}/{r['move_worst']:<6.0f} {r['click_median']:6.0f}/{r['click_worst']:<6.0f} {load_average:5.1f}")
print()
print("Where a refining frame's time goes (mean ms per frame):")
print(f"{'scene':24} {'render':>7} {'pass':>7} {'finish':>7} {'encode':>7} {'transfer':>9} {'draw':>6}")
for name, r, _ in results:
    print(f"{name:24} {r['render']:7.1f} {r['pass']:7.1f} {r['finish']:7.2f} {r['encode']:7.2f} {r['transfer']:9.2f} "
          f"{r['draw']:6.2f}")
if formats:
    print()
    print("The formats, bunny normal, refining (mean per frame):")
    print(f"{'format':8} {'fps':>6} {'bytes':>9} {'encode ms':>10} {'transfer ms':>12} {'draw ms':>8}")
    for fmt, fps, records in formats:
        print(f"{fmt:8} {fps:6.1f} {mean(records, 'bytes'):9.0f} {mean(records, 'encodeMs'):10.2f} "
              f"{mean(records, 'transferMs'):12.2f} {mean(records, 'drawMs'):8.2f}")
