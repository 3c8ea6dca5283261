"""The registry of OS2 constructs: one specification per action or modifier, read by the checker
and by the automaton. Adding a construct is writing one class; neither stage changes."""

import math

import pytest

from pytest_roadlogic.automaton import SPEED, Bound, Term, build_automaton
from pytest_roadlogic.constructs import STANDARD, AnchoredModifier, Registry
from pytest_roadlogic.frontend import OscError, check_text
from pytest_roadlogic.frontend.semantics.library import AT, Parameter, Signature
from pytest_roadlogic.frontend.syntax.units import SPEED as SPEED_DIMENSION


class AtLeast(AnchoredModifier):
    """A toy modifier: ``at_least(v)``, the actor's speed is v or more (20 m/s at most, say)."""

    signature = Signature("at_least", (Parameter("speed", "speed", positional=True), AT), required=(("speed",),))

    def check(self, binding, context):
        value = context.evaluate(binding["speed"]) if binding["speed"] is not None else None
        if value is not None and value.high > 20:
            context.error(binding["speed"].location, "at_least() takes at most 20 m/s here")

    def guard(self, use):
        low, _ = use.range("speed", SPEED_DIMENSION, "a speed such as 10mps")
        return Bound(Term(SPEED, use.actor), low, math.inf, use.location)


TOY = "scenario s:\n  a: car\n  do a.drive() with:\n    at_least({speed})\n"


def messages(text, registry=None):
    return [
        f"{d.location.line}:{d.location.column}: {d.message}"
        for d in check_text(text, "t.osc", registry=registry).errors
    ]


def test_a_modifier_added_to_a_registry_is_checked_and_translated_by_it_alone():
    registry = STANDARD.extended(AtLeast())
    checked = check_text(TOY.format(speed="15mps"), "t.osc", registry=registry)
    assert not checked.errors, checked.report()
    automaton = build_automaton(checked.scenarios[0])
    (phase,) = [loc for loc in automaton.locations if loc.name == "a.drive"]
    assert str(phase.invariant) == "v(a) >= 15", "no at: means throughout the phase, as for every anchored modifier"


def test_the_checker_binds_and_type_checks_a_registered_construct_from_its_signature():
    registry = STANDARD.extended(AtLeast())
    assert messages(TOY.format(speed="15m"), registry) == ["4:14: at_least() expects a speed for speed, got a length"]
    assert messages(TOY.format(speed="25mps"), registry) == ["4:14: at_least() takes at most 20 m/s here"], (
        "its own check() runs"
    )
    assert messages("scenario s:\n  a: car\n  do a.drive() with:\n    at_least(fast: 1mps)\n", registry)[0].startswith(
        "4:14: unknown argument 'fast'"
    )


def test_without_the_construct_the_same_file_names_it_unknown():
    assert messages(TOY.format(speed="15mps")) == ["4:5: unknown modifier 'at_least'"]
    assert "at_least" not in STANDARD.modifiers, "extending a registry copies it"


class Pending(AtLeast):
    """A toy modifier the checker accepts and the automaton does not translate yet (tier 2)."""

    translated = False


def test_a_construct_that_is_not_translated_yet_checks_and_is_refused_by_the_automaton_at_its_place():
    registry = STANDARD.extended(Pending())
    checked = check_text(TOY.format(speed="15mps"), "t.osc", registry=registry)
    assert not checked.errors, checked.report()
    with pytest.raises(OscError) as refused:
        build_automaton(checked.scenarios[0])
    assert "t.osc:4:5: error: not supported yet by the automaton: modifier 'at_least'" in refused.value.report()


def test_every_standard_construct_has_a_described_signature_and_a_home():
    for construct in [*STANDARD.actions.values(), *STANDARD.modifiers.values()]:
        assert construct.signature.name == construct.name
        assert type(construct).__module__.startswith("pytest_roadlogic.constructs."), construct
        if construct.translated:
            assert type(construct).translate is not AnchoredModifier.translate or hasattr(construct, "guard"), construct


def test_a_registry_keeps_actions_and_modifiers_of_the_same_name_apart():
    registry = Registry([STANDARD.action("change_lane"), STANDARD.modifier("change_lane")])
    assert registry.action("change_lane").kind == "action" and registry.modifier("change_lane").kind == "modifier"
    assert registry.action("change_lane").signature.parameter("reference") is not None
    assert registry.modifier("change_lane").signature.parameter("reference") is None
