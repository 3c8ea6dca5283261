"""ASAM's own checkers on what the project writes: its test maps, and the road.xodr and
scenario.xosc of a run on the straight road and on a map.

    python benchmarks/asam_checks.py --checkers /path/to/venv/bin [--out /tmp/asam]

ASAM's checkers (PyPI ``asam-qc-opendrive``, ``asam-qc-openscenarioxml``, with
``asam-qc-framework``) pin versions of their own, so they live in a virtual environment of their
own: ``python -m venv qc && qc/bin/pip install asam-qc-opendrive asam-qc-openscenarioxml
asam-qc-framework``, then ``--checkers qc/bin``. Prints, per file, the number of issues the
checker reported (0: it passes) and the first few.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CONFIG = """<?xml version="1.0" encoding="UTF-8"?>
<Config>
  <Param name="InputFile" value="{input}"/>
  <CheckerBundle application="{bundle}">
    <Param name="resultFile" value="{result}"/>
  </CheckerBundle>
</Config>
"""


def check(checkers: Path, path: Path) -> tuple[int, list[str]]:
    """(issues, their descriptions) of ASAM's checker for ``path`` (.xodr or .xosc)."""
    bundle, command = ("xodrBundle", "qc_opendrive") if path.suffix == ".xodr" else ("xoscBundle", "qc_openscenario")
    with tempfile.TemporaryDirectory() as folder:
        result = Path(folder) / "result.xqar"
        config = Path(folder) / "config.xml"
        config.write_text(CONFIG.format(input=path.resolve(), bundle=bundle, result=result))
        subprocess.run([str(checkers / command), "-c", str(config)], cwd=folder, capture_output=True, check=False)
        if not result.exists():
            return -1, [f"the checker wrote no result ({checkers / command})"]
        text = result.read_text()
    issues = re.findall(r"<Issue [^>]*description=\"([^\"]*)\"", text)
    return len(issues), issues[:3]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--checkers", type=Path, required=True, help="the bin folder holding qc_opendrive")
    parser.add_argument("--out", type=Path, default=Path(tempfile.mkdtemp(prefix="asam-")))
    args = parser.parse_args()
    files = sorted((ROOT / "scenarios" / "roads" / "maps").glob("*.xodr"))
    files += sorted((ROOT / "scenarios" / "junctions" / "maps").glob("*.xodr"))
    for name, extra in (("straight", []), ("curved", ["--map", "scenarios/roads/maps/curved_highway.xodr"])):
        out = args.out / name
        subprocess.run(
            [sys.executable, "-m", "pytest_roadlogic.cli", "run", "scenarios/overtake.osc", "--out", str(out), *extra],
            cwd=ROOT,
            capture_output=True,
            check=True,
        )
        files += [out / "road.xodr", out / "scenario.xosc"]
    for path in files:
        count, issues = check(args.checkers, path)
        shown = path.relative_to(ROOT) if path.is_relative_to(ROOT) else path
        print(f"{str(shown):<60} {count:>3} issues" + "".join(f"\n    {issue}" for issue in issues))


if __name__ == "__main__":
    main()
