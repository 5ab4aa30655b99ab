#!/usr/bin/python3
"""`frictionref report` rendered by headless Chromium (docs/cli.md, report).

For a FAIL and a PASS report, checks that
  - the page is valid HTML (html5lib, strict: any parse error fails);
  - it is self-contained: no script, no element that loads anything, no
    reference outside the page;
  - Chromium logs nothing to the console while it renders it (a JS error or
    an SVG attribute Chromium cannot parse is logged there);
  - each of the three figures is drawn: its SVG has the size it declares, and
    the screenshot inside its box is not blank and shows the candidate's
    curve (pixels of its colour) and the exact one (dark pixels).
Each detector is also shown to fire once, on a page broken on purpose, so a
check that could never fail cannot pass unnoticed.

Usage: test_report_browser.py --binary build/release/frictionref
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

import html5lib
from PIL import Image, ImageStat

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
BINARY = None
FIGURES = ["figure-velocity", "figure-error", "figure-zoom"]
WIDTH = 1100  # window width [px]: wider than the page, so nothing is scaled


def run(args, cwd, expect):
    result = subprocess.run(args, cwd=cwd, capture_output=True, timeout=120)
    if result.returncode != expect:
        raise AssertionError(f"{args}: exit {result.returncode}, expected {expect}\n"
                             + result.stderr.decode("utf-8", "replace"))
    return result


def chromium(page, workdir, *extra, height=1000):
    """Runs headless Chromium on `page`; returns (stdout, console lines)."""
    args = [
        CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
        "--force-device-scale-factor=1", "--no-first-run", "--disable-extensions",
        "--user-data-dir=" + os.path.join(workdir, "chromium-profile"),
        # Nothing may come from the network; if the page asked, it would fail.
        "--host-resolver-rules=MAP * ~NOTFOUND",
        "--enable-logging=stderr", "--v=0",
        f"--window-size={WIDTH},{height}", *extra, "file://" + os.path.abspath(page),
    ]
    result = subprocess.run(args, capture_output=True, text=True, timeout=90)
    if result.returncode != 0:
        raise AssertionError(f"chromium exit {result.returncode}:\n{result.stderr[-3000:]}")
    # Chromium logs every console message (errors, warnings, logs) as
    # "[...:INFO:CONSOLE:<line>] "<message>", source: <url> (<line>)"; our
    # page has no script, so any console line is a problem.
    console = [line for line in result.stderr.splitlines() if re.search(r":CONSOLE[:(\]]", line)]
    return result.stdout, console


def figure_boxes(page, workdir):
    """Layout of the figures: a copy of the page with a probe script that
    writes every svg.plot's box and the document height into the title,
    read back with --dump-dom. A script does not take part in layout, so the
    boxes are those of the page itself (same window width)."""
    probe = os.path.join(workdir, "probe.html")
    with open(page, encoding="utf-8") as f:
        text = f.read()
    script = (
        "<script>document.title = JSON.stringify({height: document.documentElement.scrollHeight,"
        " figures: Array.from(document.querySelectorAll('svg.plot')).map(s => {"
        " const r = s.getBoundingClientRect(); return {id: s.id, x: r.left + scrollX,"
        " y: r.top + scrollY, width: r.width, height: r.height,"
        " declared: [+s.getAttribute('width'), +s.getAttribute('height')]}; })});</script>")
    assert text.count("</body>") == 1
    with open(probe, "w", encoding="utf-8") as f:
        f.write(text.replace("</body>", script + "</body>"))
    dom, console = chromium(probe, workdir, "--dump-dom")
    assert not console, console
    title = html5lib.parse(dom, namespaceHTMLElements=False).find(".//title").text
    return json.loads(title)


def parse_errors(text):
    parser = html5lib.HTMLParser(strict=True)
    try:
        parser.parse(text)
    except html5lib.html5parser.ParseError as error:
        return [str(error)]
    return []


def outside_references(text):
    """What in the page would load or link to something outside it."""
    found = []
    tree = html5lib.parse(text, namespaceHTMLElements=False)
    for element in tree.iter():
        tag = element.tag.split("}")[-1] if isinstance(element.tag, str) else ""
        if tag in ("script", "link", "img", "iframe", "object", "embed", "audio", "video",
                   "source", "base", "image", "use", "foreignObject"):
            found.append(f"<{tag}>")
        for name, value in element.attrib.items():
            name = name.split("}")[-1] if isinstance(name, str) else str(name)
            if name == "xmlns":
                continue
            if name in ("src", "srcset", "data") or name.startswith("on"):
                found.append(f"{tag} {name}={value!r}")
            if name == "href" and not value.startswith("#"):
                found.append(f"{tag} href={value!r}")
            if "url(" in value and not re.fullmatch(r"url\(#[\w-]+\)", value):
                found.append(f"{tag} {name}={value!r}")
        if tag == "style" and element.text and re.search(r"url\(|@import|@font-face", element.text):
            found.append("style with url()/@import/@font-face")
    return found


def figure_problems(shot, boxes):
    """Why a figure does not look drawn (empty list: all drawn)."""
    problems = []
    image = Image.open(shot).convert("RGB")
    found = {box["id"]: box for box in boxes["figures"]}
    for name in FIGURES:
        box = found.get(name)
        if box is None:
            problems.append(f"{name}: not in the page")
            continue
        if [box["width"], box["height"]] != box["declared"]:
            problems.append(f"{name}: drawn {box['width']}x{box['height']}, declared {box['declared']}")
        left, top = round(box["x"]), round(box["y"])
        right, bottom = left + round(box["width"]), top + round(box["height"])
        if right > image.width or bottom > image.height or left < 0 or top < 0:
            problems.append(f"{name}: box {left},{top}..{right},{bottom} outside the screenshot")
            continue
        crop = image.crop((left, top, right, bottom))
        spread = ImageStat.Stat(crop.convert("L")).stddev[0]
        # Orange, pure or blended with the white background by antialiasing
        # (blends keep r > g > b in proportion); greys, the green tolerance
        # and the purple markers do not qualify.
        candidate = sum(1 for pr, pg, pb in crop.getdata() if pr - pg > 50 and pr - pb > 90)
        dark = sum(1 for p in crop.getdata() if max(p) < 60)
        # A blank or single-colour box has no spread; the curves are long
        # lines, hundreds of pixels each (the legend's samples are ~40).
        if spread < 10:
            problems.append(f"{name}: blank (grey-level spread {spread:.1f})")
        if candidate < 400:
            problems.append(f"{name}: {candidate} pixels of the candidate's colour")
        if dark < 400:
            problems.append(f"{name}: {dark} dark pixels (axes, labels, exact curve)")
    return problems


def render(page, workdir):
    """Screenshot of the whole page; returns (png, console lines, boxes)."""
    boxes = figure_boxes(page, workdir)
    shot = os.path.join(workdir, "shot.png")
    if os.path.exists(shot):
        os.remove(shot)
    _, console = chromium(page, workdir, "--screenshot=" + shot,
                          height=min(int(boxes["height"]) + 10, 30000))
    assert os.path.exists(shot), "no screenshot"
    return shot, console, boxes


class ReportInBrowser(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="frictionref-report-")
        d = cls.dir
        # A candidate with a soft friction spring (K_f = 1e5) fails stop_times
        # and creep; one with the seed's K_f = 1e7 passes.
        run([BINARY, "stiff", "--lambda", "0.7", "--t-end", "30", "--kf", "1e5", "-o", "soft.csv"], d, 0)
        run([BINARY, "stiff", "--lambda", "0.7", "--t-end", "30", "-o", "stiff.csv"], d, 0)
        run([BINARY, "report", "--candidate", "soft.csv", "--lambda", "0.7", "-o", "fail.html"], d, 1)
        run([BINARY, "report", "--candidate", "stiff.csv", "--lambda", "0.7", "-o", "pass.html"], d, 0)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def page(self, name):
        with open(os.path.join(self.dir, name), encoding="utf-8") as f:
            return f.read()

    def check_rendered(self, name):
        workdir = tempfile.mkdtemp(dir=self.dir)
        shot, console, boxes = render(os.path.join(self.dir, name), workdir)
        self.assertEqual(console, [], "console messages while rendering " + name)
        self.assertEqual(figure_problems(shot, boxes), [])
        return shot, boxes

    def test_valid_html(self):
        for name in ("fail.html", "pass.html"):
            self.assertEqual(parse_errors(self.page(name)), [], name)

    def test_self_contained(self):
        for name in ("fail.html", "pass.html"):
            self.assertEqual(outside_references(self.page(name)), [], name)

    def test_fail_report_renders(self):
        self.assertIn('id="verdict">FAIL<', self.page("fail.html"))
        shot, _ = self.check_rendered("fail.html")
        # Keep the screenshot for a person to look at, when asked to.
        keep = os.environ.get("FRICTIONREF_REPORT_SCREENSHOT")
        if keep:
            shutil.copyfile(shot, keep)

    def test_pass_report_renders(self):
        self.assertIn('id="verdict">PASS<', self.page("pass.html"))
        self.check_rendered("pass.html")

    def test_hostile_file_name_stays_text(self):
        # Markup, quotes, a control character and a byte that is not UTF-8.
        name = b"r&d <script>alert('x')<!-- \x01\xff.csv"
        shutil.copyfile(os.path.join(self.dir, "stiff.csv"), os.path.join(os.fsencode(self.dir), name))
        run([os.fsencode(BINARY), b"report", b"--candidate", name, b"--lambda", b"0.7",
             b"-o", b"hostile.html"], self.dir, 0)
        with open(os.path.join(self.dir, "hostile.html"), "rb") as f:
            data = f.read()
        text = data.decode("utf-8")  # strict: the page is valid UTF-8 whatever the name
        self.assertEqual(parse_errors(text), [])
        self.assertEqual(outside_references(text), [])
        tree = html5lib.parse(text, namespaceHTMLElements=False)
        self.assertEqual(tree.find(".//title").text,
                         "frictionref validation report: r&d <script>alert('x')<!-- "
                         "\ufffd\ufffd.csv: PASS")

    # The detectors fire on pages broken on purpose.

    def test_parser_detects_invalid_html(self):
        broken = self.page("pass.html").replace("</table>", "</tabel>", 1)
        self.assertNotEqual(parse_errors(broken), [])

    def test_reference_check_detects_outside_resources(self):
        page = self.page("pass.html")
        for bad in ('<img src="https://example.com/x.png">', '<link rel="stylesheet" href="s.css">',
                    "<style>body { background: url(https://example.com/a.png); }</style>"):
            self.assertNotEqual(outside_references(page.replace("</main>", bad + "</main>")), [], bad)

    def test_console_check_detects_errors(self):
        workdir = tempfile.mkdtemp(dir=self.dir)
        page = os.path.join(workdir, "broken.html")
        with open(page, "w", encoding="utf-8") as f:
            f.write(self.page("pass.html").replace(
                "</main>",
                '<svg width="10" height="10"><polyline points="0,0 1,nan"/></svg>'
                "<script>undefined_function();</script></main>"))
        _, console = chromium(page, workdir, "--screenshot=" + os.path.join(workdir, "b.png"))
        self.assertEqual(len(console), 2, console)
        self.assertTrue(any("polyline" in line for line in console), console)
        self.assertTrue(any("undefined_function" in line for line in console), console)

    def test_figure_check_detects_undrawn_figures(self):
        workdir = tempfile.mkdtemp(dir=self.dir)
        page = os.path.join(workdir, "blank.html")
        text = self.page("fail.html")
        # The curves removed from every figure, and the zoom emptied entirely.
        text = re.sub(r"<polyline [^>]*/>", "", text)
        text = re.sub(r'(<svg id="figure-zoom"[^>]*>).*?(</svg>)', r"\1\2", text, flags=re.S)
        with open(page, "w", encoding="utf-8") as f:
            f.write(text)
        shot, console, boxes = render(page, workdir)
        problems = figure_problems(shot, boxes)
        for name in FIGURES:
            self.assertTrue(any(p.startswith(name + ": ") and "candidate" in p for p in problems),
                            (name, problems))
        self.assertTrue(any(p.startswith("figure-zoom: blank") for p in problems), problems)


def main():
    global BINARY
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", required=True, help="the frictionref program")
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0], "-v", *rest])


if __name__ == "__main__":
    main()
