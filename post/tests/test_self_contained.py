"""The repository is self-contained: nothing refers to notes or data outside it, and the copies of
the paper's Table 3 agree."""
from __future__ import annotations

import re
import subprocess
from pathlib import Path


REPO = Path(__file__).resolve().parents[2]
_NOTES = "MODEL" + "_NOTES"          # spelled in two parts so that this file does not match itself
_SHARED = "sha" + "red/"
PATTERN = re.compile(re.escape(_NOTES) + "|" + re.escape(_SHARED))


def _tracked_files() -> list[Path]:
    try:
        out = subprocess.run(["git", "ls-files"], cwd=REPO, capture_output=True, text=True, check=True).stdout
        return [REPO / p for p in out.splitlines()]
    except (OSError, subprocess.CalledProcessError):
        skip = {".git", "build", ".venv", "__pycache__"}
        return [p for p in REPO.rglob("*") if p.is_file() and not skip & set(p.relative_to(REPO).parts)]


def test_no_reference_outside_the_repository():
    hits = []
    for p in _tracked_files():
        if not p.is_file() or p.suffix in (".png", ".h5", ".gif", ".mp4", ".pdf"):
            continue
        rel = p.relative_to(REPO).as_posix()
        try:
            text = p.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        for n, line in enumerate(text.splitlines(), 1):
            if PATTERN.search(line):
                hits.append(f"{rel}:{n}: {line.strip()}")
    assert not hits, "references outside the repository:\n" + "\n".join(hits)


def test_table3_copies_agree():
    a = (REPO / "post" / "landyn_post" / "data" / "table3_crush_lengths.csv").read_bytes()
    b = (REPO / "tests" / "regression" / "data" / "table3_crush_lengths.csv").read_bytes()
    assert a == b


def test_conventions_page_is_linked():
    assert (REPO / "docs" / "model_conventions.md").is_file()
    for rel in ("README.md", "docs/theory.md", "input/default.nml"):
        assert "model_conventions.md" in (REPO / rel).read_text(encoding="utf-8"), rel
