"""`make docs`, after Sphinx: the built site's gallery pages open in headless Chromium, their
pictures load and their consoles show no error.

Each page (by default the tutorials and the two galleries' index pages) is copied to a
temporary folder with a <base> pointing back at its own folder, so that what it loads resolves
as in the site, and with a probe inserted first in its <head>: the probe records the
page's errors (console.error, uncaught exceptions, unhandled rejections, a picture, script or
style sheet that fails to load) and, on the window's load, writes into the page how many of
its <img> elements are complete with a natural width above zero. Chromium runs the copy with
--virtual-time-budget (the page's timers run to idle without waiting for them) and
--dump-dom; the probe's report is read from the dumped DOM, and Chromium's own log of console
messages is kept as a second net for uncaught errors that come before the probe runs.

Without Chromium (chromium or chromium-browser on PATH) the check says so and passes: .ci/run
installs Debian's chromium when the package index can be reached.

Usage: python tools/check_site.py [SITE] [PAGE.html ...]   (SITE default docs/_build/html;
PAGEs relative to it, default DEFAULT_PAGES)
"""

import html
import json
import re
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SITE = ROOT / "docs" / "_build" / "html"
#: the pages checked by default, relative to the site: the tutorials, and the galleries' index
#: pages, whose thumbnails are every tutorial's and example's first picture (about 2 s a page)
DEFAULT_PAGES = (
    "generated/tutorials/index.html",
    "generated/tutorials/plot_*.html",
    "generated/examples/index.html",
)

CHROME_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--enable-logging=stderr",
    "--v=0",
    # virtual time: the page's load and its timers run to idle at once
    "--virtual-time-budget=5000",
    "--dump-dom",
]

#: the id of the element the probe writes its report into
REPORT_ID = "balance-site-check"

#: first in <head>: records the page's errors, and reports its pictures on the window's load
#: (and again after any later error)
PROBE = """<script>
(function () {
  var errors = [];
  var loaded = false;
  function report() {
    if (!loaded) { return; }
    var images = Array.prototype.slice.call(document.images);
    var broken = images.filter(function (i) { return !(i.complete && i.naturalWidth > 0); });
    var out = document.getElementById("@ID@");
    if (!out) {
      out = document.createElement("pre");
      out.id = "@ID@";
      out.hidden = true;
      document.body.appendChild(out);
    }
    out.textContent = JSON.stringify({
      images: images.length,
      loaded: images.length - broken.length,
      broken: broken.map(function (i) { return i.getAttribute("src"); }),
      errors: errors
    });
  }
  function note(text) { errors.push(String(text)); report(); }
  var consoleError = console.error;
  console.error = function () {
    note("console.error: " + Array.prototype.join.call(arguments, " "));
    return consoleError.apply(console, arguments);
  };
  window.addEventListener("error", function (event) {
    var target = event.target;
    if (target && target !== window && target.nodeType === 1) {
      note("failed to load " + (target.getAttribute("src") || target.getAttribute("href")));
    } else {
      note("uncaught: " + event.message);
    }
  }, true);
  window.addEventListener("unhandledrejection", function (event) {
    note("unhandled rejection: " + event.reason);
  });
  window.addEventListener("load", function () { loaded = true; report(); });
})();
</script>""".replace("@ID@", REPORT_ID)

_HEAD = re.compile(r"<head\b[^>]*>", re.I)
_REPORT = re.compile(rf'<pre id="{REPORT_ID}"[^>]*>(.*?)</pre>', re.S)
#: Chromium's log line of a console message, and the uncaught errors among them
_CONSOLE = re.compile(r':CONSOLE[:(]\d+\)?\] "(.*)", source: ')


def chromium():
    """Chromium's executable, or None."""
    return shutil.which("chromium") or shutil.which("chromium-browser")


@dataclass
class PageCheck:
    """What headless Chromium found on one page."""

    page: str
    images: int = 0
    loaded: int = 0
    broken: list = field(default_factory=list)
    errors: list = field(default_factory=list)
    console: list = field(default_factory=list)

    @property
    def problems(self) -> list:
        """Each thing wrong with the page, one line each (none: the page passes)."""
        out = [f"picture {src!r} did not load" for src in self.broken]
        if self.images == 0 and not self.errors:
            out.append("no picture on the page")
        # a picture that failed to load is said once, above
        out += [e for e in self.errors if e.removeprefix("failed to load ") not in self.broken]
        # Chromium's log, for an uncaught error before the probe ran (after it, the probe
        # has it already)
        out += [
            f"console: {line}"
            for line in self.console
            if line.startswith("Uncaught") and not any(line in e for e in self.errors)
        ]
        return out

    def summary(self) -> str:
        problems = self.problems
        if not problems:
            return f"{self.page}: {self.loaded} of {self.images} pictures loaded, no console error"
        return f"{self.page}: " + "; ".join(problems)


def probed(text, folder):
    """The page's HTML with a <base> at ``folder`` and the probe first in its <head>."""
    match = _HEAD.search(text)
    if match is None:
        raise ValueError("no <head> element")
    base = f'<base href="{html.escape(folder.as_uri())}/">'
    return text[: match.end()] + base + PROBE + text[match.end() :]


def check_page(page, browser, scratch, label=None):
    """Open ``page`` (a built HTML file) in headless Chromium and return a :class:`PageCheck`.
    ``scratch`` is an empty folder for the probed copy and Chromium's profile: a new profile
    each time, so that every page is seen as on a reader's first visit (nothing stored)."""
    label = label or page.name
    copy = scratch / f"probed-{page.name}"
    copy.write_text(probed(page.read_text(encoding="utf-8"), page.parent), encoding="utf-8")
    done = subprocess.run(
        [browser, *CHROME_FLAGS, f"--user-data-dir={scratch / 'profile'}", copy.as_uri()],
        capture_output=True,
        text=True,
        timeout=120,
    )
    console = [m.group(1) for m in map(_CONSOLE.search, done.stderr.splitlines()) if m]
    if done.returncode != 0:
        return PageCheck(label, errors=[f"chromium exited with {done.returncode}"])
    found = _REPORT.search(done.stdout)
    if found is None:
        return PageCheck(label, errors=["the page never finished loading"], console=console)
    report = json.loads(html.unescape(found.group(1)))
    return PageCheck(
        label,
        images=report["images"],
        loaded=report["loaded"],
        broken=report["broken"],
        errors=report["errors"],
        console=console,
    )


def main(argv=None):
    args = sys.argv[1:] if argv is None else argv
    site = Path(args[0]).resolve() if args else SITE
    if not (site / "index.html").is_file():
        print(f"check_site: {site}: no built site there; build it with make docs")
        return 1
    browser = chromium()
    if browser is None:
        print(
            "check_site: skipped: Chromium is not installed (chromium or chromium-browser on "
            "PATH; .ci/run installs Debian's chromium when the package index can be reached)"
        )
        return 0
    pages = [site / p for p in args[1:]] or [
        page for pattern in DEFAULT_PAGES for page in sorted(site.glob(pattern))
    ]
    missing = [p for p in pages if not p.is_file()]
    if not pages or missing:
        print(f"check_site: {site}: no page {missing[0] if missing else DEFAULT_PAGES}")
        return 1
    failed = pictures = 0
    with tempfile.TemporaryDirectory(prefix="balance-check-site-") as scratch:
        for i, page in enumerate(pages):
            folder = Path(scratch) / str(i)
            folder.mkdir()
            check = check_page(page, browser, folder, str(page.relative_to(site)))
            print(f"check_site: {check.summary()}")
            failed += bool(check.problems)
            pictures += check.loaded
    if failed:
        print(f"check_site: {failed} of {len(pages)} pages failed")
        return 1
    print(
        f"check_site: {len(pages)} pages in headless Chromium, {pictures} pictures loaded, "
        "no console error"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
