"""The user guide (docs/guide, mkdocs.yml): every command has a page, the generated pages match
the commands as they are now, the worked examples use options that exist and have recorded
output, pictures stay small, and the site builds with ``mkdocs build --strict`` (no broken
link or anchor, no docstring the API pages cannot render)."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
GUIDE = REPO / "docs" / "guide"


@pytest.fixture(scope="module")
def gen():
    spec = importlib.util.spec_from_file_location("gen_cli_docs", REPO / "scripts" / "gen_cli_docs.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_every_command_has_a_page_in_the_nav():
    from workstation.cli.main import COMMANDS

    nav = (REPO / "mkdocs.yml").read_text()
    for name in COMMANDS:
        page = GUIDE / "commands" / f"{name}.md"
        assert page.is_file(), f"no page for `ws {name}`: run `make docs-pages`"
        assert f"commands/{name}.md" in nav, f"`ws {name}` is not in the nav of mkdocs.yml: run `make docs-pages`"
        assert (GUIDE / "_src" / "commands" / f"{name}.md").is_file(), f"`ws {name}` has no worked example"


def test_generated_pages_are_current(gen):
    pages, missing = gen.build_pages(gen.load_outputs())
    stale = sorted(str(p.relative_to(REPO)) for p, text in pages.items() if not p.exists() or p.read_text() != text)
    assert not stale, f"stale generated pages {stale}: run `make docs-pages`"
    assert not missing, f"examples without recorded output {missing}: run `make docs-examples`"


def test_examples_use_options_that_exist(gen):
    assert gen.example_option_errors() == []


def test_pictures_are_small_and_used():
    images = sorted((GUIDE / "img").glob("*.png"))
    assert images
    text = "".join(p.read_text() for p in GUIDE.rglob("*.md") if "_src" not in p.parts)
    for img in images:
        assert img.stat().st_size < 150_000, f"{img.name} is {img.stat().st_size} bytes"
        assert f"img/{img.name}" in text, f"{img.name} is not shown on any page"


def test_site_builds_strictly(tmp_path):
    for module in ("mkdocs", "material", "mkdocstrings", "mkdocstrings_handlers.python"):
        if importlib.util.find_spec(module.split(".")[0]) is None or importlib.util.find_spec(module) is None:
            pytest.skip(f"{module} is not installed (the `docs` extra: pip install -e '.[docs]')")
    site = tmp_path / "site"
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1")
    # no -q: it silences the warnings that --strict counts, so a broken link would pass
    p = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-f", str(REPO / "mkdocs.yml"),
                        "-d", str(site)], cwd=REPO, env=env, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stdout + p.stderr
    from workstation.cli.main import COMMANDS

    for name in COMMANDS:
        html = (site / "commands" / name / "index.html").read_text()
        assert f"ws {name}" in html and "Example" in html
    api = (site / "api" / "core" / "index.html").read_text()
    assert "workstation.core.cloud.Cloud" in api and "with_attrs" in api  # docstrings rendered
