"""MkDocs hooks of the user guide (mkdocs.yml ``hooks:``).

The package's docstrings are numpydoc with Sphinx cross-reference roles (:class:`Cloud`,
:func:`~workstation.io.read_cloud`); mkdocstrings renders them as Markdown, where a role is
literal text. This hook drops the role (and a leading ``~``, keeping the last dotted name, as
Sphinx shows it) so the API pages read ``Cloud`` instead of ``:class:`Cloud```.
"""

from __future__ import annotations

import re

_ROLE = re.compile(r":(?:py:)?(?:class|mod|func|meth|data|attr|exc|obj|const|ref|term|math):<code>(~?)([^<]*)</code>")


def _plain(m: re.Match) -> str:
    name = m.group(2)
    if m.group(1):
        name = name.rsplit(".", 1)[-1]
    return f"<code>{name}</code>"


def on_page_content(html: str, page, config, files) -> str:
    return _ROLE.sub(_plain, html)
