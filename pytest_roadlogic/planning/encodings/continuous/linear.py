"""Linear constraints checked lazily: clingo decides the discrete plan, HiGHS checks its linear
program, and a conflict comes back to clingo as a nogood over the choices that caused it.

The continuous encoding (``asp/continuous/``) writes its linear constraints as theory atoms,
``&sum{ c1*x1; c2*x2; ... } <= k :- body.``, which hold when their body does. clingo-lpx keeps
them consistent at every decision with an exact rational simplex, far too slowly on long
scenarios (docs/decisions.md). Here they are checked only on a total assignment, as
one floating-point linear program for HiGHS (highspy), kept across checks (``SwitchedCheck``): a
choice switches its rows on through their bounds, and the dual simplex starts from the last basis.
When the program is infeasible, HiGHS's dual ray is a Farkas certificate: the switched-on rows it
uses cannot hold together with the dynamics, and the nogood forbids exactly their literals
together. It stays valid at longer horizons (more steps only add variables and constraints), so it
is kept for the whole search.

The plan itself comes from one more linear program over the accepted choices, which minimises
the sum of the absolute accelerations and their changes: smooth plans a motion planner follows.
Preferences (``&prefer{ ... } <= k``, same syntax; ``&nudge`` and ``&drift`` for weaker ones) never decide
feasibility; that last program pays ``PREFERENCE_WEIGHT`` (``NUDGE_WEIGHT``, ``DRIFT_WEIGHT``) per unit by which it misses one (a start speed a scenario leaves open
lies at highway speeds, but a scenario that asks for 200 kph at its start still gets it).

Semantics as clingo-lpx's default (non-strict): a true theory atom's constraint must hold; a
false one says nothing.
"""

from __future__ import annotations

import functools
import math
import re
from collections import defaultdict
from dataclasses import dataclass, field
from fractions import Fraction

import clingo

# imported here, never first inside clingo's solving thread
import highspy
import numpy as np

from ...core import ASP_DIR, read_programs
from ...highs import quiet_highs

# the theory of the rows (its header says what the atoms mean), read once
THEORY_FILE = ASP_DIR / "continuous" / "theory.lp"


def theory_program() -> str:
    """The ``#theory`` the continuous encoding's rows are written in (``asp/continuous/theory.lp``)."""
    return read_programs(THEORY_FILE)


# HiGHS's feasibility tolerance is 1e-7; a violation cost above this counts as a conflict
INFEASIBLE = 1e-6
# the smoothing program's cost per unit a preference is missed by, against 1 per m/s^2 of
# acceleration or of its change per step: a preference gives way only to what no plan avoids
PREFERENCE_WEIGHT = 100.0
# a nudge (``&nudge``, a random start's draws) weighs less than an acceleration: it spreads plans
# where the scenario leaves them free, and never buys itself a hard brake (drawn start speeds
# weighed as an acceleration make plans brake hard from the first instant)
NUDGE_WEIGHT = 0.1
# a drift (``&drift``, a random start's drawn acceleration and the speeds it holds within) weighs
# more than an acceleration, so that a vehicle the scenario leaves free keeps accelerating at its
# drawn rate (at 1, the weight of the acceleration itself, staying at zero would cost as much),
# and less than a preference, so that it yields to every speed a scenario prefers
DRIFT_WEIGHT = 2.0
# a steady (``&steady``: an acceleration where CARLA's position(..., at: end) asks one speed held
# over the phase) weighs ten preferences: changing speed there for a later phase's target costs
# more than missing that target for the ten steps a comfortable change to it may take, so the
# phase is not used to adjust the speed for a later one (its own end, a hard row, still holds)
STEADY_WEIGHT = 1000.0
WEIGHTS = {
    "prefer": PREFERENCE_WEIGHT,
    "nudge": NUDGE_WEIGHT,
    "drift": DRIFT_WEIGHT,
    "steady": STEADY_WEIGHT,
}


@dataclass
class Row:
    """One linear constraint ``sum(coefficients[x] * x) <= bound`` (or ``=`` when ``equal``)."""

    coefficients: dict[int, float]
    bound: float
    equal: bool = False

    def negated(self) -> Row:
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
    _hard: tuple | None = field(default=None, repr=False)
    # the program of the feasibility checks, kept across them (``SwitchedCheck``)
    checker: SwitchedCheck | None = field(default=None, repr=False)

    def variable(self, symbol: clingo.Symbol) -> int:
        key = str(symbol)
        if key not in self.variables:
            self.variables[key] = len(self.symbols)
            self.symbols.append(symbol)
        return self.variables[key]

    def hard(self):
        """The constraints that always hold, as (inequality rows, equality rows). Split once per
        growth of the program, not on every check (they are most of its rows)."""
        if self._hard is None or self._hard[0] != len(self.always):
            inequalities = [row for row in self.always if not row.equal]
            equalities = [row for row in self.always if row.equal]
            self._hard = (len(self.always), (inequalities, equalities))
        return self._hard[1]

    def printed_variable(self, text: str) -> int:
        """The variable printed as ``text`` in a theory atom (parsed once)."""
        found = self.variables.get(text)
        return found if found is not None else self.variable(clingo.parse_term(text))


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


# the printed form of the elements the encoding writes: ``x``, ``((-1)*x)``, ``((-"0.5")*x)``,
# ``("2"*x)``, ``-x``, where x is a function term without nested parentheses (its arguments may be
# quoted strings: a vehicle named ``"dut.car"``); and of a bound
_PRINTED_ELEMENT = re.compile(
    r'^\(*(?:\(?(-)?"?(-?[0-9.]+(?:/[0-9]+)?)"?\)?\*)?(-)?([a-z_][A-Za-z0-9_]*\((?:[^()"]|"[^"]*")*\))\)*$'
)
_PRINTED_BOUND = re.compile(r'^\(?(-)?"?(-?[0-9.]+(?:/[0-9]+)?)"?\)?$')
_PRINTED_ATOM = re.compile(r"^&\w+\{(.*)\}(<=|>=|=)(.*)$")


def _decimal(number: str) -> float:
    """A printed number, ``"0.5"`` or ``"1/3"``, as a float (a fraction only where it is one: a
    ``Fraction`` per coefficient was a tenth of reading a small scenario's rows)."""
    if "/" in number:
        return float(Fraction(number))
    return float(number)


@functools.lru_cache(maxsize=1 << 16)
def _read_printed(text: str) -> tuple[tuple[tuple[str, float], ...], str, float] | None:
    """An atom's printed form read as (variable printed, coefficient) pairs, its operator and its
    bound; None when it is not in the form above. Cached: every sample's controls ground most of
    the same rows."""
    whole = _PRINTED_ATOM.match(text)
    bound = whole and _PRINTED_BOUND.match(whole.group(3))
    if not bound:
        return None
    elements = []
    for element in whole.group(1).split(";"):
        parsed = _PRINTED_ELEMENT.match(element)
        if not parsed:
            return None
        sign, number, minus, variable = parsed.groups()
        coefficient = _decimal(number) if number else 1.0
        if bool(sign) != bool(minus):
            coefficient = -coefficient
        elements.append((variable, coefficient))
    value = _decimal(bound.group(2))
    return tuple(elements), whole.group(2), -value if bound.group(1) else value


def _printed_row(text: str, program: LinearProgram) -> tuple[dict[int, float], str, float] | None:
    """The atom read from its printed form, or None when it is not in the form above.

    Why: walking the theory terms through clingo's API costs a foreign call per term, a large
    share of a small scenario's first plan; one ``str(atom)`` and a regular expression read the
    same atom.
    """
    read = _read_printed(text)
    if read is None:
        return None
    elements, operator, bound = read
    coefficients: dict[int, float] = defaultdict(float)
    for variable, coefficient in elements:
        coefficients[program.printed_variable(variable)] += coefficient
    return coefficients, operator, bound


def _row(atom: clingo.TheoryAtom, program: LinearProgram, text: str) -> Row:
    """The constraint of a theory atom (``text``: the atom printed)."""
    printed = _printed_row(text, program)
    if printed is not None:
        coefficients, operator, bound = printed
    else:
        coefficients = defaultdict(float)
        for element in atom.elements:
            for term in element.terms:
                variable, coefficient = _element(term, program)
                coefficients[variable] += coefficient
        operator, right = atom.guard
        bound = _number(right)
    if operator == "<=":
        return Row(dict(coefficients), bound)
    if operator == ">=":
        return Row(dict(coefficients), bound).negated()
    return Row(dict(coefficients), bound, equal=True)


class LazyLinearPropagator:
    """Checks the linear program of a total assignment (see the module's docstring)."""

    def __init__(self) -> None:
        self.program = LinearProgram()
        self.seen: set[tuple[int, str]] = set()
        self.solution: dict[int, Smoothed] = {}  # per solver thread: its last model's

    def init(self, init: clingo.PropagateInit) -> None:
        # called on every solve of a multi-shot control, with the theory atoms grounded since the
        # last one only (clingo drops a step's theory data after solving): the program grows
        # each atom read with as few foreign calls as it takes: its printed form names its theory
        # term (``&sum{...}<=b``), and the assignment is fetched once
        program, assignment = self.program, init.assignment
        earlier = [literal for literal in (*program.switched, *program.preferred) if literal]
        for atom in init.theory_atoms:
            text = str(atom)
            name = text[1 : text.find("{")]
            if name != "sum" and name not in WEIGHTS:
                continue
            atom_literal = atom.literal
            if (key := (atom_literal, text)) in self.seen:
                continue
            self.seen.add(key)
            literal = init.solver_literal(atom_literal)
            row = _row(atom, program, text)
            if name in WEIGHTS:
                if not assignment.is_false(literal):
                    program.preferred[0 if assignment.is_true(literal) else literal].append((row, WEIGHTS[name]))
            elif assignment.is_true(literal):
                program.always.append(row)
            elif not assignment.is_false(literal):
                program.switched[literal].append(row)
        init.check_mode = clingo.PropagatorCheckMode.Total
        # which switching literals are true, kept per solver thread by propagate and undo: a check
        # reads a set instead of asking the solver literal by literal (a foreign call each, a
        # third of a check's time). Those read now are undecided (a true one always holds); one
        # read for an earlier solve may have been decided since
        for literal in (*program.switched, *program.preferred):
            if literal:
                init.add_watch(literal)
        true = {literal for literal in earlier if assignment.is_true(literal)}
        self.true = [set(true) for _ in range(init.number_of_threads)]

    def propagate(self, control: clingo.PropagateControl, changes) -> None:
        self.true[control.thread_id].update(changes)

    def undo(self, thread_id: int, assignment: clingo.Assignment, changes) -> None:
        self.true[thread_id].difference_update(changes)

    def check(self, control: clingo.PropagateControl) -> None:
        if not control.assignment.is_total:
            # clingo also calls a Total-mode check on some partial fixpoints; the check of the total assignment that
            # follows decides, and a solution found here would not be the model's
            return
        true = self.true[control.thread_id]
        on = [literal for literal in self.program.switched if literal in true]
        # a preference's literal is its own (its body's), not always one that switches a constraint
        preferring = [literal for literal in self.program.preferred if literal in true]
        conflict, smoothed = check_rows(self.program, on, preferring)
        if conflict is None:
            self.solution[control.thread_id] = smoothed
            return
        if not control.add_nogood(conflict, lock=True):
            return
        control.propagate()


@dataclass(frozen=True)
class SparseRows:
    """Rows in compressed sparse row form, as HiGHS reads a matrix row-wise: row ``i``'s
    coefficients are ``value[start[i]:start[i + 1]]`` on the columns ``index[...]``."""

    start: np.ndarray
    index: np.ndarray
    value: np.ndarray
    bound: np.ndarray

    @classmethod
    def of(cls, rows: list[Row]) -> SparseRows:
        """The rows' non-zero coefficients and their bounds."""
        index, value, start = [], [], [0]
        for row in rows:
            for variable, coefficient in row.coefficients.items():
                if coefficient:
                    index.append(variable)
                    value.append(coefficient)
            start.append(len(index))
        bound = np.array([row.bound for row in rows], dtype=float)
        return cls(
            np.array(start, dtype=np.int32), np.array(index, dtype=np.int32), np.array(value, dtype=float), bound
        )

    @property
    def nnz(self) -> int:
        return len(self.index)


@dataclass
class LinearResult:
    """What one linear program gave: whether it was solved to optimality, the values of its
    variables, its cost, and the dual values of its inequality rows (the Farkas certificate)."""

    optimal: bool
    x: np.ndarray
    cost: float
    duals: np.ndarray


def solve_linear(cost: np.ndarray, upper: list[Row], equal: list[Row], lower: np.ndarray) -> LinearResult:
    """min cost.x subject to the rows ``upper`` (sum <= bound) and ``equal`` (sum = bound),
    x >= lower (-inf: free), with HiGHS. The duals are those of the ``upper`` rows.

    Why highspy and not scipy's linprog (the same HiGHS inside): linprog's checks and conversions
    cost several times what HiGHS's own solve does on a small program (docs/decisions.md).
    """
    n, inf = len(cost), highspy.kHighsInf
    matrix = SparseRows.of(upper + equal)
    lp = highspy.HighsLp()
    lp.num_col_, lp.num_row_ = n, len(upper) + len(equal)
    lp.col_cost_ = np.asarray(cost, dtype=float)
    lp.col_lower_ = np.where(np.isinf(lower), -inf, lower)
    lp.col_upper_ = np.full(n, inf)
    lp.row_lower_ = np.concatenate([np.full(len(upper), -inf), matrix.bound[len(upper) :]])
    lp.row_upper_ = matrix.bound
    lp.a_matrix_.format_ = highspy.MatrixFormat.kRowwise
    lp.a_matrix_.start_ = matrix.start
    lp.a_matrix_.index_ = matrix.index
    lp.a_matrix_.value_ = matrix.value
    solver = quiet_highs()
    solver.passModel(lp)
    solver.run()
    if solver.getModelStatus() != highspy.HighsModelStatus.kOptimal:
        return LinearResult(False, np.zeros(n), math.inf, np.zeros(len(upper)))
    solution = solver.getSolution()
    return LinearResult(
        True,
        np.array(solution.col_value),
        solver.getInfo().objective_function_value,
        np.array(solution.row_dual[: len(upper)]),
    )


class SwitchedCheck:
    """Every switched constraint as a row of one HiGHS model kept across checks, switched on by
    its bound and off by an infinite one, with no objective.

    Between two checks only the bounds of the rows whose literals changed move; the last basis
    stays dual feasible (there is no objective), so the dual simplex starts from it and repairs
    only what the changed rows broke. An infeasible program ends in a dual ray, a Farkas
    certificate: the switched rows with a non-zero entry cannot hold together with the rows that
    always hold. Rows and variables that later horizons ground are added, never rebuilt.

    Why: an elastic program built from nothing for each check, or kept across checks with slack
    costs switched on and off, costs many times more simplex work per check (docs/decisions.md).
    """

    def __init__(self) -> None:
        self.highs = quiet_highs()
        self.highs.setOptionValue("presolve", "off")
        self.column: list[int] = []  # per variable of the program: its column
        self.hard = 0  # rows of ``program.always`` added so far
        self.synced: dict[int, int] = {}  # rows added so far per switching literal
        self.switched_rows = 0  # of ``program.switched``, all of them: the model syncs when they grow
        self.literal = np.zeros(0, dtype=np.int64)  # per switched half-row: its literal
        self.row = np.zeros(0, dtype=np.int32)  # per switched half-row: its row in the model
        self.bound = np.zeros(0)  # per switched half-row: its bound when on
        self.on = np.zeros(0, dtype=bool)  # per switched half-row: on in the model now
        self.halves_of: dict[int, list[int]] = defaultdict(list)  # per literal: its half-rows

    def _sync(self, program: LinearProgram) -> None:
        highs, inf = self.highs, highspy.kHighsInf
        n = len(program.symbols)
        if n > len(self.column):
            new, first = n - len(self.column), highs.getNumCol()
            highs.addCols(
                new,
                np.zeros(new),
                np.full(new, -inf),
                np.full(new, inf),
                0,
                np.zeros(new, dtype=np.int32),
                np.zeros(0, dtype=np.int32),
                np.zeros(0),
            )
            self.column += range(first, first + new)
        if len(program.always) > self.hard:
            rows = program.always[self.hard :]
            self._add_rows(rows, [row.bound if row.equal else -inf for row in rows], [row.bound for row in rows])
            self.hard = len(program.always)
        switched_rows = sum(map(len, program.switched.values()))
        if switched_rows == self.switched_rows:
            return
        self.switched_rows = switched_rows
        halves: list[tuple[Row, int]] = []
        for literal, rows in program.switched.items():
            done = self.synced.get(literal, 0)
            if len(rows) > done:
                halves += [(half, literal) for half in _split(rows[done:])]
                self.synced[literal] = len(rows)
        if halves:
            m, first = len(halves), highs.getNumRow()
            self._add_rows([half for half, _ in halves], [-inf] * m, [inf] * m)
            self.literal = np.concatenate([self.literal, [literal for _, literal in halves]]).astype(np.int64)
            self.bound = np.concatenate([self.bound, [half.bound for half, _ in halves]])
            self.row = np.concatenate([self.row, np.arange(first, first + m, dtype=np.int32)])
            self.on = np.concatenate([self.on, np.zeros(m, dtype=bool)])
            for offset, (_, literal) in enumerate(halves):
                self.halves_of[literal].append(len(self.on) - m + offset)

    def _add_rows(self, rows: list[Row], lower: list[float], upper: list[float]) -> None:
        matrix = SparseRows.of(rows)
        columns = np.asarray(self.column, dtype=np.int32)[matrix.index]  # the model's columns
        self.highs.addRows(
            len(rows),
            np.array(lower, dtype=float),
            np.array(upper, dtype=float),
            matrix.nnz,
            matrix.start[:-1],
            columns,
            matrix.value,
        )

    def conflict(self, program: LinearProgram, on: list[int]) -> list[int] | None | bool:
        """The literals of ``on`` whose rows cannot hold together with those that always hold,
        None when they can, False when HiGHS gave no certificate (the caller decides another way)."""
        self._sync(program)
        wanted = np.zeros(len(self.on), dtype=bool)
        for literal in on:
            if literal in self.halves_of:
                wanted[self.halves_of[literal]] = True
        changed = np.flatnonzero(wanted != self.on)
        if len(changed):
            inf = highspy.kHighsInf
            rows = self.row[changed]
            upper = np.where(wanted[changed], self.bound[changed], inf)
            self.highs.changeRowsBounds(len(changed), rows, np.full(len(changed), -inf), upper)
            self.on = wanted
        self.highs.run()
        status = self.highs.getModelStatus()
        if status == highspy.HighsModelStatus.kOptimal:
            return None
        if status != highspy.HighsModelStatus.kInfeasible:
            return False
        _, exists, ray = self.highs.getDualRay()
        if not exists:
            return False
        ray = np.asarray(ray)[self.row]
        conflict = {int(literal) for literal in self.literal[(np.abs(ray) > 1e-9) & wanted]}
        return sorted(conflict) if conflict else False


def _elastic_conflict(program: LinearProgram, on: list[int]) -> list[int] | None:
    """The same answer as ``SwitchedCheck.conflict`` from an elastic program built afresh (every
    switched-on row may be violated at a cost; the rows with a non-zero dual at the optimum clash)."""
    elastic = [(half, literal) for literal in on for half in _split(program.switched[literal])]
    if not elastic:
        return None
    n = len(program.symbols)
    inequalities, equalities = program.hard()
    # min sum(s): soft x - s <= b, s >= 0
    soft = [Row({**half.coefficients, n + j: -1.0}, half.bound) for j, (half, _) in enumerate(elastic)]
    m = len(elastic)
    cost = np.concatenate([np.zeros(n), np.ones(m)])
    lower = np.concatenate([np.full(n, -np.inf), np.zeros(m)])
    result = solve_linear(cost, inequalities + soft, equalities, lower)
    if not result.optimal:
        return sorted(set(on))
    if result.cost <= INFEASIBLE:
        return None
    duals = result.duals[len(inequalities) :]
    conflict = sorted({literal for (_, literal), dual in zip(elastic, duals) if abs(dual) > 1e-9})
    return conflict or sorted(set(on))


@dataclass
class Smoothed:
    """A feasible program's smoothest solution (``smooth``): the variables' values, and its cost
    (the absolute accelerations and their changes, and the weighted misses of the preferences)."""

    values: np.ndarray
    cost: float


def check_rows(
    program: LinearProgram, on: list[int], preferring: list[int] | None = None
) -> tuple[list[int] | None, Smoothed | None]:
    """(None, a smooth solution) when the constraints that always hold and those of the literals
    ``on`` can hold together, else (the literals of an infeasible part, None). The solution meets
    the preferences that always apply and those of the literals ``preferring`` (default: ``on``)."""
    inequalities, equalities = program.hard()
    if program.checker is None:
        program.checker = SwitchedCheck()
    conflict = program.checker.conflict(program, on)
    if conflict is False:
        conflict = _elastic_conflict(program, on)
    if conflict is not None:
        return conflict, None
    elastic = [(half, literal) for literal in on for half in _split(program.switched[literal])]
    rows = inequalities + [row for row, _ in elastic]
    preferred = [
        row
        for literal in (0, *(on if preferring is None else preferring))
        for row in program.preferred.get(literal, ())
    ]
    smoothed = smooth(program, rows, equalities, preferred)
    if smoothed is None:
        # infeasible without any switched constraint to blame (the constraints that always hold
        # clash: an empty nogood), or a numerical failure: never a model without values
        return sorted(set(on)), None
    return None, smoothed


def _split(rows: list[Row]) -> list[Row]:
    """Equalities as two inequalities."""
    return [half for row in rows for half in ((row, row.negated()) if row.equal else (row,))]


def smooth(
    program: LinearProgram, inequalities: list[Row], equalities: list[Row], preferred: list[tuple[Row, float]] = ()
) -> Smoothed | None:
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
    extra = []
    for j, expression in enumerate(expressions):
        for sign in (1.0, -1.0):
            coefficients = {i: sign * c for i, c in expression.items()}
            coefficients[n + j] = -1.0
            extra.append(Row(coefficients, 0.0))
    # a preference row r: r.x - s <= r.bound with s >= 0 at the preference's weight
    halves = [(half, weight) for row, weight in preferred for half in _split([row])]
    for j, (row, _) in enumerate(halves):
        extra.append(Row({**row.coefficients, n + absolutes + j: -1.0}, row.bound))
    weights = [1.0] * absolutes + [weight for _, weight in halves]  # one per extra variable
    slacks = len(weights)
    cost = np.concatenate([np.zeros(n), weights])
    lower = np.concatenate([np.full(n, -np.inf), np.zeros(slacks)])
    result = solve_linear(cost, inequalities + extra, equalities, lower)
    return Smoothed(result.x[:n], result.cost) if result.optimal else None


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
        smoothed = self.propagator.solution.get(thread_id)
        if smoothed is None:
            return []
        return list(zip(self.propagator.program.symbols, smoothed.values.tolist()))

    def cost(self, thread_id: int = 0) -> float:
        """What the smoothing of the thread's last model cost (``Smoothed.cost``)."""
        smoothed = self.propagator.solution.get(thread_id)
        return math.inf if smoothed is None else smoothed.cost
