#!/usr/bin/env python3
"""The page in a real browser (headless Chromium from Debian's packages, driven by selenium):
it loads from file:// with no console error; the tactile dome gives `bounce-table eval`'s
bounce, and the table mode's window, constants and envelope; a Rigol trace, and the shared
capture where it is present, give the CLI's calibrate, replay and tap texts (with the Pareto
plots); a 10 MB capture is analysed in a worker while the page answers; bad input shows its
message at the field.
Screenshots go to the directory given (docs/png).

    python3 web/tests/browser.py docs/png
"""
import json
import os
import subprocess
import sys
import tempfile
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.path.join(ROOT, "target", "release", "bounce-table")
SHOTS = sys.argv[1] if len(sys.argv) > 1 else None


def cli(*args, stdin=None, cwd=None):
    return subprocess.run([BIN, *args], input=stdin, capture_output=True, text=True, check=True, cwd=cwd).stdout


def choose(driver, *paths):
    """Chooses these files in the capture's file input, and only these (the input takes
    several files, and the driver adds to what was chosen before), calibrate's text cleared."""
    driver.execute_script("document.getElementById('calibrate').textContent = ''; document.getElementById('file').value = ''")
    driver.find_element(By.ID, "file").send_keys("\n".join(paths))


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
        # Its window in ticks and its firmware constants, as the table mode prints them for a
        # file of that one line named as the page names it (scenes.jsonl).
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "scenes.jsonl"), "w") as f:
                f.write(dome)
            table = cli("scenes.jsonl", cwd=tmp)
            header = cli("--format", "c", "scenes.jsonl", cwd=tmp)
        wait.until(lambda d: d.find_element(By.ID, "constants").text != "")
        assert driver.find_element(By.ID, "window").get_attribute("textContent").strip() == table.strip(), "window differs"
        assert driver.find_element(By.ID, "constants").get_attribute("textContent").strip() == header.strip(), "constants differ"
        # A period the CLI refuses: its message, at the window's fields.
        period = driver.find_element(By.ID, "period")
        period.clear()
        period.send_keys("0")
        driver.execute_script("document.getElementById('period').onchange()")
        wait.until(lambda d: d.find_element(By.ID, "window-error").text != "")
        refusal = driver.find_element(By.ID, "window-error").text
        assert "'--sample-period <SECONDS>': not a positive number" in refusal, refusal
        period.clear()
        period.send_keys("0.0001")
        driver.execute_script("document.getElementById('period').onchange()")
        wait.until(lambda d: d.find_element(By.ID, "window-error").text == "" and d.find_element(By.ID, "constants").text != "")
        envelope = driver.find_element(By.CSS_SELECTOR, "#envelope svg").get_attribute("outerHTML")
        assert "generating impulse J(t)" in envelope and "exact impacts" in envelope and "window" in envelope, envelope[:300]
        if SHOTS:
            driver.execute_script("document.getElementById('window').scrollIntoView()")
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
        choose(driver, rigol)
        wait.until(lambda d: d.find_element(By.ID, "calibrate").text != "")
        page = driver.find_element(By.ID, "calibrate").get_attribute("textContent")
        text = cli("calibrate", rigol)
        assert page.strip() == text.strip(), "calibrate differs"
        # Every acquisition, six at a time.
        assert len(driver.find_elements(By.CSS_SELECTOR, "#plot svg")) == 6
        acquisitions = open(rigol).read().count("X,CH1,")
        assert driver.find_element(By.ID, "pager").text == f"tests 1-6 of {acquisitions}", driver.find_element(By.ID, "pager").text
        driver.find_element(By.ID, "pager-next").click()
        assert driver.find_element(By.ID, "pager").text == f"tests 7-12 of {acquisitions}"
        assert "acquisition 7 " in driver.find_element(By.CSS_SELECTOR, "#plot svg").text
        driver.find_element(By.ID, "pager-previous").click()
        # Replay on isolated presses and on taps with human timing, with their Pareto plots.
        wait.until(lambda d: d.find_element(By.ID, "taps").text != "")
        for element, args in (("replay", ()), ("taps", ("--taps",))):
            page = driver.find_element(By.ID, element).get_attribute("textContent")
            assert page.strip() == cli("replay", *args, rigol).strip(), f"{element} differs"
        with tempfile.TemporaryDirectory() as tmp:
            cli("replay", "--plot", tmp, rigol)
            cli("replay", "--taps", "--plot", tmp, rigol)
            want = len(os.listdir(tmp))
        shown = len(driver.find_elements(By.CSS_SELECTOR, "#replay-plots svg, #taps-plots svg"))
        assert shown == want, (shown, want)
        if SHOTS:
            driver.save_screenshot(os.path.join(SHOTS, "web-capture.png"))
        # A folder of one acquisition a file (the Rigol export split): the files chosen
        # together, read as the CLI reads the folder (named "capture" where the browser gives no
        # folder).
        with tempfile.TemporaryDirectory() as tmp:
            folder = os.path.join(tmp, "capture")
            os.mkdir(folder)
            parts = ["X,CH1," + p for p in open(rigol).read().split("X,CH1,") if p]
            paths = []
            for i, part in enumerate(parts):
                paths.append(os.path.join(folder, f"acq{i:02}.csv"))
                with open(paths[-1], "w") as f:
                    f.write(part)
            choose(driver, *paths)
            wait.until(lambda d: d.find_element(By.ID, "calibrate").text != "" and d.find_element(By.ID, "progress").text == "")
            page = driver.find_element(By.ID, "calibrate").get_attribute("textContent")
            assert page.strip() == cli("calibrate", folder).strip(), "calibrate differs on a folder:\n" + page[:500]
            assert driver.find_element(By.ID, "pager").text == f"tests 1-6 of {len(parts)}"
        # The shared capture (where it is present): calibrate's, replay's and the taps' text,
        # as the CLI's.
        shared = os.path.join(ROOT, "..", "shared", "data", "bouncy-button-uno.jsonl")
        if os.path.exists(shared):
            choose(driver, os.path.abspath(shared))
            WebDriverWait(driver, 300).until(lambda d: d.find_element(By.ID, "calibrate").text != "" and d.find_element(By.ID, "progress").text == "")
            for element, args in (("calibrate", ("calibrate",)), ("replay", ("replay",)), ("taps", ("replay", "--taps"))):
                page = driver.find_element(By.ID, element).get_attribute("textContent")
                assert page.strip() == cli(*args, shared).strip(), f"{element} differs on the shared capture"
            # A capture of levels: its tests drawn as steps, with the window of their kind.
            tests = driver.find_elements(By.CSS_SELECTOR, "#plot svg")
            assert len(tests) == 6 and "level changes" in tests[0].text and "window" in tests[0].text, tests[0].text
            if SHOTS:
                driver.execute_script("document.getElementById('plot').scrollIntoView()")
                driver.save_screenshot(os.path.join(SHOTS, "web-levels.png"))
                driver.execute_script("document.getElementById('taps-plots').scrollIntoView()")
                driver.save_screenshot(os.path.join(SHOTS, "web-taps.png"))
        # A 10 MB capture (the Rigol export's acquisitions 104 times over) is analysed in a
        # worker: while it runs, the page answers at once and shows its progress; at the end it
        # gives the CLI's calibrate text for the same file.
        with tempfile.TemporaryDirectory() as tmp:
            big = os.path.join(tmp, "big.csv")
            with open(rigol) as f:
                one = f.read()
            with open(big, "w") as f:
                f.write(one * 104)
            assert os.path.getsize(big) > 10_000_000
            choose(driver, big)
            wait.until(lambda d: d.find_element(By.ID, "progress").text != "")
            seen, slowest = [], 0.0
            while driver.find_element(By.ID, "calibrate").text == "":
                start = time.monotonic()
                label = driver.find_element(By.ID, "progress").text
                slowest = max(slowest, time.monotonic() - start)
                if label:
                    seen.append(label)
                time.sleep(0.05)
            assert seen and "10.1 MB" in seen[0], seen[:3]
            assert slowest < 0.5, f"the page took {slowest:.2f} s to answer while a capture was analysed"
            print(f"web: a 10 MB capture: {len(seen)} polls during its analysis, the page's slowest answer {slowest * 1e3:.0f} ms; steps seen: {sorted(set(l.split(': ', 1)[-1] for l in seen))}")
            WebDriverWait(driver, 120).until(lambda d: d.find_element(By.ID, "progress").text == "")
            page = driver.find_element(By.ID, "calibrate").get_attribute("textContent")
            assert page.strip() == cli("calibrate", big).strip(), "calibrate differs on the 10 MB capture"
        errors = [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
        assert not errors, errors
        print("web: the page loads with no console error; for the dome it gives eval's bounce, the table mode's window and constants, and the envelope; for a Rigol trace the CLI's calibrate, replay and tap texts and as many Pareto plots; a 10 MB capture in a worker with the page answering; the CLI's texts for the shared capture where present; the field's message for bad input")
    finally:
        driver.quit()


if __name__ == "__main__":
    main()
