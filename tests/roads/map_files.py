"""What the road tests share: the project's test maps' folder, and writing a map or a scenario a
test makes."""

from __future__ import annotations

import importlib.util
import textwrap
from pathlib import Path

MAPS = Path(__file__).resolve().parents[2] / "scenarios" / "roads" / "maps"


def write(path: Path, text: str) -> Path:
    """``text``, dedented, as the file ``path``; the path."""
    path.write_text(textwrap.dedent(text).lstrip())
    return path


def recipe(folder: Path):
    """The map recipe ``make_maps.py`` of ``folder``, loaded as a module (its ``write(directory)``)."""
    spec = importlib.util.spec_from_file_location(f"make_maps_{folder.parent.name}", folder / "make_maps.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def one_road_map(path: Path, length: float, plan_view: str, lanes: str) -> Path:
    """A map of one road (id 1, ``length`` metres, outside junctions) whose ``<planView>`` and
    ``<lanes>`` hold ``plan_view`` and ``lanes``, as the file ``path``; the path."""
    return write(
        path,
        f"""
        <?xml version="1.0"?>
        <OpenDRIVE><header/>
        <road id="1" length="{length}" junction="-1"><planView>{plan_view}</planView>
        <lanes>{lanes}</lanes></road>
        </OpenDRIVE>
        """,
    )
