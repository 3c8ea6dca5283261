"""``python -m pytest_roadlogic.cli``: the ``roadlogic`` command."""

from . import command

command()
