"""Project-wide pytest configuration: Hypothesis profiles for local runs and CI.

The roadlogic plugin itself is registered through the ``pytest11`` entry point, not here, so
that it works the same for users who install the package.
"""

import os

from hypothesis import HealthCheck, settings

settings.register_profile(
    "ci", max_examples=50, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow]
)
settings.register_profile("dev", max_examples=50, deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")


def pytest_addoption(parser):
    parser.addoption(
        "--run-bench", action="store_true", help="also run the full evaluation (tests marked bench; about 6 minutes)"
    )
    parser.addoption(
        "--run-slow",
        action="store_true",
        help="also run the project's slow tests (marked slow; about 15 more minutes); -m selects by marker as usual",
    )


def pytest_collection_modifyitems(config, items):
    _deselect_slow_tests(config, items)
    if config.getoption("--run-bench"):
        return
    import pytest

    skip = pytest.mark.skip(reason="the full evaluation takes about 6 minutes; select it with --run-bench")
    for item in items:
        if "bench" in item.keywords:
            item.add_marker(skip)


def _deselect_slow_tests(config, items) -> None:
    """The project's own tests marked slow run only with ``--run-slow`` or a ``-m`` expression:
    the default test run stays under 15 minutes on two cores. Scenario items (which the plugin
    marks slow by their vehicles) are the user's to select, and are never deselected here."""
    if config.getoption("--run-slow") or config.getoption("markexpr"):
        return
    tests = config.rootpath / "tests"
    kept, slow = [], []
    for item in items:
        (slow if "slow" in item.keywords and item.path.is_relative_to(tests) else kept).append(item)
    if slow:
        config.hook.pytest_deselected(items=slow)
        items[:] = kept
