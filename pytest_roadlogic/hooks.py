"""Hooks a user's ``conftest.py`` can implement to take part in scenario runs."""

import pytest


@pytest.hookspec(firstresult=True)
def pytest_roadlogic_driver(config, scenario, vehicle):
    """Return the driver of ``vehicle`` in ``scenario`` (an object with the
    ``pytest_roadlogic.simulation.Driver`` methods ``start`` and ``plan``), or ``None`` to let the
    default frenetix driver drive it. This is where the vehicle under test gets its own planner.

    Called once per vehicle and simulation, so a driver may keep state for one run.
    """


@pytest.hookspec(firstresult=True)
def pytest_roadlogic_simulator(config, scenario):
    """Return the simulation backend for ``scenario`` (an object with ``name`` and
    ``simulate(plan, limits, drivers)``, see ``pytest_roadlogic.simulation.Simulator``), or
    ``None`` to use the one ``--roadlogic-simulator`` names (default: frenetix).

    Called once per scenario item.
    """


@pytest.hookspec(firstresult=True)
def pytest_roadlogic_oracles(config, scenario):
    """Return the oracles' thresholds for ``scenario`` (a checked scenario: ``scenario.name``) as
    a mapping of option names to values, ``{"min-ttc": 2.0, "min-gap": 3, "max-decel": 6}``, or
    ``None`` for the session's (``--roadlogic-min-ttc`` and the others, or their ini keys). A
    ``conftest.py`` beside a folder of scenarios judges its vehicle under test by its own:

        def pytest_roadlogic_oracles(config, scenario):
            return {"min-ttc": 2.5} if scenario.name == "cut_in" else None
    """


@pytest.hookspec(firstresult=True)
def pytest_roadlogic_dialect(config, path):
    """Return the dialect ``path`` (an .osc file) is written in, ``"standard"`` or ``"carla"``, or
    ``None`` to use the one ``--roadlogic-dialect`` names (default: standard). A ``conftest.py`` next
    to a folder of CARLA scenario-runner files makes them read in that dialect:

        def pytest_roadlogic_dialect(config, path):
            return "carla"
    """
