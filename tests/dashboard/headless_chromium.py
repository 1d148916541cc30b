"""Headless Chromium for the dashboard's browser tests: Selenium's imports, the skip (saying why)
when Debian's chromium, chromium-driver or python3-selenium is absent, and the driver itself.

A test module calls require() at its top, then takes By, Select, WebDriverWait and
rerendered() from here.
$GC_CHROMIUM / $GC_CHROMEDRIVER name other binaries (a path that does not exist: "absent").
"""
import os
import shutil

import pytest

CHROMIUM = shutil.which(os.environ.get("GC_CHROMIUM", "chromium"))
CHROMEDRIVER = shutil.which(os.environ.get("GC_CHROMEDRIVER", "chromedriver"))
try:
    from selenium import webdriver
    from selenium.common.exceptions import StaleElementReferenceException
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select, WebDriverWait
except ImportError:  # pragma: no cover - reported as a skip by require()
    webdriver = Service = By = Select = WebDriverWait = StaleElementReferenceException = None


def require():
    """Skips the calling test module unless a browser can be driven."""
    if webdriver is None or CHROMIUM is None or CHROMEDRIVER is None:
        pytest.skip("chromium, chromedriver or python3-selenium is absent: the dashboard's browser "
                    "test needs Debian's chromium, chromium-driver and python3-selenium "
                    "(deploy/install-deps.sh)", allow_module_level=True)


def new_driver(window_size):
    """A headless Chromium of `window_size` ("1400,2000") that keeps the page's console log."""
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", f"--window-size={window_size}"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)


def rerendered():
    """What a wait on the dashboard's cards ignores besides a missing element: a card the page
    re-rendered between finding an element and reading it (the next poll finds the new one)."""
    return (StaleElementReferenceException,)
