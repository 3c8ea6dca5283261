"""Project-wide pytest configuration: Hypothesis profiles for local runs and CI.

The roadlogic plugin itself is registered through the ``pytest11`` entry point, not here, so
that it works the same for users who install the package.
"""

import os

from hypothesis import HealthCheck, settings

settings.register_profile("ci", max_examples=50, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("dev", max_examples=50, deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")
