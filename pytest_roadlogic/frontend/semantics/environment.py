"""The environment actor: the weather and light a scenario asks for, read, checked and set aside.

A field of type ``environment`` (``env: environment``), or the name ``environment`` itself as the
standard's examples write it (``environment.rain(intensity: 5kph)``), is the scenario's
environment. Its actions are the standard library's (``stdlib/osc/environment.osc``): their
arguments are bound and type-checked as declared there, and each use gets one located warning that
the simulation does not model it. They set a state rather than take time, so they leave the
behavior before anything is planned (``without_environment``): what the vehicles are asked is
planned and checked as if they were not written. An environment action the library does not
declare is read the same way, with a warning that names the ones it knows.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable
from dataclasses import replace

from .. import model
from ..syntax.standard_library import LazyTable
from . import library

ENVIRONMENT_TYPE = "environment"
# the name the standard's examples give the environment without declaring it
IMPLICIT_ENVIRONMENT = "environment"


def _parameter(name: str, declared_type: str, enums) -> library.Parameter:
    kind = f"enum:{declared_type}" if declared_type in enums else declared_type
    return library.Parameter(name, kind, positional=name != "duration")


# each environment action of the standard library, as a signature the checker binds against
ENVIRONMENT_ACTIONS: dict[str, library.Signature] = LazyTable(
    lambda standard: {
        name: library.Signature(
            name, tuple(_parameter(p, t, standard.enums) for p, t in declared.parameters), description=name
        )
        for name, declared in standard.actions.items()
        if declared.owner == ENVIRONMENT_TYPE
    }
)


class EnvironmentActions:
    """A part of the checker (``checker._Checker``): its state is the checker's."""

    def _environment_action(self, node: model.Invocation, scenario, env, used_actors, used_names) -> None:
        """Check an action of the environment ``node.actor`` and warn that it is not simulated."""
        what = f"{node.actor}.{node.action}()"
        signature = ENVIRONMENT_ACTIONS.get(node.action)
        if self.registry.action(node.action) is not None:
            self.error(
                node.location,
                f"{what}: {node.action}() is an action of a vehicle, and {node.actor!r} is the environment",
                self._known("environment actions", list(ENVIRONMENT_ACTIONS)),
            )
        elif signature is None:
            self.warning(
                node.location,
                f"{what} is read but not simulated, its arguments unchecked: this tool does not know that environment action",
                self._known("environment actions", list(ENVIRONMENT_ACTIONS)),
            )
        else:
            self._arguments(signature, node.arguments, node.location, scenario, env, used_actors, used_names, what)
            self.warning(
                node.location,
                f"{what} is read but not simulated: the simulation has no weather or light",
                "the vehicles' actions are planned and checked as if it were not written; remove it to silence this warning",
            )
        for modifier in node.modifiers:
            self.error(
                modifier.location,
                f"{modifier.name}() on {what}: an environment action takes no modifiers",
                "give its values as arguments",
            )
        for constraint in node.constraints:
            self.error(
                constraint.location,
                f"not supported: keep() on {what}",
                "give it a duration: argument (an environment action takes no time without one)",
            )
        if node.until is not None:
            self.error(
                node.location,
                f"not supported: until on {what}",
                "give it a duration: argument (an environment action takes no time without one)",
            )


def environment_names(fields: Iterable[str], declared: Collection[str]) -> frozenset[str]:
    """The names that stand for a scenario's environment: its ``fields`` of type ``environment``,
    and ``environment`` itself unless the scenario ``declared`` a field of that name."""
    implicit = () if IMPLICIT_ENVIRONMENT in declared else (IMPLICIT_ENVIRONMENT,)
    return frozenset((*fields, *implicit))


def without_environment(behaviors: tuple[model.Behavior, ...], names: frozenset[str]) -> tuple[model.Behavior, ...]:
    """``behaviors`` without the actions of the environment ``names``, but for the time one given a
    ``duration:`` takes (a wait of that long, under its label); a composition left with no member
    goes too. A labelled one whose start or end the scenario waits for (``@wet.end``) leaves
    those events where it stood: the serial that marks them (``builtin_events``) gives way to its
    emits, which happen at that instant of its parent."""
    kept: list[model.Behavior] = []
    for behavior in behaviors:
        if isinstance(behavior, model.Invocation) and behavior.actor in names:
            duration = behavior.argument("duration")
            if duration is not None:
                # given a duration, it lasts that long: a wait for it, under its label
                elapsed = model.Call(
                    "elapsed", (model.Argument(None, duration.value, duration.location),), duration.location
                )
                kept.append(model.Wait(elapsed, behavior.label, behavior.location))
            continue
        if isinstance(behavior, model.Composition):
            children = without_environment(behavior.children, names)
            if children != behavior.children:
                if all(isinstance(child, model.Emit) for child in children):
                    kept.extend(children)  # none left, or only the events it marked
                    continue
                behavior = replace(behavior, children=children)
        kept.append(behavior)
    return tuple(kept)
