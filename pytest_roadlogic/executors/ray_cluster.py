"""A Ray cluster: each job a Ray task of one CPU, on whichever node has one free.

Ray is an optional dependency (the ``[ray]`` extra) and is imported only here, when a campaign is
given ``--ray ADDRESS``: a running cluster's address (``HOST:PORT`` of its head, ``auto`` for the
one this machine belongs to, ``ray://HOST:10001`` through Ray's client), or ``local`` to start a
cluster of this machine's CPUs for the run. Every node must run the versions this process runs
(the package and what a result depends on: ``case.VERSIONED``), or its results would not be the
serial run's; they are compared before the first job. The nodes read the scenario files and write
artifacts at the paths this process gives (a file system shared by the nodes, as on most clusters).
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Iterator, Sequence
from typing import Any

from .protocol import Call, ExecutorError, largest_first

LOCAL = "local"  # --ray local: a cluster of this machine, started for the run


def node_versions() -> dict[str, str]:
    """The versions a node runs (a Ray task's result)."""
    from ..case import installed_versions

    return installed_versions()


CONNECT_SECONDS = 5.0  # a head that does not answer a connection within this is not there


def _unreachable(address: str) -> str:
    """Why nothing listens at a ``HOST:PORT`` or ``ray://HOST:PORT`` address ('' when something
    does, or for ``local`` and ``auto``, which Ray finds itself): Ray itself waits minutes for a
    head that is not there before it gives up."""
    import socket

    if address in (LOCAL, "auto"):
        return ""
    host, _, port = address.removeprefix("ray://").rpartition(":")
    if not host or not port.isdigit():
        return "not HOST:PORT"
    try:
        with socket.create_connection((host.strip("[]"), int(port)), timeout=CONNECT_SECONDS):
            return ""
    except OSError as error:
        return error.strerror or str(error) or type(error).__name__


class RayExecutor:
    name = "ray"

    def __init__(self, address: str) -> None:
        self.address = address
        self._ray: Any = None
        self._started_here = False
        self._pending: list[Any] = []

    def workers(self) -> int:
        return max(1, int(self._ray.cluster_resources().get("CPU", 1)))

    def describe(self) -> str:
        nodes = [n for n in self._ray.nodes() if n.get("Alive")]
        return f"Ray at {self.address}: {len(nodes)} node{'s' * (len(nodes) != 1)}, {self.workers()} CPUs"

    def results(self, calls: Sequence[Call], sizes: Sequence[float] | None = None) -> Iterator[Any]:
        ray = self._ray
        tasks: dict[Callable[..., Any], Any] = {}  # one remote function per function called
        references = {}
        for k in largest_first(len(calls), sizes):
            function, arguments = calls[k]
            # spread over the nodes: Ray's default packs the tasks queued at once onto the node
            # that submits them until it is busy, and the others finish early
            if function not in tasks:
                tasks[function] = ray.remote(num_cpus=1, max_retries=0, scheduling_strategy="SPREAD")(function)
            references[k] = tasks[function].remote(*arguments)
        self._pending = list(references.values())
        for k in range(len(calls)):
            yield ray.get(references[k])
        self._pending = []

    def __enter__(self) -> RayExecutor:
        try:
            import ray
        except ImportError:
            raise ExecutorError(
                "Ray is not installed: install the extra, pip install 'pytest-roadlogic[ray]', on this machine "
                "and on every node of the cluster"
            ) from None
        self._ray = ray
        if not ray.is_initialized():
            unreachable = _unreachable(self.address)
            if unreachable:
                raise ExecutorError(
                    f"no Ray cluster answers at {self.address!r} ({unreachable}); give the address its head "
                    "printed (ray start --head), 'auto' on one of its nodes, or 'local'"
                )
            try:
                ray.init(
                    address=None if self.address == LOCAL else self.address,
                    logging_level=logging.ERROR,
                    log_to_driver=False,
                    **({"include_dashboard": False} if self.address == LOCAL else {}),
                )
            except Exception as error:  # Ray raises ConnectionError, RuntimeError, ValueError, ...
                why = (str(error).strip().splitlines() or [type(error).__name__])[0]
                raise ExecutorError(
                    f"cannot connect to a Ray cluster at {self.address!r} ({why}); give the "
                    "address its head printed (ray start --head), 'auto' on one of its nodes, or 'local'"
                ) from None
            self._started_here = True
        try:
            self._check_versions()
        except BaseException:
            self.__exit__()
            raise
        return self

    def _check_versions(self) -> None:
        """Refuse a cluster a node of which runs other versions than this process."""
        from ray.util.scheduling_strategies import NodeAffinitySchedulingStrategy

        here = node_versions()
        ray = self._ray
        probe = ray.remote(num_cpus=0, max_retries=0)(node_versions)
        nodes = [n for n in ray.nodes() if n.get("Alive")]
        answers = ray.get(
            [
                probe.options(scheduling_strategy=NodeAffinitySchedulingStrategy(n["NodeID"], soft=False)).remote()
                for n in nodes
            ]
        )
        for node, there in zip(nodes, answers, strict=True):
            differ = [
                f"{name} {there.get(name, 'missing')} (here {version})"
                for name, version in here.items()
                if there.get(name) != version
            ]
            if differ:
                raise ExecutorError(
                    f"the Ray node at {node.get('NodeManagerAddress', '?')} runs other versions than this "
                    f"process: {', '.join(differ)}; install the same ones on every node"
                )

    def __exit__(self, *exc: object) -> None:
        ray = self._ray
        if ray is None:
            return
        for reference in self._pending:  # an interrupt or a failed job: the rest are not run
            ray.cancel(reference, force=True)
        self._pending = []
        if self._started_here:
            ray.shutdown()
            self._started_here = False
