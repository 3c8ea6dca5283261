from pathlib import Path

import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import check_file

# The corpus is data for test_corpus.py, not scenarios to simulate.
collect_ignore = ["corpus"]

ROOT = Path(__file__).resolve().parent.parent
OVERTAKE = ROOT / "scenarios" / "overtake.osc"


@pytest.fixture(scope="session")
def overtake():
    return check_file(OVERTAKE).scenarios[0]


@pytest.fixture(scope="session")
def overtake_automaton(overtake):
    return build_automaton(overtake)
