"""The documents are a guide: the README short enough to read, no history in any of them
(stops, commits, issues), and no repository path that does not exist."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCUMENTS = sorted(p for p in ROOT.rglob("*.md")
                   if not {".venv", ".porter_cache", "runs", "node_modules"} & set(p.parts)
                   and "blasfeo" not in p.parts and ".pytest_cache" not in p.parts)
TOP_LEVEL = ("core/", "drivers/", "deploy/", "logs/", "tests/", ".ci/")
HISTORY = [(r"\bstop \d+\b", "a stop number"), (r"\bissues? \d+\b", "an issue number"),
           (r"(?<![\w/])#\d+\b", "an issue reference"),
           (r"\b(?=[0-9a-f]*\d)(?=[0-9a-f]*[a-f])[0-9a-f]{7,40}\b", "a commit hash")]


def _paths(text: str) -> list[str]:
    """Repository paths a document names: in backticks or links, starting at a top-level room
    (placeholders such as ``<name>``, globs and paths outside the repository, such as the
    shared paper beside it, are left out)."""
    found = re.findall(r"`([^`\s]+)`", text) + re.findall(r"\]\(([^)\s]+)\)", text)
    paths = []
    for item in found:
        item = item.split("#")[0].rstrip(".,:;")
        if "<" in item or "*" in item or "://" in item or item.startswith("../"):
            continue
        if item.startswith(TOP_LEVEL) or item.endswith(".md"):
            paths.append(item)
    return paths


def test_the_readme_is_a_guide_of_at_most_450_lines() -> None:
    text = (ROOT / "README.md").read_text()
    assert len(text.splitlines()) <= 450
    for heading in ("Set-up", "tour", "Where next"):
        assert heading in text


@pytest.mark.parametrize("document", DOCUMENTS, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_history_in_a_document(document: Path) -> None:
    text = document.read_text()
    found = [f"{what}: {m.group(0)!r}" for pattern, what in HISTORY
             for m in re.finditer(pattern, text, re.IGNORECASE)]
    assert not found


@pytest.mark.parametrize("document", DOCUMENTS, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_path_a_document_names_exists(document: Path) -> None:
    missing = [path for path in _paths(document.read_text())
               if not (ROOT / path).exists() and not (document.parent / path).exists()]
    assert not missing


def test_the_path_check_can_fail() -> None:
    assert _paths("see `deploy/no_such_module.py` and [x](core/README.md)") == [
        "deploy/no_such_module.py", "core/README.md"]
    assert not (ROOT / "deploy/no_such_module.py").exists()
