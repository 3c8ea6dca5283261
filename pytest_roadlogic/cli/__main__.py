"""``python -m pytest_roadlogic.cli``: the ``roadlogic`` command."""

from . import main

raise SystemExit(main())
