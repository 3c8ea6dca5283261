"""Expression methods: a call of ``def name(p: T, ...) -> R is expression E`` is E with each
parameter bound to the call's argument (by position, by name, else the parameter's default),
whether called on a type (CARLA's ``speeds.compute(x:, y:)``), on a field of that type or as the
scenario's own; a call that cannot be bound, of a method with no body, or of an external method is
refused at the call."""

import pytest

from pytest_roadlogic.frontend import check_text
from pytest_roadlogic.frontend.semantics.values import Interval, evaluate

SPEEDS = "struct speeds:\n    def compute(x: speed, y: speed = 10kph) -> speed is expression x - y\n"
PAIR = "scenario top:\n    ego: car\n    npc: car\n"
DO = (
    "    do parallel(duration: 10s):\n"
    "        ego.drive() with:\n"
    "            speed(fast)\n"
    "        npc.drive() with:\n"
    "            position(20m, ahead_of: ego, at: start)\n"
)


def domains(text: str) -> dict[str, str]:
    result = check_text(text, "t.osc")
    assert not result.errors, result.report()
    return {name: domain.describe() for name, domain in result.scenarios[0].space.domains.items()}


def report(text: str) -> str:
    return check_text(text, "t.osc").report()


def test_a_struct_method_called_on_its_type_is_its_body_with_the_named_arguments():
    assert domains(SPEEDS + PAIR + "    fast: speed = speeds.compute(x: 70kph, y: 20kph)\n" + DO) == {
        "fast": "13.8889m/s"
    }


def test_a_positional_argument_binds_the_first_parameter_and_a_left_out_one_takes_its_default():
    assert domains(SPEEDS + PAIR + "    fast: speed = speeds.compute(30kph)\n" + DO) == {"fast": "5.55556m/s"}


def test_a_method_called_on_a_field_of_its_type_is_the_same_method():
    text = SPEEDS + PAIR + "    s: speeds\n    fast: speed = s.compute(x: 46kph)\n" + DO
    assert domains(text) == {"fast": "10m/s"}


def test_the_scenarios_own_method_reads_the_scenarios_parameters_and_its_value_is_used_where_it_is_called():
    text = (
        PAIR
        + "    base: speed = 10mps\n"
        + "    def faster(by: speed) -> speed is expression base + by\n"
        + "    fast: speed = faster(2mps)\n"
        + DO
    )
    assert domains(text)["fast"] == "12m/s"


def test_a_method_may_call_another_and_its_argument_may_be_a_sampled_parameter():
    text = (
        SPEEDS
        + PAIR
        + "    def half(v: speed) -> speed is expression speeds.compute(v, 0kph) / 2\n"
        + "    top_speed: speed with:\n        keep(it in [20mps..30mps])\n"
        + "    fast: speed = half(top_speed)\n"
        + DO
    )
    result = check_text(text, "t.osc")
    assert not result.errors, result.report()
    scenario = result.scenarios[0]
    assert scenario.space.domains["top_speed"].describe() == "[20..30]m/s"
    assert scenario.space.domains["fast"].describe() == "[10..15]m/s"
    # the value follows the sampled parameter: half of it, whatever is drawn
    (relation,) = scenario.space.relations
    assert relation.expression.operator == "==" and relation.expression.left.name == "fast"
    drawn = {"top_speed": Interval(24.0, 24.0, "speed")}
    assert evaluate(relation.expression.right, drawn) == Interval(12.0, 12.0, "speed")


@pytest.mark.parametrize(
    "value, message",
    [
        ("speeds.compte(x: 1mps)", "6:19: error: type 'speeds' has no method 'compte'"),
        ("speeds.compute(1mps, 2mps, 3mps)", "6:19: error: method 'compute' takes 2 arguments, the call gives 3"),
        ("speeds.compute(z: 1mps)", "6:34: error: method 'compute' has no parameter 'z'"),
        ("speeds.compute(y: 1mps)", "6:19: error: the call of method 'compute' gives no 'x'"),
        ("speeds.compute(1mps, x: 2mps)", "6:40: error: parameter 'x' is given twice"),
    ],
)
def test_a_call_that_cannot_be_bound_is_an_error_at_the_call(value, message):
    assert message in report(SPEEDS + PAIR + f"    fast: speed = {value}\n" + DO)


def test_a_method_with_no_body_or_an_external_one_is_refused_where_it_is_called():
    undefined = report(PAIR + "    def f() -> speed is undefined\n    fast: speed = f()\n" + DO)
    assert "t.osc:5:19: error: method 'f' is declared `is undefined`: it has no value here" in undefined, undefined
    external = report(
        PAIR
        + '    def f(x: float) -> float is only external python(module: "math", name: "sin")\n'
        + "    fast: speed = f(1) * 1mps\n"
        + DO
    )
    assert "t.osc:5:19: error: not supported: a call of the external method 'f'" in external, external
    assert "t.osc:4:9: warning: an external method is read and ignored" in external, external


def test_a_method_that_calls_itself_is_an_error_not_a_hang():
    text = PAIR + "    def f(x: speed) -> speed is expression f(x) + 1mps\n    fast: speed = f(1mps)\n" + DO
    assert "error: method 'f' calls itself" in report(text)


def test_a_call_on_a_line_of_its_own_is_checked_and_warned_as_changing_nothing():
    text = SPEEDS + PAIR + "    speeds.compute(x: 2mps, y: 1mps)\n    fast: speed = 10mps\n" + DO
    result = check_text(text, "t.osc")
    assert not result.errors, result.report()
    assert "t.osc:6:12: warning: the value of speeds.compute(...) is not used" in result.report()
    bad = report(SPEEDS + PAIR + "    speeds.compute(w: 2mps)\n    fast: speed = 10mps\n" + DO)
    assert "error: method 'compute' has no parameter 'w'" in bad, bad


def test_an_actor_types_own_method_leaves_the_librarys_methods_of_its_vehicles_callable():
    text = (
        "actor sedan inherits car:\n    def twice(x: length) -> length is expression 2 * x\n"
        "scenario top:\n    ego: sedan\n    npc: sedan\n"
        "    gap: length = ego.twice(10m)\n"
        "    do parallel(duration: 10s):\n"
        "        ego.drive() with:\n            speed(20mps)\n"
        "        npc.drive() with:\n            position(gap, ahead_of: ego, at: start)\n"
        "    cover(space, expression: ego.space_gap(npc), unit: m)\n"
    )
    result = check_text(text, "t.osc")
    assert "has no method" not in result.report(), result.report()
    assert {n: d.describe() for n, d in result.scenarios[0].space.domains.items()}["gap"] == "20m"


def test_methods_that_multiply_themselves_are_refused_quickly_not_expanded_without_end():
    # each level uses the one below four times (4^16 terms), or nests its own calls in an argument
    levels = [PAIR, "    def d0(x: length) -> length is expression x\n"]
    levels += [
        f"    def d{i}(x: length) -> length is expression d{i - 1}(x) + d{i - 1}(x) + d{i - 1}(x) + d{i - 1}(x)\n"
        for i in range(1, 17)
    ]
    wide = "".join(levels) + "    gap: length = d16(1cm)\n"
    nested = PAIR + "    def q(x: length) -> length is expression x + x + x + x\n"
    nested += "    gap: length = " + "q(" * 16 + "1cm" + ")" * 16 + "\n"
    tail = "    do parallel(duration: 5s):\n        ego.drive()\n        npc.drive() with:\n"
    tail += "            position(gap, ahead_of: ego, at: start)\n"
    wide_report, nested_report = report(wide + tail), report(nested + tail)
    assert "error: methods call each other more than 16 deep here" in wide_report, wide_report[:500]
    assert "expands to an expression of more than 10,000 terms" in nested_report, nested_report[:500]
