"""Linear constraints checked lazily: clingo decides the discrete plan, HiGHS checks its linear
program, and a conflict comes back to clingo as a nogood over the choices that caused it.

The continuous encoding (``asp/continuous.lp``) writes its linear constraints as theory atoms,
``&sum{ c1*x1; c2*x2; ... } <= k :- body.``, which hold when their body does. clingo-lpx keeps
them consistent at every decision with an exact rational simplex; measured on
follow_then_overtake at its first horizon (24 steps, 2 vehicles): 53 conflicts in 20 s, about
0.4 s per conflict, and no plan in 120 s. Here they are checked only on a total assignment, as
one floating-point linear program for HiGHS (scipy): when it is infeasible, an elastic copy of it
(every constraint that some choice switched on may be violated at a cost) gives, through its
dual values, a Farkas certificate: the switched-on constraints it uses cannot hold together with
the dynamics, and the nogood forbids exactly their literals together. It stays valid at longer
horizons (more steps only add variables and constraints), so it is kept for the whole search.

The plan itself comes from one more linear program over the accepted choices, which minimises
the sum of the absolute accelerations and their changes: smooth plans a motion planner follows.
Preferences (``&prefer{ ... } <= k``, same syntax; ``&nudge`` for weak ones) never decide
feasibility; that last program pays ``PREFERENCE_WEIGHT`` (``NUDGE_WEIGHT``) per unit by which it misses one (a start speed a scenario leaves open
lies at highway speeds, but a scenario that asks for 200 kph at its start still gets it).

Semantics as clingo-lpx's default (non-strict): a true theory atom's constraint must hold; a
false one says nothing.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, field
from fractions import Fraction
import time

import clingo
import numpy as np

# imported here, never first inside clingo's solving thread: scipy imported there left a thread
# that made the interpreter hang at exit (measured)
from scipy.optimize import linprog
from scipy.sparse import csr_matrix, hstack, identity, vstack

THEORY = """
#theory lpx {
    term { - : 3, unary; * : 2, binary, left };
    &sum/0 : term, {<=, >=, =}, term, any;
    &prefer/0 : term, {<=, >=, =}, term, any;
    &nudge/0 : term, {<=, >=, =}, term, any
}.
"""

# HiGHS's feasibility tolerance is 1e-7; a violation cost above this counts as a conflict
INFEASIBLE = 1e-6
# the smoothing program's cost per unit a preference is missed by, against 1 per m/s^2 of
# acceleration or of its change per step: a preference gives way only to what no plan avoids
PREFERENCE_WEIGHT = 100.0
# a nudge (``&nudge``, a random start's draws) weighs less than an acceleration: it spreads plans
# where the scenario leaves them free, and never buys itself a hard brake (measured: drawn start
# speeds at PREFERENCE_WEIGHT made change_lane's plans brake at -8 m/s^2 from the first instant)
NUDGE_WEIGHT = 0.1
WEIGHTS = {"prefer": PREFERENCE_WEIGHT, "nudge": NUDGE_WEIGHT}


@dataclass
class Row:
    """One linear constraint ``sum(coefficients[x] * x) <= bound`` (or ``=`` when ``equal``)."""

    coefficients: dict[int, float]
    bound: float
    equal: bool = False

    def negated(self) -> "Row":
        """``-sum <= -bound``: the same row read from the other side (``>=`` as ``<=``)."""
        return Row({k: -c for k, c in self.coefficients.items()}, -self.bound)


@dataclass
class LinearProgram:
    """The linear constraints of the ground program: those that always hold, and those a literal
    switches on."""

    variables: dict[str, int] = field(default_factory=dict)
    symbols: list[clingo.Symbol] = field(default_factory=list)
    always: list[Row] = field(default_factory=list)
    switched: dict[int, list[Row]] = field(default_factory=lambda: defaultdict(list))
    # preferences with their weights, by the literal that switches them on (0: always)
    preferred: dict[int, list[tuple[Row, float]]] = field(default_factory=lambda: defaultdict(list))

    def variable(self, symbol: clingo.Symbol) -> int:
        key = str(symbol)
        if key not in self.variables:
            self.variables[key] = len(self.symbols)
            self.symbols.append(symbol)
        return self.variables[key]


def _number(term: clingo.TheoryTerm) -> float:
    if term.type == clingo.TheoryTermType.Number:
        return float(term.number)
    if term.type == clingo.TheoryTermType.Symbol and term.name.startswith('"'):
        return float(Fraction(term.name.strip('"')))
    if term.type == clingo.TheoryTermType.Function and term.name == "-" and len(term.arguments) == 1:
        return -_number(term.arguments[0])
    raise ValueError(f"not a number in a linear constraint: {term}")


def _symbol(term: clingo.TheoryTerm) -> clingo.Symbol:
    if term.type == clingo.TheoryTermType.Number:
        return clingo.Number(term.number)
    if term.type == clingo.TheoryTermType.Symbol:
        return clingo.parse_term(term.name)
    return clingo.Function(term.name, [_symbol(a) for a in term.arguments])


def _element(term: clingo.TheoryTerm, program: LinearProgram) -> tuple[int, float]:
    """(variable, coefficient) of one ``&sum`` element: ``x``, ``-x``, ``c*x``."""
    if term.type == clingo.TheoryTermType.Function and term.name == "*" and len(term.arguments) == 2:
        return program.variable(_symbol(term.arguments[1])), _number(term.arguments[0])
    if term.type == clingo.TheoryTermType.Function and term.name == "-" and len(term.arguments) == 1:
        variable, coefficient = _element(term.arguments[0], program)
        return variable, -coefficient
    return program.variable(_symbol(term)), 1.0


def _rows(atom: clingo.TheoryAtom, program: LinearProgram) -> list[Row]:
    coefficients: dict[int, float] = defaultdict(float)
    for element in atom.elements:
        for term in element.terms:
            variable, coefficient = _element(term, program)
            coefficients[variable] += coefficient
    operator, right = atom.guard
    bound = _number(right)
    if operator == "<=":
        return [Row(dict(coefficients), bound)]
    if operator == ">=":
        return [Row(dict(coefficients), bound).negated()]
    return [Row(dict(coefficients), bound, equal=True)]


class LazyLinearPropagator:
    """Checks the linear program of a total assignment (see the module's docstring)."""

    def __init__(self) -> None:
        self.program = LinearProgram()
        self.seen: set[str] = set()
        self.solution: dict[int, np.ndarray] = {}
        self.stats = {"checks": 0, "conflicts": 0, "lp_s": 0.0}

    def init(self, init: clingo.PropagateInit) -> None:
        # called on every solve of a multi-shot control, with the theory atoms grounded since the
        # last one only (clingo drops a step's theory data after solving): the program grows
        program = self.program
        for atom in init.theory_atoms:
            if atom.term.name not in ("sum", *WEIGHTS) or (key := f"{atom.literal}:{atom}") in self.seen:
                continue
            self.seen.add(key)
            literal = init.solver_literal(atom.literal)
            rows = _rows(atom, program)
            if atom.term.name in WEIGHTS:
                if not init.assignment.is_false(literal):
                    program.preferred[0 if init.assignment.is_true(literal) else literal].extend((row, WEIGHTS[atom.term.name]) for row in rows)
            elif init.assignment.is_true(literal):
                program.always.extend(rows)
            elif not init.assignment.is_false(literal):
                program.switched[literal].extend(rows)
        init.check_mode = clingo.PropagatorCheckMode.Total

    def check(self, control: clingo.PropagateControl) -> None:
        start = time.perf_counter()
        self.stats["checks"] += 1
        on = [literal for literal in self.program.switched if control.assignment.is_true(literal)]
        conflict, solution = check_rows(self.program, on)
        self.stats["lp_s"] += time.perf_counter() - start
        if conflict is None:
            self.solution[control.thread_id] = solution
            return
        self.stats["conflicts"] += 1
        if not control.add_nogood(conflict, lock=True):
            return
        control.propagate()


def _matrix(rows: list[tuple[Row, int]], n: int):
    data, indices, pointers, bounds = [], [], [0], []
    for row, _ in rows:
        for variable, coefficient in row.coefficients.items():
            if coefficient:
                indices.append(variable)
                data.append(coefficient)
        pointers.append(len(indices))
        bounds.append(row.bound)
    return csr_matrix((data, indices, pointers), shape=(len(rows), n)), np.array(bounds)


def check_rows(program: LinearProgram, on: list[int]) -> tuple[list[int] | None, np.ndarray | None]:
    """(None, a smooth solution) when the constraints that always hold and those of the literals
    ``on`` can hold together, else (the literals of an infeasible part, None)."""
    n = len(program.symbols)
    inequalities = [(row, 0) for row in program.always if not row.equal]
    equalities = [(row, 0) for row in program.always if row.equal]
    elastic = [(half, literal) for literal in on for half in _split(program.switched[literal])]
    free = [(None, None)] * n
    hard_ub, hard_b = _matrix(inequalities, n)
    eq, eq_b = _matrix(equalities, n)
    if elastic:
        soft, soft_b = _matrix(elastic, n)
        m = len(elastic)
        # min sum(s): soft x - s <= b, s >= 0
        a_ub = vstack([hstack([hard_ub, csr_matrix((hard_ub.shape[0], m))]), hstack([soft, -identity(m, format="csr")])], format="csr")
        b_ub = np.concatenate([hard_b, soft_b])
        a_eq = hstack([eq, csr_matrix((eq.shape[0], m))], format="csr")
        cost = np.concatenate([np.zeros(n), np.ones(m)])
        result = linprog(cost, A_ub=a_ub, b_ub=b_ub, A_eq=a_eq, b_eq=eq_b, bounds=free + [(0, None)] * m, method="highs")
        if result.status == 0 and result.fun > INFEASIBLE:
            duals = result.ineqlin.marginals[hard_ub.shape[0]:]
            conflict = sorted({literal for (_, literal), dual in zip(elastic, duals) if abs(dual) > 1e-9})
            return conflict or sorted(set(on)), None
        if result.status != 0:
            return sorted(set(on)), None
    rows = inequalities + [(row, 0) for row, _ in elastic]
    preferred = [row for literal in (0, *on) for row in program.preferred.get(literal, ())]
    solution = smooth(program, rows, equalities, preferred)
    if solution is None:
        # infeasible without any switched constraint to blame (the constraints that always hold
        # clash: an empty nogood), or a numerical failure: never a model without values
        return sorted(set(on)), None
    return None, solution


def _split(rows: list[Row]) -> list[Row]:
    """Equalities as two inequalities."""
    return [half for row in rows for half in ((row, row.negated()) if row.equal else (row,))]


def smooth(program: LinearProgram, inequalities, equalities, preferred: list[tuple[Row, float]] = ()) -> np.ndarray | None:
    """A solution that minimises the absolute accelerations and their changes (variables named
    ``a(V,t)``) and what the preferences are missed by (``PREFERENCE_WEIGHT`` each), among all
    that meet the constraints."""
    n = len(program.symbols)
    accelerations = [(i, s) for i, s in enumerate(program.symbols) if s.name == "a"]
    index = {(str(s.arguments[0]), s.arguments[1].number): i for i, s in accelerations}
    # |a(t)| and |a(t) - a(t-1)|, each through one extra variable u >= +-expression
    expressions = [{i: 1.0} for i, _ in accelerations]
    expressions += [{i: 1.0, index[(v, t - 1)]: -1.0} for (v, t), i in index.items() if (v, t - 1) in index]
    absolutes = len(expressions)
    ub, b = _matrix(inequalities, n)
    eq, eq_b = _matrix(equalities, n)
    extra = []
    for j, expression in enumerate(expressions):
        for sign in (1.0, -1.0):
            coefficients = {i: sign * c for i, c in expression.items()}
            coefficients[n + j] = -1.0
            extra.append((Row(coefficients, 0.0), 0))
    # a preference row r: r.x - s <= r.bound with s >= 0 at the preference's weight
    halves = [(half, weight) for row, weight in preferred for half in _split([row])]
    for j, (row, _) in enumerate(halves):
        extra.append((Row({**row.coefficients, n + absolutes + j: -1.0}, row.bound), 0))
    weights = [1.0] * absolutes + [weight for _, weight in halves]  # one per extra variable
    slacks = len(weights)
    extra_ub, extra_b = _matrix(extra, n + slacks)
    a_ub = vstack([hstack([ub, csr_matrix((ub.shape[0], slacks))]), extra_ub], format="csr")
    a_eq = hstack([eq, csr_matrix((eq.shape[0], slacks))], format="csr")
    cost = np.concatenate([np.zeros(n), weights])
    result = linprog(cost, A_ub=a_ub, b_ub=np.concatenate([b, extra_b]), A_eq=a_eq, b_eq=eq_b,
                     bounds=[(None, None)] * n + [(0, None)] * slacks, method="highs")
    return result.x[:n] if result.status == 0 else None


class LazyLinearTheory:
    """The interface the planner expects of a theory (clingo-lpx's), over ``LazyLinearPropagator``."""

    def __init__(self) -> None:
        self.propagator = LazyLinearPropagator()

    def register(self, control: clingo.Control) -> None:
        control.register_propagator(self.propagator)

    def rewrite_ast(self, statement, add) -> None:
        add(statement)

    def prepare(self, control: clingo.Control) -> None:
        pass

    def on_model(self, model: clingo.Model) -> None:
        pass

    def assignment(self, thread_id: int = 0):
        solution = self.propagator.solution.get(thread_id)
        if solution is None:
            return []
        return list(zip(self.propagator.program.symbols, solution.tolist()))
