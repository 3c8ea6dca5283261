"""Writing a file so that an interrupted run never leaves a half-written one behind."""

from __future__ import annotations

import os
from pathlib import Path


def write_text(path: Path, text: str) -> Path:
    temporary = path.parent / f".{path.name}.{os.getpid()}.partial"
    temporary.write_text(text, encoding="utf-8")
    os.replace(temporary, path)
    return path
