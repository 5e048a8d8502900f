"""pytest set-up for the whole repository (tests/ and the library's doctests).

The suite is hermetic: a whole-book overrides file named by ``$MAGBENCH_PARAMS`` (for
example by ``make test PARAMS=...``) would change every chapter's inputs under the
tests, which check the sources' own values. Tests that need overrides set the
variable themselves (monkeypatch) or pass ``overrides=`` explicitly.
"""

import os


def pytest_configure(config):
    os.environ.pop("MAGBENCH_PARAMS", None)
