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


def pytest_collection_modifyitems(config, items):
    if config.getoption("--run-bench"):
        return
    import pytest

    skip = pytest.mark.skip(reason="the full evaluation takes about 6 minutes; select it with --run-bench")
    for item in items:
        if "bench" in item.keywords:
            item.add_marker(skip)
