"""Drivers by importable name: what a case file records of the drivers that produced a failure.

Why: a failure found with a ``pytest_roadlogic_driver`` hook (the vehicle under test driven by the
user's planner) must replay with the same drivers under ``roadlogic replay``, which knows nothing
of the hook. The plugin records, per vehicle, the class of the driver the hook gave
(``module:QualName``); a replay outside pytest builds the same classes again, and one that cannot
says so rather than run other drivers.
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Iterable
from pathlib import Path

from .interface import DriverFactory


class DriverLoadError(RuntimeError):
    """A recorded driver that cannot be built here: its module does not import, or its class needs arguments."""


def importable_name(driver: object) -> str:
    """``module:QualName`` of ``driver``'s class."""
    cls = type(driver)
    return f"{cls.__module__}:{cls.__qualname__}"


class RecordingDrivers:
    """A driver factory that remembers which class drove which vehicle (``names``)."""

    def __init__(self, factory: DriverFactory) -> None:
        self.factory = factory
        self.names: dict[str, str] = {}

    def __call__(self, vehicle: str):
        driver = self.factory(vehicle)
        if driver is not None:
            self.names[vehicle] = importable_name(driver)
        return driver


def drivers_from_names(names: dict[str, str], search: Iterable[Path] = ()) -> DriverFactory:
    """A factory that builds, per vehicle, the recorded class with no arguments.

    ``search``: folders to import from when a module is not importable as it is (pytest put the
    rootdir and the conftest folders on ``sys.path`` when the case was found). Raises
    ``DriverLoadError`` naming the vehicle and the class when one cannot be built.
    """
    classes = {vehicle: _load(vehicle, name, search) for vehicle, name in sorted(names.items())}
    for vehicle, cls in classes.items():
        try:
            cls()
        except Exception as error:  # a user's class: any exception means it cannot be built here
            raise DriverLoadError(
                f"the driver of {vehicle}, {names[vehicle]}, cannot be built without arguments ({type(error).__name__}: {error})"
            ) from None
    return lambda vehicle: classes[vehicle]() if vehicle in classes else None


def _load(vehicle: str, name: str, search: Iterable[Path]) -> type:
    module_name, _, qualname = name.partition(":")
    try:
        module = _import(module_name, search)
        target = module
        for part in qualname.split("."):
            target = getattr(target, part)
    except (ImportError, AttributeError) as error:
        raise DriverLoadError(
            f"the driver of {vehicle}, {name}, does not load here ({type(error).__name__}: {error})"
        ) from None
    return target


def _import(module_name: str, search: Iterable[Path]):
    try:
        return importlib.import_module(module_name)
    except ModuleNotFoundError as error:
        if error.name is None or not module_name.startswith(error.name):
            raise  # the module itself imports something missing: not a matter of the path
    added = [str(folder) for folder in search if str(folder) not in sys.path]
    sys.path[:0] = added
    try:
        return importlib.import_module(module_name)
    finally:
        for folder in added:
            sys.path.remove(folder)
