"""Open every page of the built book in a real browser and check what a reader sees.

Serves the HTML folder on 127.0.0.1 and drives the system Chromium (Debian's
``chromium``) with Playwright at three window widths: a phone's 414 px (mobile emulation,
as an iPhone Plus shows a page), 1024 px, and 1200 px, where the theme switches to three
columns and the text column is at its narrowest (553 px against 685 px at 1024). For
each page of the toc it fails
on: a failed request (no answer, or an HTTP error status) or any request that leaves
the local server (the book must work offline), a JavaScript error (an uncaught
exception; the theme's console messages are not errors of the book), an image that did not load (``naturalWidth == 0``), an
equation left untypeset (raw ``\\(``, ``\\[`` or ``$$`` in the text), a table wider than
the content column (on the phone a table may instead scroll inside its own box), a
display equation wider than its own box (clipped: a reader sees part of it; on the phone
a display equation may instead scroll inside its box), and,
on the phone, a page wider than the screen (the phone would zoom the whole page out),
naming the widest elements that stick out. The search page must find "Helmholtz".

Usage: ``python tools/browser_check.py HTML_DIR [--screenshots DIR]``. Exit 0 when every
page passes, 1 on any problem, 3 when Chromium is not installed (the caller says so).
"""

import argparse
import functools
import http.server
import sys
import threading
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from check_book import chapter_files  # noqa: E402

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-quic"]
#: Width tolerance [px] for sub-pixel rounding.
SLACK = 1.5
#: Window widths [px] every page is checked at: a phone's, a laptop's, and the theme's
#: narrowest three-column layout.
WIDTHS = (414, 1024, 1200)
#: Widths below this are phones: mobile emulation, and a page wider than the screen fails.
PHONE = 600

PAGE_PROBE = r"""
async () => {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
    await MathJax.startup.promise;
    if (MathJax.typesetPromise) { await MathJax.typesetPromise(); }
  }
  const main = document.querySelector("main") || document.body;
  const article = document.querySelector("article.bd-article") || main;
  const column = article.getBoundingClientRect().width;
  const text = article.innerText;
  const images = [...article.querySelectorAll("img")].map(i => ({src: i.getAttribute("src"),
    ok: i.complete && i.naturalWidth > 0}));
  const scrolls = el => { for (let a = el.parentElement; a && a !== article; a = a.parentElement) {
    if (["auto", "scroll"].includes(getComputedStyle(a).overflowX)) { return true; } } return false; };
  const tables = [...article.querySelectorAll("table")].map(t => ({
    width: t.getBoundingClientRect().width, caption: (t.caption ? t.caption.innerText : "").slice(0, 60),
    scrolls: scrolls(t)}));
  // A labelled equation's box is as wide as the column and clips what does not fit, so the
  // measure is the content's width against the box's, not the box's against the column.
  const equations = [...article.querySelectorAll("mjx-container[display='true']")].map(e => ({
    content: e.scrollWidth, box: e.clientWidth, right: e.getBoundingClientRect().right,
    scrolls: ["auto", "scroll"].includes(getComputedStyle(e).overflowX),
    where: (e.closest("[id]") || {id: ""}).id}));
  // What sticks out of the screen: elements whose right edge passes the viewport and that
  // are not inside a box that scrolls or clips them; the outermost of each is reported.
  const viewport = document.documentElement.clientWidth;
  const wide = [];
  for (const el of document.querySelectorAll("body *")) {
    const r = el.getBoundingClientRect();
    if (r.width === 0 || r.right <= viewport + 1.5) { continue; }
    let contained = false;
    for (let a = el.parentElement; a && a !== document.body; a = a.parentElement) {
      const o = getComputedStyle(a).overflowX;
      if (o !== "visible") { contained = true; break; }
    }
    if (contained || (el.parentElement && wide.some(w => w.el.contains(el)))) { continue; }
    wide.push({el, what: el.tagName.toLowerCase() + (el.className && typeof el.className === "string" ?
      "." + el.className.trim().split(/\s+/).join(".") : ""), right: Math.round(r.right),
      text: (el.innerText || "").trim().slice(0, 50)});
  }
  const page = {width: document.documentElement.scrollWidth, viewport,
                wide: wide.slice(0, 4).map(w => ({what: w.what, right: w.right, text: w.text}))};
  const typeset = article.querySelectorAll("mjx-container").length;
  const raw = [];
  for (const marker of ["\\(", "\\[", "$$"]) {
    const k = text.indexOf(marker);
    if (k >= 0) { raw.push(text.slice(Math.max(0, k - 20), k + 40)); }
  }
  return {column, images, tables, equations, typeset, raw, page};
}
"""


def serve(directory):
    """A quiet HTTP server for ``directory`` on an ephemeral port of 127.0.0.1."""
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    handler = functools.partial(Quiet, directory=str(directory))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def check_page(page, url, origin, *, phone=False):
    """Load one page; return (problems, summary dict). ``phone``: also fail on a page
    wider than the screen, and let display equations scroll in their own box."""
    problems, requests = [], []
    page.on("request", lambda r: requests.append(r.url))
    page.on("requestfailed", lambda r: problems.append(f"request failed: {r.url} ({r.failure})"))
    page.on("pageerror", lambda e: problems.append(f"JavaScript error: {e}"))
    page.on("response", lambda r: problems.append(f"HTTP {r.status}: {r.url}") if r.status >= 400 else None)
    page.goto(url, wait_until="load")
    result = page.evaluate(PAGE_PROBE)
    page.wait_for_timeout(100)
    outside = sorted({r for r in requests if not r.startswith(origin) and not r.startswith("data:")})
    problems += [f"request leaves the machine: {r}" for r in outside]
    problems += [f"image did not load: {i['src']}" for i in result["images"] if not i["ok"]]
    problems += [f"equation not typeset: …{r}…" for r in result["raw"]]
    column = result["column"]
    # On a phone a table with many columns may scroll inside its own box (the page does
    # not); on a laptop every table must fit the column.
    problems += [f"table wider than the column ({t['width']:.0f} > {column:.0f} px): {t['caption']!r}"
                 for t in result["tables"] if t["width"] > column + SLACK and not (phone and t["scrolls"])]
    problems += [f"equation clipped ({e['content']:.0f} px of content in a {e['box']:.0f} px box): "
                 f"#{e['where']}" for e in result["equations"]
                 if e["content"] > e["box"] + SLACK and not (phone and e["scrolls"])]
    layout = result["page"]
    if phone and layout["width"] > layout["viewport"] + SLACK:
        culprits = "; ".join(f"{w['what']} to {w['right']} px ({w['text']!r})" for w in layout["wide"])
        problems.append(f"page wider than the screen ({layout['width']} > {layout['viewport']} px): {culprits}")
    return problems, {"images": len(result["images"]), "typeset": result["typeset"],
                      "tables": len(result["tables"])}


def _check_pages(origin, pages, shots):
    """Check ``pages`` in a browser of their own (one per thread: Playwright's sync API is
    per thread); ``{name: (summary line, problems)}``."""
    from playwright.sync_api import sync_playwright

    out = {}
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        contexts = {w: browser.new_context(viewport={"width": w, "height": 768 if w >= PHONE else 736},
                                           service_workers="block", is_mobile=w < PHONE, has_touch=w < PHONE,
                                           device_scale_factor=2 if w < PHONE else 1)
                    for w in WIDTHS}
        for name in pages:
            problems = []
            for width, context in contexts.items():
                page = context.new_page()
                found, summary = check_page(page, f"{origin}/{name}.html", origin, phone=width < PHONE)
                if shots and width in (WIDTHS[0], WIDTHS[1]):
                    page.screenshot(path=str(shots / f"{Path(name).name}-{width}.png"), full_page=True)
                page.close()
                problems += [f"{problem} (at {width} px)" for problem in found]
            status = "ok" if not problems else f"{len(problems)} problems"
            line = (f"  {name:32s} {summary['images']:3d} images loaded  {summary['typeset']:4d} equations typeset  "
                    f"{summary['tables']:3d} tables  {status}")
            out[name] = (line, [f"{name}: {problem}" for problem in problems])
        browser.close()
    return out


def _search_hits(origin, search):
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        page = browser.new_context(viewport={"width": WIDTHS[1], "height": 768}, service_workers="block").new_page()
        page.goto(f"{origin}/search.html?q={search}", wait_until="load")
        try:
            page.wait_for_selector("#search-results li, ul.search li", timeout=15000)
            hits = page.locator("#search-results li, ul.search li").count()
        except Exception:       # noqa: BLE001 - a timeout is the finding
            hits = 0
        browser.close()
    return hits


def check_site(html_dir, pages, screenshots=None, search="Helmholtz", workers=2):
    """Check ``pages`` (paths without ``.html``) of ``html_dir``; return the problems found.

    ``search``: a word the site's search page must find (``None``: no search check).
    ``workers`` browsers check the pages side by side (two cores: the check's time halves,
    what it finds does not change). Prints one line per page, in the order given.
    """
    import concurrent.futures

    server = serve(html_dir)
    origin = f"http://127.0.0.1:{server.server_address[1]}"
    shots = Path(screenshots) if screenshots else None
    if shots:
        shots.mkdir(parents=True, exist_ok=True)
    failures = []
    try:
        shares = [pages[k::workers] for k in range(workers) if pages[k::workers]]
        with concurrent.futures.ThreadPoolExecutor(len(shares) or 1) as pool:
            results = {}
            for part in pool.map(lambda share: _check_pages(origin, share, shots), shares):
                results.update(part)
        for name in pages:
            line, problems = results[name]
            print(line)
            failures += problems
        if search:
            hits = _search_hits(origin, search)
            print(f"  search {search!r}: {hits} results")
            if hits == 0:
                failures.append(f"search page: no result for {search!r}")
    finally:
        server.shutdown()
        server.server_close()
    return failures


def chromium_installed():
    return Path(CHROMIUM).exists()


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("html_dir")
    parser.add_argument("--screenshots", help="folder for a full-page screenshot of every page")
    args = parser.parse_args(argv)
    if not chromium_installed():
        print(f"browser check: {CHROMIUM} not found")
        return 3
    pages = chapter_files()
    failures = check_site(Path(args.html_dir), pages, args.screenshots)
    if failures:
        print("browser check failed:\n  " + "\n  ".join(failures))
        return 1
    print(f"browser check: {len(pages)} pages at {' and '.join(map(str, WIDTHS))} px, offline, no problems")
    return 0


if __name__ == "__main__":
    sys.exit(main())
