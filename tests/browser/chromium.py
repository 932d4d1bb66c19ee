"""Headless Chromium driven over the Chrome DevTools Protocol, standard library
only: the browser is started with --remote-debugging-pipe, which speaks the
protocol's JSON messages, each ended by a NUL byte, on file descriptors 3
(to the browser) and 4 (from it). WebGL runs on SwiftShader, the CPU
renderer, so the tests need no GPU and no display.

    with Chromium(executable, work_dir) as browser:
        page = browser.open("file:///.../report.html")
        page.evaluate("window.polymass.ready")
        page.screenshot("report.png")
        page.errors  # console errors, uncaught exceptions, blocked loads
"""

import base64
import contextlib
import json
import os
import select
import subprocess
import tempfile
import time


class BrowserError(Exception):
    pass


class Chromium:
    def __init__(self, executable, width=1400, height=900, timeout=60.0):
        self.executable = executable
        self.size = (width, height)
        self.timeout = timeout
        self.next_id = 0
        self.buffer = b""
        self.events = []  # (session, method, params) not yet handed to a page

    def __enter__(self):
        to_browser_read, self.to_browser = os.pipe()
        self.from_browser, from_browser_write = os.pipe()
        self.profile = tempfile.TemporaryDirectory(prefix="polymass-chromium-")

        def wire_pipes():  # in the child, before exec: the pipes as 3 and 4
            os.dup2(to_browser_read, 3)
            os.dup2(from_browser_write, 4)

        self.process = subprocess.Popen(
            [
                self.executable,
                "--headless=new",
                "--remote-debugging-pipe",
                # The tests run as root in CI containers, where the sandbox
                # cannot start; the pages are the tests' own files.
                "--no-sandbox",
                "--use-angle=swiftshader",
                "--enable-unsafe-swiftshader",
                "--ignore-gpu-blocklist",
                "--no-first-run",
                "--no-default-browser-check",
                "--disable-extensions",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                "--mute-audio",
                "--hide-scrollbars",
                f"--window-size={self.size[0]},{self.size[1]}",
                f"--user-data-dir={self.profile.name}",
                "about:blank",
            ],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            pass_fds=(3, 4),
            preexec_fn=wire_pipes,
        )
        os.close(to_browser_read)
        os.close(from_browser_write)
        return self

    def __exit__(self, *exc):
        with contextlib.suppress(BrowserError, OSError):
            self.send("Browser.close", timeout=10)
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        os.close(self.to_browser)
        os.close(self.from_browser)
        self.profile.cleanup()

    # ---- the protocol ----------------------------------------------------

    def _read_message(self, deadline):
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                raise BrowserError("the browser did not answer in time")
            ready, _, _ = select.select([self.from_browser], [], [], left)
            if not ready:
                continue
            chunk = os.read(self.from_browser, 1 << 20)
            if not chunk:
                raise BrowserError(f"the browser exited (status {self.process.poll()})")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def send(self, method, params=None, session=None, timeout=None):
        """Sends a command and returns its result; events seen meanwhile
        are kept for the pages."""
        self.next_id += 1
        command = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            command["sessionId"] = session
        os.write(self.to_browser, json.dumps(command).encode() + b"\0")
        deadline = time.monotonic() + (timeout or self.timeout)
        while True:
            message = self._read_message(deadline)
            if message.get("id") == self.next_id:
                if "error" in message:
                    raise BrowserError(f"{method}: {message['error']}")
                return message["result"]
            if "method" in message:
                self.events.append((message.get("sessionId"), message["method"], message["params"]))

    def open(self, url):
        """A new tab showing url, once loaded."""
        target = self.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True})[
            "sessionId"
        ]
        page = Page(self, session, target)
        for domain in ("Page", "Runtime", "Log", "Network"):
            self.send(f"{domain}.enable", session=session)
        self.send(
            "Emulation.setDeviceMetricsOverride",
            {
                "width": self.size[0],
                "height": self.size[1],
                "deviceScaleFactor": 1,
                "mobile": False,
            },
            session=session,
        )
        page.url = url
        self.send("Page.navigate", {"url": url}, session=session)
        return page


class Page:
    def __init__(self, browser, session, target):
        self.browser = browser
        self.session = session
        self.target = target
        self.url = None
        self._errors = []
        self._requests = []

    def _collect(self):
        kept = []
        for session, method, params in self.browser.events:
            if session != self.session:
                kept.append((session, method, params))
                continue
            if method == "Runtime.exceptionThrown":
                details = params["exceptionDetails"]
                text = details.get("exception", {}).get("description") or details.get("text")
                self._errors.append(f"exception: {text}")
            elif method == "Runtime.consoleAPICalled" and params["type"] in ("error", "assert"):
                texts = [
                    str(arg.get("value", arg.get("description", ""))) for arg in params["args"]
                ]
                self._errors.append("console.error: " + " ".join(texts))
            elif method == "Log.entryAdded" and params["entry"]["level"] == "error":
                self._errors.append(f"log: {params['entry']['text']}")
            elif method == "Network.requestWillBeSent":
                self._requests.append(params["request"]["url"])
        self.browser.events = kept

    @property
    def errors(self):
        self._collect()
        return list(self._errors)

    @property
    def requests(self):
        """Every URL the page asked for (the page itself included)."""
        self._collect()
        return list(self._requests)

    def evaluate(self, expression, timeout=None):
        """The JSON value of a JavaScript expression (awaited if a promise)."""
        result = self.browser.send(
            "Runtime.evaluate",
            {"expression": expression, "returnByValue": True, "awaitPromise": True},
            session=self.session,
            timeout=timeout,
        )
        if "exceptionDetails" in result:
            details = result["exceptionDetails"]
            text = details.get("exception", {}).get("description") or details.get("text")
            raise BrowserError(f"{expression}: {text}")
        return result["result"].get("value")

    def wait_for(self, expression, timeout=60.0):
        """Waits until expression is true (an error on the page ends the
        wait); the time it took."""
        start = time.monotonic()
        while time.monotonic() - start < timeout:
            if self.errors:
                raise BrowserError(f"{self.url}: {self.errors}")
            try:
                if self.evaluate(expression):
                    return time.monotonic() - start
            except BrowserError:
                pass  # the page is not there yet
            time.sleep(0.05)
        raise BrowserError(
            f"{self.url}: not true after {timeout} s: {expression}; errors: {self.errors}"
        )

    def screenshot(self, path):
        data = self.browser.send("Page.captureScreenshot", {"format": "png"}, session=self.session)[
            "data"
        ]
        with open(path, "wb") as out:
            out.write(base64.b64decode(data))

    def close(self):
        self.browser.send("Target.closeTarget", {"targetId": self.target})
