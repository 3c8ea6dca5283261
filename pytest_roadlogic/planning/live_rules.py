"""The rules of an encoding that can fire for one instance.

What goes in: the parsed statements of an encoding and the names the rest of the program (the
instance's text, and any other statements added beside) may give. What comes out: the statements
without the rules that can never fire, in their order. A rule can never fire when its body needs,
as a positive literal, a predicate whose name no head of any statement kept gives (an
``#external`` gives its atom) and the rest of the program never writes; dropping one can make
others so, until none does. Names, not signatures: a name written anywhere in the instance counts
as given, which keeps a rule too many at worst.

Why: clingo instantiates every rule of a program part at each ground call, whether or not its
facts exist, and a planner grounds one call per step: a rule for a construct the scenario does not
use (a shaped speed change, a replan's past) costs every step of every search, and it adds no atom
and no row (docs/decisions.md). The ground program and the plans are the same without it.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from clingo.ast import AST, ASTType, Sign

_NAME = re.compile(r"[a-z_][A-Za-z0-9_']*")


@dataclass(frozen=True)
class Annotated:
    """An encoding's statements, each with what its body needs and what it gives (``needs``,
    ``gives``), read once: an encoding's statements are the same for every instance."""

    statements: tuple[AST, ...]
    needed: tuple[frozenset[str], ...]
    given: tuple[frozenset[str], ...]

    @classmethod
    def of(cls, statements: Iterable[AST]) -> Annotated:
        statements = tuple(statements)
        return cls(statements, tuple(map(needs, statements)), tuple(map(gives, statements)))


def live_statements(encoding: Annotated, given: frozenset[str]) -> list[AST]:
    """The ``encoding``'s statements without its rules that can never fire, ``given`` the
    predicates the rest of the program gives."""
    kept = range(len(encoding.statements))
    while True:
        defined = given.union(*(encoding.given[i] for i in kept))
        still = [i for i in kept if encoding.needed[i] <= defined]
        if len(still) == len(kept):
            return [encoding.statements[i] for i in still]
        kept = still


def names_in(text: str) -> frozenset[str]:
    """Every name written in a program's ``text``: the predicates it may give, and more."""
    return frozenset(_NAME.findall(text))


def program_gives(statements: Iterable[AST]) -> frozenset[str]:
    """The predicates ``statements`` give: their rules' heads and their externals."""
    return frozenset().union(*(gives(statement) for statement in statements))


def gives(statement: AST) -> frozenset[str]:
    """The predicates a statement can make true: a rule's head atoms, an external's atom."""
    if statement.ast_type == ASTType.External:
        return _signatures([statement.atom])
    if statement.ast_type != ASTType.Rule:
        return frozenset()
    head = statement.head
    if head.ast_type == ASTType.Literal:
        return _signatures([head.atom])
    if head.ast_type in (ASTType.Disjunction, ASTType.Aggregate):
        return _signatures(element.literal.atom for element in head.elements)
    if head.ast_type == ASTType.HeadAggregate:
        return _signatures(element.condition.literal.atom for element in head.elements)
    return frozenset()  # a theory atom or a constraint: no atom of a predicate


def needs(statement: AST) -> frozenset[str]:
    """The predicates a rule's body needs true (its plain positive literals); none for any other
    statement, which is always kept."""
    if statement.ast_type != ASTType.Rule:
        return frozenset()
    return _signatures(
        literal.atom
        for literal in statement.body
        if literal.ast_type == ASTType.Literal and literal.sign == Sign.NoSign
    )


def _signatures(atoms: Iterable[AST]) -> frozenset[str]:
    found = set()
    for atom in atoms:
        if atom.ast_type != ASTType.SymbolicAtom:
            continue
        term = atom.symbol
        if term.ast_type == ASTType.Function:
            found.add(term.name)
        elif term.ast_type == ASTType.SymbolicTerm and term.symbol.type.name == "Function":
            found.add(term.symbol.name)
    return frozenset(found)
