"""Every case of the fault corpus ends cleanly: a clear error (or a correct result), no
traceback, no file left behind, no input modified (see tests/faults/corpus.py)."""

from __future__ import annotations

import pytest

from .cases import cases
from .corpus import check
from .fixtures import build

CASES = cases()


@pytest.fixture(scope="module")
def good(tmp_path_factory):
    return build(tmp_path_factory.mktemp("faults") / "good")


def test_corpus_is_big_enough():
    assert len(CASES) >= 300
    assert len({c.id for c in CASES}) == len(CASES)


@pytest.mark.timeout(120)
@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_case_ends_cleanly(case, good, tmp_path):
    outcome = check(case, good, tmp_path / "work")
    assert not outcome.problems, f"{outcome.problems}\nexit {outcome.rc}\n{outcome.stderr[-2000:]}"
