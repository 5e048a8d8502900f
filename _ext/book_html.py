"""HTML fixes for the built book.

sphinx-thebe and sphinx-togglebutton (pulled in by jupyter-book even with Thebe switched
off) register their inline configuration scripts at every read phase. Sphinx dedupes
scripts on registration, but it stores the first copy with file name ``None`` and a
later one with ``''``, so a build that reads twice puts both on each page, and the
second ``const THEBE_JS_URL`` is a JavaScript error on every page. This extension drops
scripts that differ only in that way from each page's script list.
"""


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


def setup(app):
    app.connect("html-page-context", _dedupe_scripts, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
