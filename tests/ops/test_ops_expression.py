"""PDAL expressions: precedence, arithmetic, types, names and errors, never eval."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.io import read_cloud, write_cloud
from workstation.ops.expression import compile_expression, filter_expression


@pytest.fixture
def cloud():
    n = 8
    return Cloud(np.column_stack([np.arange(n), np.arange(n) * 2.0, np.arange(n) % 3]),
                 {"classification": [2, 2, 5, 6, 2, 1, 2, 9], "return_number": [1, 2, 1, 1, 1, 3, 2, 1],
                  "number_of_returns": [1, 2, 2, 1, 3, 3, 2, 1], "intensity": [10, 200, 30, 400, 50, 600, 70, 800],
                  "rgb": np.tile([[1, 2, 3]], (n, 1)) * np.arange(1, n + 1)[:, None], "treeID": np.arange(n) + 100})


@pytest.mark.parametrize("expr, expected", [
    ("Classification == 2 && ReturnNumber == 1", [0, 4]),
    ("Classification == 2 || Classification == 5 && Intensity > 100", [0, 1, 4, 6]),  # && binds tighter
    ("(Classification == 2 || Classification == 5) && Intensity < 40", [0, 2]),
    ("!(NumberOfReturns == 1)", [1, 2, 4, 5, 6]),
    ("NumberOfReturns > 1 && ReturnNumber == 1", [2, 4]),
    ("X * 2 == Y && X - 1 >= 5", [6, 7]),  # arithmetic binds tighter than comparisons
    ("Intensity / 100 > 5.5", [5, 7]),
    ("Z == 0 && -X < -5", [6]),
    ("Red == 3 && Blue == 9", [2]),
    ("classification == 9", [7]),  # any case
    ("return_number == 3", [5]),  # canonical names
    ("treeID >= 106", [6, 7]),  # extra-byte names
    ("X > 1e0 && X <= .5e1", [2, 3, 4, 5]),
])
def test_expressions(cloud, expr, expected):
    assert np.flatnonzero(compile_expression(expr)(cloud)).tolist() == expected


@pytest.mark.parametrize("expr, message", [
    ("Clasification == 2", "unknown dimension 'Clasification'"),
    ("Classification == 2 &&", "unexpected end"),
    ("(Classification == 2", "missing ')'"),
    ("Classification = 2", "unexpected character"),
    ("Intensity > 0 && Classification", "joins comparisons"),
    ("!Classification", "'!' needs a comparison"),
    ("Intensity + 2", "numbers, not a condition"),
    ("(X > 1) + 2 > 0", "takes numbers"),
    ("__import__('os').system('true')", "unexpected character"),
    ("", "empty"),
])
def test_errors(cloud, expr, message):
    with pytest.raises(InvalidInputError, match=message.replace("(", r"\(").replace(")", r"\)")):
        compile_expression(expr)(cloud)


def test_unknown_dimension_lists_the_valid_ones(cloud):
    with pytest.raises(InvalidInputError) as e:
        compile_expression("GpsTime > 0")(cloud)
    assert "Classification" in e.value.hint and "ReturnNumber" in e.value.hint and "treeID" in e.value.hint


def test_filter_stage_and_cli(tmp_path, cloud, capsys):
    assert filter_expression(cloud, "Classification == 2").n == 4
    src = tmp_path / "in.laz"
    write_cloud(cloud.without_attrs("treeID"), src)
    out = tmp_path / "g.laz"
    assert main(["filter", str(src), "-o", str(out), "--expr", "Classification == 2 && ReturnNumber == 1"]) == 0
    assert read_cloud(out).xyz[:, 0].tolist() == [0.0, 4.0]
    assert main(["filter", str(src), "-o", str(tmp_path / "x.laz"), "--expr", "Classification == 99"]) == 1
    assert main(["filter", str(src), "-o", str(tmp_path / "x.laz"), "--expr", "Foo == 1"]) == 1
    err = capsys.readouterr().err
    assert "unknown dimension 'Foo'" in err and not (tmp_path / "x.laz").exists()
