"""Stage 5: the runtime monitor (``monitor``), from an automaton and a trace to a ``Verdict``."""

from .monitor import GuardMiss, Verdict, monitor

__all__ = ["GuardMiss", "Verdict", "monitor"]
