#!/usr/bin/env python3
"""The explorer's page in a real browser: Debian's chromium, headless, through selenium.

  explore_browser_test.py ROOT BIN_DIR WORK_DIR

Serves ch07's mirrors, loads the page, waits until the view has converged, clicks a pixel
with the mouse and checks that the panel shows the numbers `ch07 --pick X,Y` prints and one
line per ray of its tree, with the SVG side view and the rays drawn in 3D; drags the view and
checks a new frame comes; applies a broken scene file and checks the loader's line is shown;
applies a scene whose surface is named with markup (<script>, "onload=, an <img> whose onerror
would leave a mark) and checks the page shows the name as text and ran none of it; and opened
without its token, the page says why it cannot start. Saves WORK_DIR/explore.png, a screenshot.
"""
import json
import pathlib
import subprocess
import sys
import time

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By

sys.path.insert(0, str(pathlib.Path(__file__).parent))
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "tools"))
from checks import check, finish  # noqa: E402
from explore_client import ball_scene  # noqa: E402
from chromium import browser, wait_for  # noqa: E402

root, bin_dir, work = (pathlib.Path(a).resolve() for a in sys.argv[1:4])
work.mkdir(parents=True, exist_ok=True)
ch07 = str(bin_dir / "ch07")
W, H = 320, 180
SCENE = root / "chapters/ch07_specular_reflection/scenes/mirrors.json"
size = ["--width", str(W), "--height", str(H)]


def numbers(text):
    """'(1, 2.5, -3)' or '4.25' as a list of floats."""
    return [float(v) for v in text.strip("()").split(",")]


server = subprocess.Popen([ch07, "--explore", "--scene", str(SCENE), *size, "--spp", "4"],
                          stdout=subprocess.PIPE, text=True)
url = server.stdout.readline().split(" at ")[1].split()[0]  # with ?token=...
driver = None
try:
    driver = browser()
    driver.get(url)
    f = wait_for(driver, "const f = window.rtlab.frame; return f && f.samples === f.target && f.width === %d && f" % W)
    check(f is not None, "the view converges to its samples")
    check(driver.find_element(By.ID, "chapter").text.startswith("ch07"), "the page names the chapter")
    build = driver.find_element(By.ID, "build").text
    check("exercises" in build, f"the page says whose exercises run: {build!r}")

    # Click a pixel: 60 right of and 30 above the view's centre.
    canvas = driver.find_element(By.ID, "frame")
    ActionChains(driver).move_to_element_with_offset(canvas, 60, -30).click().perform()
    picked = wait_for(driver, "return window.rtlab.pick", 60)
    check(picked is not None, "the click is answered")
    x, y = picked["pixel"] if picked else (W // 2 + 60, H // 2 - 30)
    check(abs(x - (W // 2 + 60)) <= 1 and abs(y - (H // 2 - 30)) <= 1, f"the clicked pixel is the one under the mouse: {x},{y}")
    cli = json.loads(subprocess.run([ch07, "--scene", str(SCENE), *size, "--pick", f"{x},{y}"], check=True,
                                    capture_output=True, text=True).stdout)
    shown = {td.get_attribute("id"): td.text for td in driver.find_elements(By.CSS_SELECTOR, "#pick-table td[id]")}
    check(shown.get("pick-surface") == cli["surface"], f"surface {shown.get('pick-surface')!r} is --pick's {cli['surface']!r}")
    for key in ("t", "point", "normal", "color"):
        cell = shown.get("pick-colour" if key == "color" else f"pick-{key}", "")
        want = cli[key] if isinstance(cli[key], list) else [cli[key]]
        check(cell and numbers(cell) == want, f"{key}: the panel shows {cell!r}, --pick prints {want}")

    def count(node):
        return 1 + sum(count(c) for c in node.get("children", []))

    rays = driver.find_elements(By.CSS_SELECTOR, "#tree li")
    check(len(rays) == count(cli["tree"]) and len(rays) > 2, f"one line per ray of the tree: {len(rays)}")
    check(rays and rays[0].text.startswith("camera") and cli["surface"] in rays[0].text, "the first is the camera ray")
    check(wait_for(driver, "const i = document.querySelector('#svg img'); return i && i.complete && i.naturalWidth > 0", 30),
          "the SVG side view is shown")
    check(driver.execute_script("return window.rtlab.raysDrawn") == len(rays), "every ray is drawn in 3D")
    latency = driver.execute_script("return window.rtlab.clickLatencies[0]")
    print(f"click to ray tree: {latency:.0f} ms")

    # Drag: the camera orbits, the next frame is of a new generation.
    generation = driver.execute_script("return window.rtlab.generation")
    ActionChains(driver).move_to_element(canvas).click_and_hold().move_by_offset(30, 0).move_by_offset(30, 5) \
        .release().perform()
    moved = wait_for(driver, f"return window.rtlab.generation > {generation} && window.rtlab.moveLatencies.length", 60)
    check(moved, "a drag moves the camera and a new frame is shown")
    camera = driver.execute_script("return window.rtlab.api('/api/state').then(r => r.json()).then(s => s.camera)")
    check(camera["eye"] != [-1.4, 1.7, 3.4], f"the server's camera moved: {camera['eye']}")

    # The controls: an option the parser refuses shows its line; a shading goes into the file.
    # Each control is set and its change event fired in one script: the page rebuilds its
    # selects' options whenever the server's state comes back, so an option element found
    # first and clicked after can be gone by then (selenium's StaleElementReferenceException,
    # seen once in CI under ASan).
    def set_field(key, value):  # as typed or chosen, then left: one change event
        driver.execute_script("const e = document.getElementById(arguments[0]); e.value = arguments[1];"
                              "e.dispatchEvent(new Event('change'))", key, value)

    set_field("pattern", "jittered")
    check(driver.execute_script("return document.getElementById('pattern').value") == "jittered",
          "the pattern control offers jittered")
    set_field("spp", "3")
    refused = wait_for(driver, "const e = document.getElementById('error').textContent; return e.includes('n x n') && e", 30)
    check(refused, f"--spp 3 with the jittered pattern is refused in the page: {refused!r}")
    set_field("spp", "4")
    check(wait_for(driver, "return document.getElementById('error').textContent === ''", 30), "--spp 4 is taken")
    generation = driver.execute_script("return window.rtlab.generation")
    set_field("shading", "cost")
    check(wait_for(driver, f"return window.rtlab.generation > {generation}", 60), "a shading change renders")
    # The text is rewritten when the server has taken the scene, which can be after the first
    # frame of it is shown: wait for it, or the edit below could be overwritten by it.
    check(wait_for(driver, "return document.getElementById('text').value.includes('\"shading\": \"cost\"')", 30),
          "and is in the scene file")

    # A broken scene file: the loader's line, and the view keeps the last good scene.
    driver.execute_script("document.getElementById('text').value = "
                          "document.getElementById('text').value.replace('\"max_depth\": 8', '\"max_depth\": -1')")
    driver.find_element(By.ID, "apply").click()
    message = wait_for(driver, "return document.getElementById('scene-error').textContent", 30) or ""
    check(message.startswith(str(SCENE) + ":") and "/max_depth: " in message, f"the loader's line is shown: {message!r}")

    # A name that is markup is shown as text, and runs nothing.
    name = '<script>window.rtlabRan = 1</script>"onload="window.rtlabRan = 2"<img src=x onerror="window.rtlabRan = 3">'
    ball = ball_scene(name)
    scripts = driver.execute_script("return document.scripts.length")
    driver.execute_script("document.getElementById('text').value = arguments[0]", json.dumps(ball, indent=1))
    driver.find_element(By.ID, "apply").click()
    check(wait_for(driver, "return document.getElementById('scene-error').textContent === '' && "
                           "window.rtlab.state.text.includes('rtlabRan')", 30), "the scene with a markup name is taken")
    driver.execute_script("window.rtlab.pick = null")
    ActionChains(driver).move_to_element(canvas).click().perform()
    check(wait_for(driver, "return window.rtlab.pick", 60), "a click on it is answered")
    shown = driver.execute_script("return document.getElementById('pick-surface').textContent")
    check(shown == name, f"the name is shown as it is, as text: {shown!r}")
    check(driver.find_elements(By.CSS_SELECTOR, "#tree li") and name in driver.find_elements(By.CSS_SELECTOR, "#tree li")[0].text,
          "and in the ray tree's first line")
    check(wait_for(driver, "const i = document.querySelector('#svg img'); return i && i.complete && i.naturalWidth > 0", 30),
          "its side view is shown")
    check(driver.execute_script("return document.scripts.length") == scripts and
          not driver.find_elements(By.CSS_SELECTOR, "#pick-table *:not(tr, td, tbody), #tree li *, [onload], [onerror]"),
          "no element was made of the name")
    time.sleep(0.5)
    check(driver.execute_script("return window.rtlabRan") is None, "and none of it ran")

    time.sleep(0.5)
    driver.save_screenshot(str(work / "explore.png"))
    # (Besides the refusals asked for above: their 400s are logged as failed loads.)
    def asked_for(m):
        return ("/api/scene" in m or "/api/options" in m) and "(Bad Request)" in m

    logs = [e["message"] for e in driver.get_log("browser") if e["level"] == "SEVERE" and not asked_for(e["message"])]
    check(not logs, f"no errors in the browser's console (a script or style the page's policy refused would be one): "
                    f"{logs[:3]}")

    # Without its token the page cannot start, and says why.
    driver.get(url.split("?")[0])
    said = wait_for(driver, "return document.getElementById('error').textContent", 30) or ""
    check("no token" in said and "open the address the explorer printed" in said, f"without the token: {said!r}")
finally:
    if driver:
        driver.quit()
    server.terminate()
    server.wait(30)

finish("explore_browser")
