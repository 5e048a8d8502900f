"""The README's commands work as written (from the repository root, with the set-up
``make env`` makes)."""

import json
import os
import re
import shlex
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def _block_after(marker):
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    start = text.index(marker)
    block = re.search(r"```\n(.*?)```", text[start:], re.S)
    return [line.strip() for line in block.group(1).splitlines() if line.strip()]


@pytest.mark.slow
def test_papermill_route_runs_a_chapter_with_a_parameter():
    commands = _block_after("run the\n  chapter with papermill")
    tools = [ROOT / shlex.split(c)[0] for c in commands]
    if not all(t.is_file() for t in tools):
        pytest.skip(f"the commands need {', '.join(map(str, tools))} (make env)")
    created = [ROOT / shlex.split(c)[-1] for c in commands[:1]] + [ROOT / "out.ipynb"]
    assert not any(p.exists() for p in created), "would overwrite a file in the repository"
    env = {k: v for k, v in os.environ.items() if k != "MAGBENCH_PARAMS"}
    env["MPLBACKEND"] = "Agg"
    try:
        for command in commands:
            run = subprocess.run(shlex.split(command), cwd=ROOT, env=env, capture_output=True, text=True)
            assert run.returncode == 0, f"{command}\n{run.stderr[-2000:]}"
        notebook = json.loads((ROOT / "out.ipynb").read_text(encoding="utf-8"))
    finally:
        for path in created:
            path.unlink(missing_ok=True)
    glued = {o["metadata"]["scrapbook"]["name"]: o["data"] for c in notebook["cells"]
             for o in c.get("outputs", []) if "scrapbook" in o.get("metadata", {})}
    # the README sets orbit_altitude = 500e3 m: the page glues it in km
    assert glued["orbit-alt-km"]["application/papermill.record/text/plain"] == "500.0"
