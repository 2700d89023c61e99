#!/usr/bin/env python3
"""The page in a real browser (headless Chromium from Debian's packages, driven by selenium):
it loads from file:// with no console error; the tactile dome gives `bounce-table eval`'s
bounce; a Rigol trace, and the shared capture where it is present, give the CLI's calibrate
(and replay) text; bad input shows its message at the field.
Screenshots go to the directory given (docs/png).

    python3 web/tests/browser.py docs/png
"""
import json
import os
import subprocess
import sys

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.path.join(ROOT, "target", "release", "bounce-table")
SHOTS = sys.argv[1] if len(sys.argv) > 1 else None


def cli(*args, stdin=None):
    return subprocess.run([BIN, *args], input=stdin, capture_output=True, text=True, check=True).stdout


def main():
    options = webdriver.ChromeOptions()
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=1200,1400"):
        options.add_argument(a)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    # Debian's browser and driver: nothing downloaded.
    options.binary_location = "/usr/bin/chromium"
    driver = webdriver.Chrome(options=options, service=Service("/usr/bin/chromedriver"))
    try:
        driver.get("file://" + os.path.join(ROOT, "web", "index.html"))
        wait = WebDriverWait(driver, 30)
        wait.until(lambda d: len(d.find_elements(By.CSS_SELECTOR, "#tiers tbody tr")) == 5)
        # The dome: the exact tier's bounce as `bounce-table eval --method exact-tier` prints it.
        dome = [l for l in open(os.path.join(ROOT, "bounce-table/scenes/catalogue.jsonl")) if "tactile dome" in l][0]
        want = json.loads(cli("eval", "--method", "exact-tier", stdin=dome))["end_time"]
        first = driver.find_elements(By.CSS_SELECTOR, "#tiers tbody tr")[0].find_elements(By.TAG_NAME, "td")
        shown = first[1].text
        expect = f"{want * 1e6:.2f} us" if want < 1e-3 else f"{want * 1e3:.3f} ms"
        assert first[0].text == "exact-tier" and shown == expect, (shown, expect)
        if SHOTS:
            driver.save_screenshot(os.path.join(SHOTS, "web-calculator.png"))
        # Bad input: the message at the field.
        scene = driver.find_element(By.ID, "scene")
        scene.clear()
        scene.send_keys('{"name": "x", "mass": -1, "stiffness": 5000, "preload_force": 1, "restitution": 0.7, "closing_speed": 0.5}')
        wait.until(lambda d: d.find_element(By.ID, "scene-error").text != "")
        error = driver.find_element(By.ID, "scene-error").text
        assert error.startswith("mass"), error
        # A Rigol export: calibrate's text, as the CLI prints it.
        driver.find_element(By.ID, "tab-capture").click()
        rigol = os.path.join(ROOT, "bounce-table/tests/fixtures/scope/rigol.csv")
        driver.find_element(By.ID, "file").send_keys(rigol)
        wait.until(lambda d: d.find_element(By.ID, "calibrate").text != "")
        page = driver.find_element(By.ID, "calibrate").get_attribute("textContent")
        text = cli("calibrate", rigol)
        assert page.strip() == text.strip(), "calibrate differs"
        assert len(driver.find_elements(By.CSS_SELECTOR, "#plot svg")) == 6
        if SHOTS:
            driver.save_screenshot(os.path.join(SHOTS, "web-capture.png"))
        # The shared capture (where it is present): calibrate's and replay's text, as the CLI's.
        shared = os.path.join(ROOT, "..", "shared", "data", "bouncy-button-uno.jsonl")
        if os.path.exists(shared):
            driver.execute_script("document.getElementById('calibrate').textContent = ''")
            driver.find_element(By.ID, "file").send_keys(os.path.abspath(shared))
            WebDriverWait(driver, 300).until(lambda d: d.find_element(By.ID, "calibrate").text != "")
            for command in ("calibrate", "replay"):
                page = driver.find_element(By.ID, command).get_attribute("textContent")
                assert page.strip() == cli(command, shared).strip(), f"{command} differs on the shared capture"
        errors = [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
        assert not errors, errors
        print("web: the page loads with no console error, gives eval's bounce for the dome, the CLI's calibrate text for a Rigol trace (and calibrate's and replay's for the shared capture where present), and the field's message for bad input")
    finally:
        driver.quit()


if __name__ == "__main__":
    main()
