"""Each chapter's test module names its chapter (``CHAPTER_KEY``) and the printed values
it expects not to reproduce (``EXPECTED_ERRATA``); a test taking ``printed_check`` runs
once per printed-value check of that chapter, strict xfail for the expected errata."""

import pytest

from magbench.chapters import source_checks


def pytest_generate_tests(metafunc):
    if "printed_check" not in metafunc.fixturenames:
        return
    key, expected = metafunc.module.CHAPTER_KEY, metafunc.module.EXPECTED_ERRATA
    params = []
    for check in source_checks(key):
        marks = pytest.mark.xfail(strict=True, reason=expected[check.id]) if check.id in expected else ()
        params.append(pytest.param(check, id=check.id, marks=marks))
    metafunc.parametrize("printed_check", params)
