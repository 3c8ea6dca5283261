"""Where a campaign's independent jobs run: in this process, on a local process pool, or on a Ray
cluster, each behind one protocol (``protocol.Executor``) and each giving the serial run's results
in its order."""

from __future__ import annotations

from .processes import ProcessExecutor
from .protocol import Call, Executor, ExecutorError, Job
from .serial import SerialExecutor

__all__ = ["Call", "Executor", "ExecutorError", "Job", "ProcessExecutor", "SerialExecutor", "executor"]


def executor(jobs: int = 1, ray: str | None = None) -> Executor:
    """The executor a campaign's options ask for: ``ray`` (a cluster address, or ``local``), or
    ``jobs`` processes of this machine (1: serial, in this process); ``ExecutorError`` for both."""
    if ray is not None and jobs > 1:
        raise ExecutorError("--jobs runs the jobs on this machine's processes, --ray on a cluster's: give one of them")
    if ray is not None:
        from .ray_cluster import RayExecutor

        return RayExecutor(ray)
    return ProcessExecutor(jobs) if jobs > 1 else SerialExecutor()
