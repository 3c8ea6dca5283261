"""Events a scenario declares, emits and waits for: their specifications and elapsed-time conditions."""

from __future__ import annotations

from .. import model
from ..errors import OscError, SourceLocation
from ..syntax.units import TIME
from .builtin_events import EDGES
from .values import EvaluationError, Interval, describe, evaluate


class EventChecks:
    """A part of the checker (``checker._Checker``): its state is the checker's."""

    def _event_specification(
        self, spec, scenario: model.Scenario, env: dict, location: SourceLocation, waits: bool = False
    ) -> None:
        """An event reference or a condition (``constructs.conditions`` says which ones the tool reads);
        ``waits``: it is a ``wait``'s, which may also be ``elapsed(t)``."""
        if isinstance(spec, model.EventReference):
            events = {e.name: e for e in scenario.events}
            if spec.name not in events:
                label, _, edge = spec.name.rpartition(".")
                if edge in EDGES:  # with_builtin_events declared those of every labelled phase
                    labels = sorted(
                        {n.label for b in scenario.behaviors for n in model.walk(b) if getattr(n, "label", None)}
                    )
                    self.error(
                        spec.location,
                        f"@{spec.name} is the {edge} of the phase labelled {label!r}, and no phase has that label",
                        f"label the phase ({label}: ...); labels here: {', '.join(labels) or 'none'}",
                    )
                else:
                    self.error(spec.location, f"unknown event {spec.name!r}", f"declare it: event {spec.name}")
                return
            declared = events[spec.name]
            if declared.specification is None and spec.name not in self._emitted(scenario):
                self.error(
                    spec.location,
                    f"nothing emits the event {spec.name!r}: this wait never ends",
                    f"emit it where it happens: emit {spec.name}",
                )
            if spec.condition is not None:
                self._event_specification(spec.condition, scenario, env, location)
            return
        if waits and isinstance(spec, model.Call) and spec.function == "elapsed":
            self._elapsed(spec, env)
            return
        try:
            self.registry.condition(spec, env, [a.name for a in scenario.actors])
        except OscError as error:
            for diagnostic in error.diagnostics:
                self.error(diagnostic.location, diagnostic.message, diagnostic.hint)

    @staticmethod
    def _emitted(scenario: model.Scenario) -> set[str]:
        return {
            node.event
            for behavior in scenario.behaviors
            for node in model.walk(behavior)
            if isinstance(node, model.Emit)
        }

    def _elapsed(self, call: model.Call, env: dict) -> None:
        if len(call.arguments) != 1 or call.arguments[0].name is not None:
            self.error(call.location, "elapsed() takes one time, e.g. elapsed(3s) or elapsed([2..4]s)")
            return
        try:
            value = evaluate(call.arguments[0].value, env)
        except EvaluationError as error:
            self.error(error.location, error.message, error.hint)
            return
        if not isinstance(value, Interval) or value.dimension != TIME:
            got = describe(value.dimension) if isinstance(value, Interval) else "a name"
            self.error(
                call.arguments[0].location, f"elapsed() expects a time, got {got}", "write it with a unit, e.g. 3s"
            )
