"""One HiGHS instance that prints nothing, for every linear program the planner solves (the
continuous encoding's lazy theory and the linear relaxation)."""

from __future__ import annotations

import os
import sys

import highspy

_BANNER_SILENCED = False


def quiet_highs() -> highspy.Highs:
    """A HiGHS instance that prints nothing. Its first construction in a process writes HiGHS's
    banner to the standard output from C++, before any option can be set (seen as two lines at the
    top of every `roadlogic run`), so that one construction runs with file descriptor 1 on /dev/null."""
    global _BANNER_SILENCED
    if _BANNER_SILENCED:
        solver = highspy.Highs()
    else:
        sys.stdout.flush()
        saved = os.dup(1)
        try:
            with open(os.devnull, "w") as null:
                os.dup2(null.fileno(), 1)
                solver = highspy.Highs()
        finally:
            os.dup2(saved, 1)
            os.close(saved)
        _BANNER_SILENCED = True
    solver.setOptionValue("output_flag", False)
    return solver
