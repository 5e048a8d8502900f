"""HTML additions and fixes for the built book.

* **Executed notebooks for download.** Each executed page gets an ``.ipynb`` entry in the
  theme's download menu, next to its ``.md`` source: the notebook with every output
  (glued figures shown, glued numbers kept as records), taken from the execution cache.
  myst-nb's own copy in ``jupyter_execute/`` has its glued outputs stripped.
* **Build provenance on every page.** The footer names the git commit the book was
  built from (and whether the work tree had uncommitted changes), the build date (UTC;
  ``SOURCE_DATE_EPOCH`` when set, for reproducible builds) and the SHA-256 of
  ``requirements.lock``. The computation itself is named by each page's own line
  (``magbench.report.provenance``: library and data hashes), which is cached with it.
* **Provenance in small print.** A figure caption ends with the figure's id and the
  function that drew it (pasted from the page's glue). That text gets the class
  ``provenance`` (small, normal weight, free to wrap anywhere; ``_static/magbench.css``),
  so the caption's own sentence stays what the reader sees first.
* **No duplicate scripts.** sphinx-thebe and sphinx-togglebutton (pulled in by
  jupyter-book even with Thebe switched off) register their inline configuration scripts
  at every read phase. Sphinx dedupes scripts on registration, but it stores the first
  copy with file name ``None`` and a later one with ``''``, so a build that reads twice
  puts both on each page, and the second ``const THEBE_JS_URL`` is a JavaScript error on
  every page. Scripts that differ only in that way are dropped from each page.
"""

import datetime
import hashlib
import html
import os
import re
import subprocess
from pathlib import Path

from docutils import nodes

#: A figure's caption provenance as ``magbench.figures.caption_provenance`` writes it.
_PROVENANCE = re.compile(r"^\[[\w.-]+\] made by ")


def _mark_provenance(app, doctree, docname):
    """Give the pasted caption provenance (``[id] made by …``) the class ``provenance``."""
    for node in doctree.findall(nodes.inline):
        if "pasted-text" in node["classes"] and _PROVENANCE.match(node.astext()):
            node["classes"].append("provenance")


def _script_key(script):
    filename = getattr(script, "filename", script) or ""
    attributes = getattr(script, "attributes", {})
    return (str(filename), getattr(script, "priority", 500), tuple(sorted((k, str(v)) for k, v in attributes.items())))


def _dedupe_scripts(app, pagename, templatename, context, doctree):
    seen, unique = set(), []
    for script in context.get("script_files", []):
        key = _script_key(script)
        if key not in seen:
            seen.add(key)
            unique.append(script)
    context["script_files"] = unique


def _git(srcdir, *args):
    try:
        result = subprocess.run(["git", *args], cwd=srcdir, capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.SubprocessError):
        return None
    return result.stdout.strip() if result.returncode == 0 else None


def build_provenance(srcdir):
    """The footer line: commit (or its absence), build date [UTC], lock-file hash."""
    commit = _git(srcdir, "rev-parse", "--short=12", "HEAD")
    if commit is None:
        source = "no git commit (not built from a git checkout)"
    else:
        # Build products (_build) are ignored by git, so any change listed is a source change.
        dirty = bool(_git(srcdir, "status", "--porcelain", "--untracked-files=no"))
        source = f"commit {commit}" + (" with uncommitted changes" if dirty else "")
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    when = (datetime.datetime.fromtimestamp(int(epoch), datetime.timezone.utc) if epoch
            else datetime.datetime.now(datetime.timezone.utc))
    lock = Path(srcdir, "requirements.lock")
    lock_hash = hashlib.sha256(lock.read_bytes()).hexdigest()[:12] if lock.exists() else "missing"
    return f"Built from {source} on {when:%Y-%m-%d %H:%M} UTC with requirements.lock sha256 {lock_hash}."


def _add_provenance(app, pagename, templatename, context, doctree):
    line = html.escape(app.config.book_build_provenance)
    context["theme_extra_footer"] = f'<p class="magbench-provenance">{line}</p>'


def _executed_notebook(app, docname):
    """The page's notebook with its cached outputs, or None (not a notebook, not cached)."""
    config = getattr(app.env, "mystnb_config", None)
    source = Path(app.srcdir, docname + ".md")
    if config is None or not config.execution_cache_path or not source.exists():
        return None
    import jupytext
    import nbformat
    from jupyter_cache import get_cache

    notebook = jupytext.read(source, fmt="md:myst")      # the book's only notebook format
    if "kernelspec" not in notebook.metadata:      # a plain Markdown page
        return None
    try:
        _, merged = get_cache(config.execution_cache_path).merge_match_into_notebook(notebook)
    except KeyError:                               # not in the cache: nothing executed to offer
        return None
    _show_glued_figures(merged)
    return nbformat.writes(merged).encode("utf-8")


GLUE_PREFIX = "application/papermill.record/"


def _show_glued_figures(notebook):
    """Make glued figures visible in Jupyter, where they were computed.

    myst-nb's glue stores outputs under ``application/papermill.record/<mime>``, which
    Jupyter does not display. Records holding an image get their plain MIME types back;
    records of numbers and text stay records (shown in the book's prose, where they are
    glued, and still readable by myst-nb and scrapbook).
    """
    for cell in notebook.cells:
        for output in cell.get("outputs", []):
            data = output.get("data", {})
            if any(key.startswith(GLUE_PREFIX + "image/") for key in data):
                output["data"] = {key.removeprefix(GLUE_PREFIX): value for key, value in data.items()}


def _offer_notebook(app, pagename, templatename, context, doctree):
    if doctree is None:
        return
    content = _executed_notebook(app, pagename)
    if content is None:
        return
    target = Path(app.outdir, "_sources", pagename + ".ipynb")
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_bytes(content)
    context["ipynb_source"] = pagename + ".ipynb"   # read by the theme's download menu


def _config_inited(app, config):
    config.book_build_provenance = build_provenance(app.srcdir)


def setup(app):
    app.add_config_value("book_build_provenance", "", "html")   # every page rewritten: its footer is this build's
    app.connect("config-inited", _config_inited)
    app.connect("doctree-resolved", _mark_provenance)
    app.connect("html-page-context", _offer_notebook, priority=400)    # before the theme's buttons (501)
    app.connect("html-page-context", _add_provenance, priority=400)
    app.connect("html-page-context", _dedupe_scripts, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
