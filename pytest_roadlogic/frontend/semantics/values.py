"""Evaluating OS2 expressions to intervals with physical dimensions.

A logical parameter is an interval until sampling fixes it, and a concrete value is an interval of
width zero; evaluating over intervals lets one function serve both the base strategy (ranges go to
the planner) and the refined strategy (sampled points), and checks dimensions on the way: adding a
speed to a length is an error wherever it is written.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from .. import model
from ..errors import SourceLocation, error_at
from ..syntax.units import DIMENSIONS as _DIMENSIONS
from ..syntax.units import EXPONENTS as _EXPONENTS
from ..syntax.units import SI_UNIT
from .library import UNSUPPORTED_EXPRESSIONS


def describe(dimension: str | None) -> str:
    if dimension is None:
        return "a plain number"
    return f"{'an' if dimension[:1] in 'aeiou' else 'a'} {dimension}"


@dataclass(frozen=True)
class Interval:
    """``[low, high]`` in SI units of ``dimension``; a point when ``low == high``."""

    low: float
    high: float
    dimension: str | None

    @property
    def is_point(self) -> bool:
        return self.low == self.high

    def intersect(self, other: Interval) -> Interval:
        return Interval(max(self.low, other.low), min(self.high, other.high), self.dimension)

    @property
    def empty(self) -> bool:
        return self.low > self.high

    def __str__(self) -> str:
        unit = SI_UNIT.get(self.dimension, "")
        if self.is_point:
            return f"{self.low:g}{unit}"
        return f"[{self.low:g}..{self.high:g}]{unit}"


class EvaluationError(Exception):
    def __init__(self, location: SourceLocation, message: str, hint: str | None = None) -> None:
        super().__init__(message)
        self.location = location
        self.message = message
        self.hint = hint


Value = Interval | bool | model.Name | model.Literal | model.Call | model.ListValue


def evaluate(expression: model.Expression, env: Mapping[str, object]) -> Value:
    """The value of ``expression`` where ``env`` gives parameters (Intervals) and other names.

    Names not in ``env`` evaluate to themselves (actors, enum members); the caller decides whether
    that is right where they appear.
    """
    if isinstance(expression, model.Quantity):
        return Interval(expression.value, expression.value, expression.dimension)
    if isinstance(expression, model.Range):
        return Interval(expression.low.value, expression.high.value, expression.dimension)
    if isinstance(expression, model.Name):
        if expression.enum is None and expression.name in env:
            return env[expression.name]
        return expression
    if isinstance(expression, model.Call) and expression.function in UNSUPPORTED_EXPRESSIONS:
        raise EvaluationError(
            expression.location,
            f"not supported: {UNSUPPORTED_EXPRESSIONS[expression.function]}",
            "write the value or condition it stands for",
        )
    if isinstance(expression, (model.Literal, model.Call, model.ListValue)):
        if isinstance(expression, model.Literal) and isinstance(expression.value, bool):
            return expression.value
        return expression
    if isinstance(expression, model.Unary):
        operand = evaluate(expression.operand, env)
        if expression.operator == "not":
            return not _boolean(operand, expression.operand)
        interval = _interval(operand, expression.operand)
        return Interval(-interval.high, -interval.low, interval.dimension)
    if isinstance(expression, model.Binary):
        return _binary(expression, env)
    raise EvaluationError(getattr(expression, "location", SourceLocation("?", 1, 1)), "cannot evaluate this expression")


def _binary(expression: model.Binary, env: Mapping[str, object]) -> Value:
    op = expression.operator
    if op in ("and", "or", "=>"):
        left = _boolean(evaluate(expression.left, env), expression.left)
        right = _boolean(evaluate(expression.right, env), expression.right)
        return {"and": left and right, "or": left or right, "=>": (not left) or right}[op]
    left_value = evaluate(expression.left, env)
    right_value = evaluate(expression.right, env)
    if op in ("==", "!=") and not isinstance(left_value, Interval) and not isinstance(right_value, Interval):
        equal = _symbol(left_value) == _symbol(right_value)
        return equal if op == "==" else not equal
    left = _interval(left_value, expression.left)
    right = _interval(right_value, expression.right)
    if op == "..":  # a range whose bounds are computed
        _same_dimension(left, right, expression)
        if left.low > right.high:
            raise EvaluationError(
                expression.location,
                f"an empty range: its first bound ({left}) is above its second ({right})",
                "write the smaller bound first",
            )
        return Interval(left.low, right.high, left.dimension)
    if op in ("+", "-"):
        _same_dimension(left, right, expression)
        if op == "+":
            return Interval(left.low + right.low, left.high + right.high, left.dimension)
        return Interval(left.low - right.high, left.high - right.low, left.dimension)
    if op in ("*", "/", "%"):
        if op == "%":
            _same_dimension(left, right, expression)
            if not (left.is_point and right.is_point) or right.low == 0:
                raise EvaluationError(expression.location, "% needs two fixed values and a non-zero divisor")
            return Interval(math.fmod(left.low, right.low), math.fmod(left.low, right.low), left.dimension)
        dimension = _combine(left.dimension, right.dimension, +1 if op == "*" else -1, expression)
        if op == "/":
            if right.low <= 0 <= right.high:
                raise EvaluationError(expression.right.location, "division by a value that can be zero")
            right = Interval(1 / right.high, 1 / right.low, right.dimension)
        products = [left.low * right.low, left.low * right.high, left.high * right.low, left.high * right.high]
        products = [0.0 if math.isnan(p) else p for p in products]
        return Interval(min(products), max(products), dimension)
    # comparisons: meaningful on points (sampled values); on intervals they hold for every member
    _same_dimension(left, right, expression)
    if op == "in":
        return right.low <= left.low and left.high <= right.high
    if op == "==":
        return left.is_point and right.is_point and left.low == right.low
    if op == "!=":
        return left.high < right.low or right.high < left.low
    if op == "<":
        return left.high < right.low
    if op == "<=":
        return left.high <= right.low
    if op == ">":
        return left.low > right.high
    if op == ">=":
        return left.low >= right.high
    raise EvaluationError(expression.location, f"unknown operator {op!r}")


def possibly(expression: model.Expression, env: Mapping[str, object]) -> bool:
    """Whether ``expression`` can hold for some member of the intervals ``env`` gives; True when
    unsure. ``evaluate`` asks whether a comparison holds for every member; this is its dual, so
    that a constraint no member meets (``keep(a + b <= 20m)`` with a, b in [15..25]m) is found at
    once. Sound for refuting only: False means it never holds."""
    if isinstance(expression, model.Binary) and expression.operator in ("and", "or"):
        left, right = possibly(expression.left, env), possibly(expression.right, env)
        return (left and right) if expression.operator == "and" else (left or right)
    if not (isinstance(expression, model.Binary) and expression.operator in ("in", "==", "!=", "<", "<=", ">", ">=")):
        return True
    try:
        left, right = evaluate(expression.left, env), evaluate(expression.right, env)
    except EvaluationError:
        return True
    if not (isinstance(left, Interval) and isinstance(right, Interval)) or left.dimension != right.dimension:
        return True
    op = expression.operator
    if op in ("in", "=="):
        return left.low <= right.high and right.low <= left.high
    if op == "!=":
        return not (left.is_point and right.is_point and left.low == right.low)
    return {
        "<": left.low < right.high,
        "<=": left.low <= right.high,
        ">": left.high > right.low,
        ">=": left.high >= right.low,
    }[op]


def _symbol(value: object) -> object:
    if isinstance(value, model.Name):
        return value.name
    if isinstance(value, model.Literal):
        return value.value
    return value


def _interval(value: Value, expression: model.Expression) -> Interval:
    if isinstance(value, Interval):
        return value
    if isinstance(value, model.Name):
        raise EvaluationError(
            expression.location,
            f"{value.name!r} is not a number here",
            "only numbers and parameters of a numeric type can be computed with",
        )
    raise EvaluationError(expression.location, "expected a number or a quantity with a unit")


def _boolean(value: Value, expression: model.Expression) -> bool:
    if isinstance(value, bool):
        return value
    raise EvaluationError(expression.location, "expected a condition (true or false)")


def _same_dimension(left: Interval, right: Interval, expression: model.Binary) -> None:
    if left.dimension != right.dimension:
        raise EvaluationError(
            expression.location,
            f"{expression.operator!r} between {describe(left.dimension)} and {describe(right.dimension)}",
            "both sides need units of the same kind",
        )


def _combine(left: str | None, right: str | None, sign: int, expression: model.Binary) -> str | None:
    if left not in _EXPONENTS or right not in _EXPONENTS:  # a dimension the pipeline does not plan
        if right is None:
            return left
        if left is None and sign > 0:
            return right
        raise EvaluationError(
            expression.location, f"{describe(left)} {expression.operator} {describe(right)} has no supported unit"
        )
    a, b = _EXPONENTS[left], _EXPONENTS[right]
    exponents = (a[0] + sign * b[0], a[1] + sign * b[1])
    if exponents not in _DIMENSIONS:
        raise EvaluationError(
            expression.location, f"{describe(left)} {expression.operator} {describe(right)} has no supported unit"
        )
    return _DIMENSIONS[exponents]


def subexpressions(expression: model.Expression | None):
    """The expression and everything inside it, parents before children, left before right."""
    if expression is None:
        return
    yield expression
    if isinstance(expression, model.Unary):
        yield from subexpressions(expression.operand)
    elif isinstance(expression, model.Binary):
        yield from subexpressions(expression.left)
        yield from subexpressions(expression.right)
    elif isinstance(expression, model.Call):
        for argument in expression.arguments:
            yield from subexpressions(argument.value)
    elif isinstance(expression, model.ListValue):
        for item in expression.items:
            yield from subexpressions(item)


def names_in(expression: model.Expression | None) -> list[model.Name]:
    """Every name an expression mentions (to find the parameters a constraint is about)."""
    return [e for e in subexpressions(expression) if isinstance(e, model.Name)]


def calls_in(expression: model.Expression | None) -> list[model.Call]:
    return [e for e in subexpressions(expression) if isinstance(e, model.Call)]


# ------------------------------------------------------------------ arguments, after checking


def argument_interval(argument: model.Argument, env: Mapping[str, object]) -> Interval:
    """An argument's value as an interval; an error at its place when it is not a number or quantity.

    For the stages after the checker (the automaton, the constructs' translations): the checker has
    reported every error it can find, so what reaches here raises at once.
    """
    try:
        value = evaluate(argument.value, env)
    except EvaluationError as error:
        raise error_at(error.location, error.message, error.hint) from None
    if not isinstance(value, Interval):
        raise error_at(argument.location, "expected a number or a quantity")
    return value


def argument_range(
    argument: model.Argument, dimension: str, example: str, env: Mapping[str, object]
) -> tuple[float, float]:
    """An argument's bounded range in SI units of ``dimension``; an error at its place otherwise."""
    value = argument_interval(argument, env)
    if value.dimension != dimension:
        got = value.dimension or "a plain number"
        raise error_at(argument.location, f"expected {example}, got {got}", hint="add a unit of the right kind")
    if not (math.isfinite(value.low) and math.isfinite(value.high)):
        raise error_at(
            argument.location, f"expected {example}, got an unbounded value", hint="give the parameter a range"
        )
    return value.low, value.high
