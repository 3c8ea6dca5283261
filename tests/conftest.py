from pathlib import Path

# loaded before any test: pytester drops the modules a test imported when it ends, and numpy's
# extension modules cannot be loaded twice in one process ("cannot load module more than once per
# process" in whichever test imported numpy.fft next, on the worker that ran a pytester test first)
import numpy.fft  # noqa: F401
import pytest

from pytest_roadlogic.automaton import build_automaton
from pytest_roadlogic.frontend import check_file

# The corpus is data for test_corpus.py, not scenarios to simulate.
collect_ignore = ["corpus", "scenarios"]

ROOT = Path(__file__).resolve().parent.parent
OVERTAKE = ROOT / "scenarios" / "overtake.osc"
# The paper's Listing 1 as published (the suite's overtake.osc starts its end gap at 8 m, see there).
PAPER_OVERTAKE = ROOT / "tests" / "corpus" / "01_overtake_paper.osc"


@pytest.fixture(scope="session")
def overtake():
    return check_file(PAPER_OVERTAKE).scenarios[0]


@pytest.fixture(scope="session")
def overtake_automaton(overtake):
    return build_automaton(overtake)


@pytest.fixture(autouse=True)
def _a_home_folder_beside_pytesters(request):
    """pytester makes its test folder the home folder; the tool never reads the whole home folder
    (confinement.too_wide), so files pytester writes there could not import or name a map. A
    separate home beside it keeps each test's folder what a user's project folder is."""
    if "pytester" not in request.fixturenames:
        yield
        return
    folder = request.getfixturevalue("pytester").path
    home = folder.parent / f"{folder.name}-home"
    home.mkdir(exist_ok=True)
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("HOME", str(home))
        yield


@pytest.fixture(scope="module")
def two_node_ray_cluster():
    """A Ray cluster of two nodes of one CPU each, on this machine, for one module's tests (its
    daemons take CPU while they run: stopped after the module); its address."""
    from ray.cluster_utils import Cluster

    cluster = Cluster(initialize_head=True, head_node_args={"num_cpus": 1, "include_dashboard": False})
    try:
        cluster.add_node(num_cpus=1)
        cluster.wait_for_nodes()
        yield cluster.address
    finally:
        cluster.shutdown()
