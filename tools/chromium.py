"""Debian's chromium, headless, through selenium (python3-selenium, chromium-driver): the
browser that tests/explore_browser_test.py and bench/explore_bench.py drive the explorer's
page in.
"""
import time

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service


def browser():
    """A headless chromium. There is no GPU here: WebGL (the ray tree's 3D view, three.js) runs
    on SwiftShader, a GPU emulated on the CPU, and the page is composited in software, as
    chromium does on a machine without a usable GPU (composited through SwiftShader, each
    frame of the explorer cost the 2 cores about 30 ms more: ./lab bench explore measured
    about 45 ms of chromium's CPU per frame drawn, 30 of them in its GPU process, against
    about 15 without). No sandbox (it may run as root in a container) and no /dev/shm
    (small in containers)."""
    options = Options()
    for a in ("--headless=new", "--no-sandbox", "--window-size=1300,1000", "--use-angle=swiftshader",
              "--enable-unsafe-swiftshader", "--disable-gpu-compositing", "--disable-dev-shm-usage"):
        options.add_argument(a)
    options.binary_location = "/usr/bin/chromium"
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


def wait_for(driver, script, seconds=120, poll=0.1):
    """The value of the page's `script` once it is truthy, or None after `seconds`."""
    deadline = time.time() + seconds
    while time.time() < deadline:
        value = driver.execute_script(script)
        if value:
            return value
        time.sleep(poll)
    return None
